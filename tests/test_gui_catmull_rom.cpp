// The Catmull-Rom tab (docs/tabs.md): Ex 2.11 and Ex 2.13 exactly as printed in the exact
// panel, Ex 2.1's slip exposed, mouse drags with undo, the tension list and its refusals,
// the segment counts of Def 2.10, Prop 2.3 at every knot, interpolation, documents, the
// stiff cases of docs/extreme-cases.md, and §2.3 made visible: κ against arc length (jumping
// at the Catmull-Rom knots, continuous along the C² spline), each segment's Bézier points and
// the C/G order of every knot, and exports that write cubic paths.
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/segment_joins.h"
#include "core/exact/polynomial_text.h"
#include "core/exact/rational_approximation.h"
#include "core/io/worked_examples.h"
#include "ui/catmull_rom/catmull_rom_report.h"
#include "ui/catmull_rom/catmull_rom_tab.h"
#include "ui/catmull_rom/tension_colour.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/exact_panel.h"
#include "ui/common/point_editor.h"
#include "ui/files/exporter.h"
#include "ui/common/language.h"
#include "ui/files/tikz_writer.h"
#include "gui_timeouts.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QGroupBox>
#include <QLabel>
#include <QTemporaryDir>
#include <QJsonArray>
#include <QSlider>
#include <QJsonDocument>
#include <QTest>
#include "tests/test_main.h"
#include <QUndoStack>
#include <qcustomplot.h>

#include <cmath>

using namespace granota;
using namespace granota::ui;

namespace {

const WorkedExample& example(const char* id)
{
    const WorkedExample* ex = findWorkedExample(id);
    if (!ex)
        qFatal("missing example %s", id);
    return *ex;
}

/// The printed polynomials of an example's "expected" object: {"x": …, "y": …} leaves.
QStringList expectedTexts(const Json& node)
{
    QStringList out;
    if (const auto s = node.asString())
        out << QString::fromStdString(*s);
    if (const auto* a = node.asArray())
        for (const Json& item : *a)
            out << expectedTexts(item);
    if (const auto* o = node.asObject())
        for (const auto& [key, value] : *o)
            out << expectedTexts(value);
    return out;
}

bool near(Point a, Point b, double tol = 1e-9)
{
    const double scale = std::max({1.0, std::fabs(a.x), std::fabs(a.y)});
    return std::fabs(a.x - b.x) <= tol * scale && std::fabs(a.y - b.y) <= tol * scale;
}

std::vector<Point> ex213Points() { return toDouble(example("2.13").points); }

void showTab(CatmullRomTab& tab)
{
    tab.resize(1280, 760);
    tab.show();
    QVERIFY(waitExposed(&tab));
}

bool allFinite(const CatmullRomScene& scene)
{
    for (const auto& c : scene.curves)
        for (const Point& p : c.samples)
            if (!isFinite(p))
                return false;
    for (const Point& p : scene.spline)
        if (!isFinite(p))
            return false;
    for (const Point& p : scene.bezier)
        if (!isFinite(p))
            return false;
    return true;
}

/// The graph of the plot named `name`, or nullptr.
QCPGraph* graphNamed(QCustomPlot* plot, const QString& name)
{
    for (int i = 0; i < plot->graphCount(); ++i)
        if (plot->graph(i)->name() == name)
            return plot->graph(i);
    return nullptr;
}

/// κ on both sides of each gap of a κ(s) graph: the last value before a NaN and the first
/// after it, with their arc lengths.
struct KnotSides {
    double sLeft, kappaLeft, sRight, kappaRight;
};
std::vector<KnotSides> knotSides(const QCPGraph* g)
{
    std::vector<KnotSides> out;
    const auto data = g->data();
    for (auto it = data->constBegin(); it != data->constEnd(); ++it)
        if (std::isnan(it->value) && it != data->constBegin() && it + 1 != data->constEnd() && !std::isnan((it - 1)->value) &&
            !std::isnan((it + 1)->value))
            out.push_back({(it - 1)->key, (it - 1)->value, (it + 1)->key, (it + 1)->value});
    return out;
}

/// Signed curvature (x′y″ − y′x″)/|p′|³ of a printed segment at t, from its polynomials.
double printedCurvature(const Json& segment, const Rational& t)
{
    const auto x = parsePolynomial(*segment.find("x")->asString());
    const auto y = parsePolynomial(*segment.find("y")->asString());
    if (!x || !y)
        qFatal("unreadable printed segment");
    const double dx = toDouble(x->derivative()(t)), dy = toDouble(y->derivative()(t));
    const double ddx = toDouble(x->derivative().derivative()(t)), ddy = toDouble(y->derivative().derivative()(t));
    return (dx * ddy - dy * ddx) / std::pow(dx * dx + dy * dy, 1.5);
}

/// The letter after each '&' of a control's text ("&&" is a literal &), lower case.
QChar mnemonic(const QString& text)
{
    for (int i = 0; i + 1 < text.size(); ++i) {
        if (text[i] != QLatin1Char('&'))
            continue;
        if (text[i + 1] == QLatin1Char('&')) {
            ++i;
            continue;
        }
        return text[i + 1].toLower();
    }
    return {};
}

} // namespace

class TestGuiCatmullRom : public QObject {
    Q_OBJECT

private slots:
    void startsAsEx211()
    {
        CatmullRomTab tab;
        QCOMPARE(tab.pointEditor()->points(), toDouble(example("2.11").points));
        QCOMPARE(int(tab.settings().taus.size()), 3);
        QVERIFY(tab.settings().taus[1] == frac(1, 2));
        QCOMPARE(tab.settings().ends, CatmullRomEnds::Open);
        QCOMPARE(int(tab.scene().curves.size()), 3);
        // Open, 4 points: 3 segments; the middle one is Ex 2.11's segment.
        QCOMPARE(int(tab.scene().curves[0].segments.size()), 3);
        QVERIFY(tab.exactPanel()->plainText().contains(QStringLiteral("3 + 1/2 t - 5t^2 + 7/2 t^3")));
    }

    void ex211ExactlyAsPrinted()
    {
        CatmullRomTab tab;
        QVERIFY(tab.loadExample(example("2.11")));
        QCOMPARE(tab.settings().ends, CatmullRomEnds::Segment);
        QCOMPARE(int(tab.scene().curves.size()), 3);
        for (const auto& c : tab.scene().curves)
            QCOMPARE(int(c.segments.size()), 1); // one segment, q1 → q2
        const QString text = tab.exactPanel()->plainText();
        const QStringList want = expectedTexts(*example("2.11").data.find("expected"));
        QCOMPARE(want.size(), 6);
        for (const QString& w : want)
            QVERIFY2(text.contains(w), qPrintable(w));
        QVERIFY(text.contains(QStringLiteral("p(t)")));
    }

    void ex213BothModesExactlyAsPrinted()
    {
        CatmullRomTab tab;
        QVERIFY(tab.loadExample(example("2.13")));
        QCOMPARE(tab.settings().ends, CatmullRomEnds::Cyclic);
        QVERIFY(tab.settings().compareEnds);
        const auto* combo = tab.findChildren<QComboBox*>().first();
        QCOMPARE(combo->currentIndex(), int(CatmullRomEnds::Cyclic));
        const QString text = tab.exactPanel()->plainText();
        const QStringList want = expectedTexts(*example("2.13").data.find("expected"));
        QCOMPARE(want.size(), 16);
        for (const QString& w : want)
            QVERIFY2(text.contains(w), qPrintable(w));
        // The cyclic p1 and the open p1 differ (x: −5/2 t vs −1/2 t): both must be there.
        QVERIFY(text.contains(QStringLiteral("3 - 5/2 t + 1/2 t^2 + t^3")));
        QVERIFY(text.contains(QStringLiteral("3 - 1/2 t - 7/2 t^2 + 3t^3")));
    }

    // The comparison of §2.3 gives the order in the knot parameter, as the knot table does:
    // a centripetal curve is C¹ there (its local tangents are only parallel), a uniform one
    // too; neither is C².
    void smoothnessComparedIsInTheKnotParameter_data()
    {
        QTest::addColumn<int>("spacing");
        QTest::newRow("uniform") << static_cast<int>(CatmullRomSpacing::Uniform);
        QTest::newRow("centripetal") << static_cast<int>(CatmullRomSpacing::Centripetal);
        QTest::newRow("chordal") << static_cast<int>(CatmullRomSpacing::Chordal);
    }
    void smoothnessComparedIsInTheKnotParameter()
    {
        QFETCH(int, spacing);
        CatmullRomTab tab;
        tab.pointEditor()->setPoints({{0, 0}, {1, 0}, {5, 2}, {6, 6}, {9, 7}}, QStringLiteral("test"));
        tab.setSpacing(static_cast<CatmullRomSpacing>(spacing));
        tab.setBezierVisible(true);
        const QString text = tab.exactPanel()->plainText();
        QVERIFY2(text.contains(QStringLiteral("C^1 at the joins (checked)")), qPrintable(text));
        QVERIFY(!text.contains(QStringLiteral("C^0 at the joins")));
    }

    void ex21ExposesTheSlip()
    {
        CatmullRomTab tab;
        QVERIFY(tab.loadExample(example("2.1")));
        QVERIFY(tab.settings().spline);
        QVERIFY(!tab.scene().spline.empty());
        const QString text = tab.exactPanel()->plainText();
        // The printed pieces, checked: s₂ misses (1, 3) and (2, 1).
        QVERIFY2(text.contains(QStringLiteral("394/53 x - 288/53 x^2 + 52/53 x^3")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("s_2 does not interpolate (1, 3): s_2(1) = 158/53")), qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("s_2 does not interpolate (2, 1): s_2(2) = 52/53")));
        QVERIFY(text.contains(QStringLiteral("+1/53")));
        // Fig 2.1: Ex 2.1's own spline alone — its ends (s₁‴ = 0, no x² in s₃), not natural
        // ones, and no Catmull-Rom curve. Its pieces are the printed ones corrected.
        QCOMPARE(tab.settings().splineEnds, granota::SplineEnds::AsEx21);
        QVERIFY(!tab.settings().catmullRom);
        QVERIFY2(text.contains(QStringLiteral("the ends of Ex 2.1")), qPrintable(text));
        QVERIFY(text.contains(QStringLiteral("1/53 + 394/53 x - 288/53 x^2 + 52/53 x^3")));
        QVERIFY(text.contains(QStringLiteral("exactly the corrected ones")));
        QVERIFY(text.contains(QStringLiteral("C^2 at every knot")));
        QVERIFY(!tab.tikz(granota::ui::TikzOptions()).contains(QStringLiteral("tau =")));
        // The natural spline of Def 2.3 (M_1 = −32/5, M_2 = 8/5) is another one, one undo step away.
        tab.setSplineEnds(granota::SplineEnds::Natural);
        const QString natural = tab.exactPanel()->plainText();
        QVERIFY2(natural.contains(QStringLiteral("1 + 46/15 x - 16/15 x^3")), qPrintable(natural));
        QVERIFY(natural.contains(QStringLiteral("Choose the ends")));
        tab.undoStack()->undo();
        QCOMPARE(tab.settings().splineEnds, granota::SplineEnds::AsEx21);
        tab.setCatmullRomVisible(true);
        QVERIFY(tab.tikz(granota::ui::TikzOptions()).contains(QStringLiteral("tau = 1/2")));
        tab.undoStack()->undo();
        QVERIFY(!tab.settings().catmullRom);
        // The spline interpolates the points (samples at the knots).
        const auto& s = tab.scene().spline;
        const int per = CatmullRomScene::kSamplesPerSegment;
        const auto pts = tab.pointEditor()->points();
        for (int i = 0; i < 3; ++i) {
            QVERIFY(near(s[std::size_t(i * per)], pts[std::size_t(i)]));
            QVERIFY(near(s[std::size_t(i * per + per - 1)], pts[std::size_t(i + 1)]));
        }
    }

    void splineRefusesNonFunctionData()
    {
        CatmullRomTab tab; // Ex 2.11's points: x = 1, 3, 2, 5 is not increasing
        tab.setSplineVisible(true);
        QVERIFY(tab.settings().spline);
        QVERIFY(tab.scene().spline.empty());
        QVERIFY(!tab.scene().splineError.isEmpty());
        QVERIFY(tab.exactPanel()->plainText().contains(QStringLiteral("not a function of x")));
        QVERIFY(tab.lastMessage().contains(QStringLiteral("not a function of x")));
    }

    void dragMovesAPointAndUndoRestores()
    {
        CatmullRomTab tab;
        showTab(tab);
        CurveCanvas* canvas = tab.canvas();
        const auto before = tab.pointEditor()->points();
        const auto samplesBefore = tab.scene().curves[1].samples;
        const QString panelBefore = tab.exactPanel()->plainText();
        const int undoBefore = tab.undoStack()->count();

        const QPoint from = canvas->view().toScreen(before[1]).toPoint();
        const QPoint to = from + QPoint(-40, 30);
        QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, from);
        QTest::mouseMove(canvas, from + QPoint(-20, 15));
        QTest::mouseMove(canvas, to);
        const Point target = canvas->view().toModel(QPointF(to));
        QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, to);

        const auto after = tab.pointEditor()->points();
        QVERIFY(near(after[1], target, 0.5 / canvas->view().scale())); // within half a pixel (on its round step)
        QVERIFY(!near(after[1], before[1], 1e-3));
        QCOMPARE(after[0], before[0]);
        QCOMPARE(tab.undoStack()->count(), undoBefore + 1);
        QVERIFY(tab.scene().curves[1].samples != samplesBefore);
        QVERIFY(tab.exactPanel()->plainText() != panelBefore);

        tab.undoStack()->undo();
        QCOMPARE(tab.pointEditor()->points(), before);
        QCOMPARE(tab.scene().curves[1].samples, samplesBefore);
        QCOMPARE(tab.exactPanel()->plainText(), panelBefore);
    }

    void addAndRemoveTensions()
    {
        CatmullRomTab tab;
        QVERIFY(tab.addTension(QStringLiteral("-1/2"))); // Ex 2.12: negatives allowed
        QCOMPARE(int(tab.scene().curves.size()), 4);
        QVERIFY(tab.scene().curves[3].tau == frac(-1, 2));
        QVERIFY(tab.exactPanel()->plainText().contains(QStringLiteral("τ = -1/2")));
        QVERIFY(tab.addTension(QStringLiteral("0.25")));
        QVERIFY(tab.settings().taus.back() == frac(1, 4));
        QVERIFY(tab.removeTension(0)); // τ = 0
        QCOMPARE(int(tab.scene().curves.size()), 4);
        QVERIFY(tab.scene().curves[0].tau == frac(1, 2));
        tab.undoStack()->undo();
        tab.undoStack()->undo();
        tab.undoStack()->undo();
        QCOMPARE(int(tab.settings().taus.size()), 3);
        QCOMPARE(int(tab.scene().curves.size()), 3);
    }

    // Issue 34, item 11: a curve's colour is a function of its τ (tension_colour.h), not of its
    // place in the list: adding a τ or removing another one leaves it alone.
    void tauColourFollowsTheValue()
    {
        CatmullRomTab tab;
        const auto colourOf = [&tab](const QString& text) {
            for (const CanvasLegendEntry& e : tab.legend().entries)
                if (e.text == text)
                    return e.color;
            return QColor();
        };
        const QString half = QStringLiteral("τ = 1/2");
        const QColor before = colourOf(half);
        QVERIFY(before.isValid());
        QVERIFY(tab.addTension(QStringLiteral("0.2")));
        QCOMPARE(colourOf(half), before);
        // Removing τ = 0, first in the list, handed τ = 1/2 the first colour.
        const QColor fifth = colourOf(QStringLiteral("τ = 1/5"));
        QVERIFY(tab.removeTension(0));
        QCOMPARE(colourOf(half), before);
        QCOMPARE(colourOf(QStringLiteral("τ = 1/5")), fifth);
        // The same τ, the same colour, in another tab with another list.
        CatmullRomTab other;
        QVERIFY(other.removeTension(0));
        QVERIFY(other.removeTension(0)); // τ = 2 alone
        QVERIFY(other.addTension(QStringLiteral("1/2")));
        QCOMPARE(colourOf(half), before);
        QCOMPARE(other.legend().entries.at(1).color, before);
        // Different tensions of the examples get clearly different hues (Ex 2.12: −2, 0, 1/2, 2).
        const QList<double> taus{-2, 0, 0.5, 2, 1, -0.5};
        for (int i = 0; i < taus.size(); ++i)
            for (int j = i + 1; j < taus.size(); ++j)
                QVERIFY(std::abs(tensionColour(taus[i]).hsvHue() - tensionColour(taus[j]).hsvHue()) >= 18);
    }

    // Issue 34, item 11: the check boxes under the τ list stay where they were when τ are added
    // (they moved under the pointer as the list grew).
    void checkBoxesStayWhenATauIsAdded()
    {
        CatmullRomTab tab;
        tab.resize(800, 540); // an 800×600 screen: the side panel has no height to spare, it scrolls
        tab.show();
        QVERIFY(waitExposed(&tab));
        const auto geometries = [&tab] {
            QList<QRect> out;
            for (QCheckBox* box : tab.findChildren<QCheckBox*>())
                out << QRect(box->mapTo(&tab, QPoint(0, 0)), box->size());
            return out;
        };
        const auto settle = [] {
            for (int i = 0; i < 8; ++i) // the layouts settle, each level asking its parent in turn
                QApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        };
        settle();
        const QList<QRect> before = geometries();
        QVERIFY(before.size() >= 5);
        QVERIFY(tab.addTension(QStringLiteral("0.2")));
        QVERIFY(tab.addTension(QStringLiteral("-0.35")));
        QVERIFY(tab.addTension(QStringLiteral("0.7"))); // six τ: past the rows the list shows
        settle();
        QCOMPARE(geometries(), before);
    }

    void sliderMovesMergeIntoOneUndoStep()
    {
        CatmullRomTab tab;
        QSlider* slider = tab.findChild<QSlider*>();
        QVERIFY(slider);
        QCOMPARE(tab.settings().selectedTau, 1); // τ = 1/2
        QCOMPARE(slider->value(), 10);           // steps of 0.05
        const auto samples = tab.scene().curves[1].samples;
        const int count = tab.undoStack()->count();
        slider->setValue(30);
        slider->setValue(32);
        QVERIFY(tab.settings().taus[1] == frac(8, 5));
        QCOMPARE(tab.undoStack()->count(), count + 1);
        QVERIFY(tab.scene().curves[1].samples != samples);
        QVERIFY(tab.exactPanel()->plainText().contains(QStringLiteral("τ = 8/5")));
        slider->setValue(0); // τ = 0 is already in the list: refused, nothing changes
        QVERIFY(tab.settings().taus[1] == frac(8, 5));
        QVERIFY(!tab.lastMessage().isEmpty());
        QCOMPARE(slider->value(), 32);
        tab.undoStack()->undo();
        QVERIFY(tab.settings().taus[1] == frac(1, 2));
        QCOMPARE(tab.scene().curves[1].samples, samples);
        QCOMPARE(slider->value(), 10);
    }

    void refusedTensions_data()
    {
        QTest::addColumn<QString>("text");
        QTest::newRow("above 10") << "11";
        QTest::newRow("below -10") << "-10.5";
        QTest::newRow("garbage") << "abc";
        QTest::newRow("zero denominator") << "1/0";
        QTest::newRow("empty") << "";
        QTest::newRow("nan") << "nan";
        QTest::newRow("duplicate") << "0.5";
    }
    void refusedTensions()
    {
        QFETCH(QString, text);
        CatmullRomTab tab;
        const auto before = tab.settings().taus;
        const int undo = tab.undoStack()->count();
        QVERIFY(!tab.addTension(text));
        QVERIFY(!tab.lastMessage().isEmpty());
        QVERIFY(tab.settings().taus == before);
        QCOMPARE(int(tab.scene().curves.size()), int(before.size()));
        QCOMPARE(tab.undoStack()->count(), undo);
    }

    void tensionLimitsAccepted()
    {
        CatmullRomTab tab;
        QVERIFY(tab.addTension(QStringLiteral("10")));
        QVERIFY(tab.addTension(QStringLiteral("−10"))); // Unicode minus, as printed
        QVERIFY(allFinite(tab.scene()));
        QVERIFY(!tab.exactPanel()->plainText().contains(QStringLiteral("nan")));
    }

    void segmentCounts_data()
    {
        QTest::addColumn<int>("ends");
        QTest::addColumn<int>("segments");
        // n + 1 = 5 points (Ex 2.13): Def 2.10 and docs/tabs.md.
        QTest::newRow("open: n") << int(CatmullRomEnds::Open) << 4;
        QTest::newRow("cyclic: n") << int(CatmullRomEnds::Cyclic) << 4;
        QTest::newRow("closed: n + 1") << int(CatmullRomEnds::Closed) << 5;
        QTest::newRow("single segments: n - 2") << int(CatmullRomEnds::Segment) << 2;
    }
    void segmentCounts()
    {
        QFETCH(int, ends);
        QFETCH(int, segments);
        CatmullRomTab tab;
        tab.pointEditor()->setPoints(ex213Points(), QStringLiteral("test"));
        tab.setEnds(CatmullRomEnds(ends));
        for (const auto& c : tab.scene().curves) {
            QCOMPARE(int(c.segments.size()), segments);
            QCOMPARE(int(c.samples.size()), segments * CatmullRomScene::kSamplesPerSegment);
        }
    }

    void tangentContinuityAtEveryKnot_data()
    {
        QTest::addColumn<int>("ends");
        QTest::newRow("open") << int(CatmullRomEnds::Open);
        QTest::newRow("cyclic") << int(CatmullRomEnds::Cyclic);
        QTest::newRow("closed") << int(CatmullRomEnds::Closed);
    }
    void tangentContinuityAtEveryKnot()
    {
        QFETCH(int, ends);
        CatmullRomTab tab;
        tab.pointEditor()->setPoints(ex213Points(), QStringLiteral("test"));
        tab.setEnds(CatmullRomEnds(ends));
        const bool closed = CatmullRomEnds(ends) == CatmullRomEnds::Closed;
        for (const auto& c : tab.scene().curves) {
            const auto joins = segmentJoinValues(c.segments, 1, closed, 1e-12);
            QCOMPARE(int(joins.size()), closed ? 5 : 3);
            for (const auto& j : joins)
                QVERIFY(j.equal);
        }
        const QString text = tab.exactPanel()->plainText();
        QVERIFY(text.contains(QStringLiteral("✓")));
        QVERIFY2(!text.contains(QStringLiteral("✗")), qPrintable(text));
        // Ex 2.13, τ = 1/2 selected: the tangent at q1 is (q2 − q0)/2 = (3/2, −5/2) from both sides.
        QVERIFY(text.contains(QStringLiteral("′(1) = (3/2, -5/2)")));
        QVERIFY(text.contains(QStringLiteral("′(0) = (3/2, -5/2)")));
    }

    void centripetalJoinsAreG1()
    {
        CatmullRomTab tab;
        tab.pointEditor()->setPoints({{0, 0}, {1, 0}, {5, 3}, {6, 3}, {6, 8}}, QStringLiteral("test"));
        tab.setSpacing(CatmullRomSpacing::Centripetal);
        QVERIFY(tab.exactPanel()->plainText().contains(QStringLiteral("G¹")));
        QVERIFY(allFinite(tab.scene()));
    }

    void curvesInterpolateThePoints_data()
    {
        QTest::addColumn<int>("ends");
        QTest::addColumn<int>("spacing");
        QTest::newRow("open uniform") << int(CatmullRomEnds::Open) << int(CatmullRomSpacing::Uniform);
        QTest::newRow("closed uniform") << int(CatmullRomEnds::Closed) << int(CatmullRomSpacing::Uniform);
        QTest::newRow("cyclic chordal") << int(CatmullRomEnds::Cyclic) << int(CatmullRomSpacing::Chordal);
        QTest::newRow("segment centripetal") << int(CatmullRomEnds::Segment) << int(CatmullRomSpacing::Centripetal);
    }
    void curvesInterpolateThePoints()
    {
        QFETCH(int, ends);
        QFETCH(int, spacing);
        CatmullRomTab tab;
        const auto pts = ex213Points();
        tab.pointEditor()->setPoints(pts, QStringLiteral("test"));
        tab.setEnds(CatmullRomEnds(ends));
        tab.setSpacing(CatmullRomSpacing(spacing));
        const int per = CatmullRomScene::kSamplesPerSegment;
        const int first = CatmullRomEnds(ends) == CatmullRomEnds::Segment ? 1 : 0;
        const int n = int(pts.size());
        for (const auto& c : tab.scene().curves) {
            QVERIFY(c.error.isEmpty());
            const int segments = int(c.samples.size()) / per;
            QVERIFY(segments >= 2);
            for (int s = 0; s < segments; ++s) {
                QVERIFY(near(c.samples[std::size_t(s * per)], pts[std::size_t((s + first) % n)]));
                QVERIFY(near(c.samples[std::size_t(s * per + per - 1)], pts[std::size_t((s + first + 1) % n)]));
            }
        }
    }

    void blendingPlot()
    {
        CatmullRomTab tab;
        QCOMPARE(tab.blendingPlot()->graphCount(), 4); // w0..w3 of the selected τ
        QVERIFY(tab.loadExample(example("2.12")));
        QVERIFY(tab.settings().allTausInPlot);
        QCOMPARE(int(tab.settings().taus.size()), 4);
        QCOMPARE(tab.blendingPlot()->graphCount(), 4 * 4 + 4); // and one legend key per τ
        // Ex 2.12, τ = −2: w0 = 2t − 4t² + 2t³ … exactly in the panel.
        const QString text = tab.exactPanel()->plainText();
        for (const char* w : {"2t - 4t^2 + 2t^3", "1 - 5t^2 + 4t^3", "-2t + 7t^2 - 4t^3", "2t^2 - 2t^3", "1 - t^2", "2t - t^2"})
            QVERIFY2(text.contains(QLatin1String(w)), w);
        // Partition of unity in the plot: Σ_j w_j(t) = 1 for the first τ's four graphs.
        for (int k = 0; k < 101; k += 10) {
            double sum = 0;
            for (int j = 0; j < 4; ++j)
                sum += (tab.blendingPlot()->graph(j)->data()->begin() + k)->value;
            QVERIFY(std::fabs(sum - 1) < 1e-12);
        }
    }

    void exampleLoadIsOneUndoStep()
    {
        CatmullRomTab tab;
        const auto points = tab.pointEditor()->points();
        const auto settings = tab.settings();
        const int count = tab.undoStack()->count();
        QVERIFY(tab.loadExample(example("2.13")));
        QCOMPARE(tab.undoStack()->count(), count + 1);
        QVERIFY(tab.pointEditor()->points() != points);
        tab.undoStack()->undo();
        QCOMPARE(tab.pointEditor()->points(), points);
        QVERIFY(tab.settings() == settings);
        QVERIFY(!tab.loadExample(example("2.2"))); // not this tab's
    }

    void saveLoadRoundTrip()
    {
        CatmullRomTab tab;
        QVERIFY(tab.loadExample(example("2.13")));
        QVERIFY(tab.addTension(QStringLiteral("1/3")));
        tab.setEnds(CatmullRomEnds::Closed);
        tab.setSpacing(CatmullRomSpacing::Centripetal);
        tab.setBezierVisible(true);
        tab.setSplineVisible(true);
        tab.setSplineEnds(granota::SplineEnds::Clamped);
        tab.setSplineSlopes(granota::frac(1, 2), granota::Rational(-3));
        tab.setCatmullRomVisible(false);
        const QJsonObject saved = tab.saveState();
        QCOMPARE(saved.value(QStringLiteral("spline_ends")).toString(), QStringLiteral("clamped"));
        QCOMPARE(saved.value(QStringLiteral("spline_end_slope")).toString(), QStringLiteral("-3"));
        QCOMPARE(saved.value(QStringLiteral("taus")).toArray().last().toString(), QStringLiteral("1/3"));
        // Through text, as a document would.
        const QJsonObject reread = QJsonDocument::fromJson(QJsonDocument(saved).toJson()).object();

        CatmullRomTab other;
        QString error;
        QVERIFY2(other.loadState(reread, &error), qPrintable(error));
        QCOMPARE(other.pointEditor()->points(), tab.pointEditor()->points());
        QVERIFY(other.settings() == tab.settings());
        QCOMPARE(other.saveState(), saved);
        QCOMPARE(other.exactPanel()->plainText(), tab.exactPanel()->plainText());
        QCOMPARE(int(other.scene().bezier.size()), CatmullRomScene::kBezierSamples);
    }

    // A tension written as a JSON number by hand is the decimal written: 0.1 is 1/10 (the
    // shortest decimal of the double), not 10000000000000001/100000000000000000.
    void numericTensionIsTheDecimalWritten()
    {
        CatmullRomTab tab;
        QString error;
        const QJsonObject state =
            QJsonDocument::fromJson("{\"points\": [[0, 0], [1, 1], [2, 0]], \"taus\": [0.1, 0.05688]}").object();
        QVERIFY2(tab.loadState(state, &error), qPrintable(error));
        QCOMPARE(int(tab.settings().taus.size()), 2);
        QCOMPARE(granota::toString(tab.settings().taus[0]), std::string("1/10"));
        QCOMPARE(granota::toString(tab.settings().taus[1]), std::string("711/12500"));
    }

    void loadStateRejectsGarbage_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::newRow("empty") << QByteArray("{}");
        QTest::newRow("points not a list") << QByteArray("{\"points\": 7, \"taus\": [\"1/2\"]}");
        QTest::newRow("one point") << QByteArray("{\"points\": [[1, 2]], \"taus\": [\"1/2\"]}");
        QTest::newRow("nan point") << QByteArray("{\"points\": [[\"nan\", 1], [2, 3]], \"taus\": [\"1/2\"]}");
        QTest::newRow("short point") << QByteArray("{\"points\": [[1], [2, 3]], \"taus\": [\"1/2\"]}");
        QTest::newRow("tau out of range") << QByteArray("{\"points\": [[0, 0], [1, 1]], \"taus\": [\"11\"]}");
        QTest::newRow("tau garbage") << QByteArray("{\"points\": [[0, 0], [1, 1]], \"taus\": [\"x\"]}");
        QTest::newRow("no taus") << QByteArray("{\"points\": [[0, 0], [1, 1]], \"taus\": []}");
        QTest::newRow("duplicate taus") << QByteArray("{\"points\": [[0, 0], [1, 1]], \"taus\": [\"1/2\", \"0.5\"]}");
        QTest::newRow("bad mode") << QByteArray("{\"points\": [[0, 0], [1, 1]], \"taus\": [\"1/2\"], \"mode\": \"loop\"}");
        QTest::newRow("bad selection") << QByteArray("{\"points\": [[0, 0], [1, 1]], \"taus\": [\"1/2\"], \"selected_tau\": 3}");
        QTest::newRow("bad flag") << QByteArray("{\"points\": [[0, 0], [1, 1]], \"taus\": [\"1/2\"], \"spline\": 2}");
        QTest::newRow("bad curvature flag") << QByteArray(
            "{\"points\": [[0, 0], [1, 1]], \"taus\": [\"1/2\"], \"curvature_plot\": \"yes\"}");
    }
    void loadStateRejectsGarbage()
    {
        QFETCH(QByteArray, json);
        CatmullRomTab tab;
        QVERIFY(tab.addTension(QStringLiteral("3")));
        const QJsonObject before = tab.saveState();
        const QString panel = tab.exactPanel()->plainText();
        QString error;
        QVERIFY(!tab.loadState(QJsonDocument::fromJson(json).object(), &error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(tab.saveState(), before);
        QCOMPARE(tab.exactPanel()->plainText(), panel);
    }

    void stiffCases_data()
    {
        QTest::addColumn<double>("scale");
        QTest::newRow("1e9") << 1e9;
        QTest::newRow("1e-9") << 1e-9;
        QTest::newRow("1") << 1.0;
    }
    void stiffCases()
    {
        QFETCH(double, scale);
        CatmullRomTab tab;
        showTab(tab);
        // Duplicate points, huge or tiny coordinates, extreme tensions, every mode and the comparisons.
        std::vector<Point> pts = {{0, 0}, {1 * scale, 2 * scale}, {1 * scale, 2 * scale}, {3 * scale, 0}, {4 * scale, scale}};
        tab.pointEditor()->setPoints(pts, QStringLiteral("test"));
        QVERIFY(tab.addTension(QStringLiteral("-10")));
        QVERIFY(tab.addTension(QStringLiteral("10")));
        tab.setBezierVisible(true);
        tab.setSplineVisible(true); // x not strictly increasing (duplicate): refused with a message
        QVERIFY(!tab.scene().splineError.isEmpty());
        for (auto ends : {CatmullRomEnds::Open, CatmullRomEnds::Cyclic, CatmullRomEnds::Closed, CatmullRomEnds::Segment})
            for (auto spacing : {CatmullRomSpacing::Uniform, CatmullRomSpacing::Centripetal, CatmullRomSpacing::Chordal}) {
                tab.setEnds(ends);
                tab.setSpacing(spacing);
                QVERIFY(allFinite(tab.scene()));
                for (const auto& c : tab.scene().curves)
                    QVERIFY2(c.error.isEmpty(), qPrintable(c.error));
                const QString text = tab.exactPanel()->plainText().toLower();
                QVERIFY(!text.contains(QStringLiteral("nan")) && !text.contains(QStringLiteral("inf ")));
            }
        tab.fitView();
        QImage image(400, 300, QImage::Format_ARGB32);
        QPainter painter(&image);
        tab.canvas()->render(painter, QRectF(0, 0, 400, 300)); // draws without crashing
        QVERIFY(!tab.csv().contains(QStringLiteral("nan")));
        QVERIFY(tab.tikz().contains(QStringLiteral("tikzpicture")));
    }

    void csvHasPointsThenSamples()
    {
        CatmullRomTab tab;
        const QStringList lines = tab.csv().split(QLatin1Char('\n'));
        QCOMPARE(lines[0], QStringLiteral("point,x,y"));
        QCOMPARE(lines[1], QStringLiteral("q0,1,1"));
        QVERIFY(lines.contains(QStringLiteral("tau,segment,t,x,y")));
        // τ = 1/2, segment 2 (Ex 2.11's), t = 0 is q1 = (3, 4).
        QVERIFY(lines.contains(QStringLiteral("1/2,2,0,3,4")));
        const int rows = int(lines.filter(QRegularExpression(QStringLiteral("^(0|1/2|2),"))).size());
        QCOMPARE(rows, 3 * 3 * CatmullRomScene::kSamplesPerSegment);
    }

    // §2.3 made visible: one κ(s) graph per curve on the canvas, the axes say what they are.
    void curvaturePlotHasOneGraphPerCurve()
    {
        CatmullRomTab tab;
        QVERIFY(!tab.settings().curvaturePlot);
        tab.setCurvaturePlot(true);
        QCustomPlot* plot = tab.blendingPlot();
        QCOMPARE(plot->graphCount(), 3); // τ = 0, 1/2, 2
        QCOMPARE(plot->xAxis->label(), QStringLiteral("arc length s"));
        QCOMPARE(plot->yAxis->label(), QStringLiteral("curvature κ"));
        for (const char* tau : {"0", "1/2", "2"})
            QVERIFY2(graphNamed(plot, QStringLiteral("τ = %1").arg(QLatin1String(tau))), tau);
        tab.setBezierVisible(true);
        QCOMPARE(plot->graphCount(), 4);
        QVERIFY(graphNamed(plot, QStringLiteral("Bézier")));
        tab.setCompareEnds(true);
        QCOMPARE(plot->graphCount(), 7);
        tab.setSplineVisible(true); // Ex 2.11's x are not increasing: no spline, no graph
        QVERIFY(!tab.scene().splineError.isEmpty());
        QCOMPARE(plot->graphCount(), 7);
        QVERIFY(tab.loadExample(example("2.1"))); // τ = 1/2 and the spline; the plot stays κ(s)
        QVERIFY(tab.settings().curvaturePlot);
        QCOMPARE(plot->graphCount(), 2);
        QVERIFY(graphNamed(plot, QStringLiteral("cubic spline C²")));
        // Open, 4 points: 3 segments, so 2 knots marked for the selected τ.
        QCOMPARE(plot->itemCount(), 2);
        // The τ = 0 curve of Ex 2.11 is straight segments: κ = 0 wherever it is defined.
        tab.undoStack()->undo();
        for (const auto& d : *graphNamed(plot, QStringLiteral("τ = 0"))->data())
            QVERIFY(std::isnan(d.value) || std::fabs(d.value) < 1e-9);
        tab.setCurvaturePlot(false);
        QCOMPARE(plot->itemCount(), 0);
        QCOMPARE(plot->xAxis->label(), QStringLiteral("t"));
    }

    // 200 points, 10 tensions, both end modes: 3980 segments, so many that even the minimum
    // per segment (both ends and inside) exceeds the κ(s) sample budget: each gets just that;
    // a short curve keeps 41 per segment.
    void curvatureSamplesStayWithinTheBudget()
    {
        std::vector<Point> points;
        for (int i = 0; i < CatmullRomSettings::kMaxPoints; ++i)
            points.push_back({double(i), std::sin(i * 0.7)});
        CatmullRomSettings s;
        s.taus.clear();
        for (int k = 0; k < CatmullRomSettings::kMaxTensions; ++k)
            s.taus.push_back(frac(k, 4));
        s.selectedTau = 0;
        s.compareEnds = true;
        s.curvaturePlot = true;
        const CatmullRomScene scene = computeScene(points, s);
        std::size_t segments = 0;
        for (const auto* curves : {&scene.curves, &scene.otherEnds})
            for (const CatmullRomCurve& c : *curves) {
                QCOMPARE(c.curvature.samples.size(), c.segments.size());
                segments += c.segments.size();
                for (const auto& row : c.curvature.samples)
                    QCOMPARE(int(row.size()), CatmullRomScene::kMinCurvatureSamples);
            }
        QCOMPARE(int(segments), 10 * 199 + 10 * 199); // open and cyclic: n segments each
        QVERIFY(segments * CatmullRomScene::kMinCurvatureSamples > std::size_t(CatmullRomScene::kCurvatureSampleBudget));
        const CatmullRomScene small = computeScene(ex213Points(), s);
        QCOMPARE(int(small.curves[0].curvature.samples[0].size()), CatmullRomScene::kSamplesPerSegment);
    }

    // Ex 2.13 (τ = 1/2, cyclic): κ jumps at each interior knot by what the printed segments
    // give on either side; the C² spline of Ex 2.1's points does not jump.
    void curvatureJumpsAtCatmullRomKnotsOnly()
    {
        CatmullRomTab tab;
        QVERIFY(tab.loadExample(example("2.13")));
        tab.setCurvaturePlot(true);
        const QCPGraph* g = graphNamed(tab.blendingPlot(), QStringLiteral("τ = 1/2"));
        QVERIFY(g);
        const auto sides = knotSides(g);
        const Json::Array& printed = *example("2.13").data.find("expected")->find("cyclic")->asArray();
        QCOMPARE(sides.size(), printed.size() - 1); // 4 segments, 3 knots
        for (std::size_t k = 0; k < sides.size(); ++k) {
            QCOMPARE(sides[k].sLeft, sides[k].sRight); // the same point of the curve
            const double left = printedCurvature(printed[k], Rational(1));
            const double right = printedCurvature(printed[k + 1], Rational(0));
            QVERIFY2(std::fabs(right - left) > 0.01, qPrintable(QString::number(right - left)));
            QVERIFY2(std::fabs(sides[k].kappaLeft - left) < 1e-9 && std::fabs(sides[k].kappaRight - right) < 1e-9,
                     qPrintable(QStringLiteral("knot %1: %2 → %3, printed %4 → %5")
                                    .arg(k)
                                    .arg(sides[k].kappaLeft)
                                    .arg(sides[k].kappaRight)
                                    .arg(left)
                                    .arg(right)));
        }

        QVERIFY(tab.loadExample(example("2.1")));
        tab.setSplineEnds(granota::SplineEnds::Natural); // the natural spline: s″ = −32/5, 8/5 at the knots
        const QCPGraph* spline = graphNamed(tab.blendingPlot(), QStringLiteral("cubic spline C²"));
        QVERIFY(spline);
        const auto splineSides = knotSides(spline);
        QCOMPARE(int(splineSides.size()), 2); // 3 pieces
        for (const auto& s : splineSides) {
            QCOMPARE(s.sLeft, s.sRight);
            QVERIFY(std::fabs(s.kappaLeft) > 0.05); // a real test: the spline bends at its knots (s″ = −32/5, 8/5)
            QVERIFY2(std::fabs(s.kappaRight - s.kappaLeft) <= 1e-9 * std::max(1.0, std::fabs(s.kappaLeft)),
                     qPrintable(QStringLiteral("%1 vs %2").arg(s.kappaLeft, 0, 'g', 17).arg(s.kappaRight, 0, 'g', 17)));
        }
    }

    // The exact panel: Ex 2.13's p2 as a Bézier segment, b1 = p1 + τ(p2 − p0)/3 and
    // b2 = p2 − τ(p3 − p1)/3 with p0…p3 = q0…q3, and every knot C¹, not C² (uniform).
    void exactPanelGivesBezierPointsAndKnotOrders()
    {
        CatmullRomTab tab;
        QVERIFY(tab.loadExample(example("2.13")));
        QVERIFY(tab.settings().taus[std::size_t(tab.settings().selectedTau)] == frac(1, 2));
        const auto& q = example("2.13").points;
        const Rational tau = frac(1, 2), three(3);
        const Rational third = tau / three;
        const RPoint b1 = q[1] + third * (q[2] - q[0]);
        const RPoint b2 = q[2] - third * (q[3] - q[1]);
        const auto text = [](const RPoint& p) {
            return QStringLiteral("(%1, %2)").arg(QString::fromStdString(toString(p.x)), QString::fromStdString(toString(p.y)));
        };
        QCOMPARE(text(b1), QStringLiteral("(5/2, 7/6)")); // the formula, by hand
        const QString row = QStringLiteral("p2\t%1\t%2\t%3\t%4").arg(text(q[1]), text(b1), text(b2), text(q[2]));
        const QString plain = tab.exactPanel()->plainText();
        QVERIFY2(plain.contains(row), qPrintable(row));
        // Cyclic, 5 points: 4 segments and 3 knots, each C¹ and G¹ only.
        const QRegularExpression c1(QStringLiteral("^q\\d\tC\\^1\tG\\^1\tΔp″ = "), QRegularExpression::MultilineOption);
        QCOMPARE(int(plain.count(c1)), 3);

        // Ex 2.1: the C² spline's knots are C² and G²; the Catmull-Rom knots through the same points are not.
        QVERIFY(tab.loadExample(example("2.1")));
        const QString spline = tab.exactPanel()->plainText();
        const QRegularExpression c2(QStringLiteral("^q\\d\tC\\^2\tG\\^2\t—\tκ = "), QRegularExpression::MultilineOption);
        QCOMPARE(int(spline.count(c2)), 2);
        QCOMPARE(int(spline.count(c1)), 2);
    }

    // SVG and PDF come from the canvas's painting: the curves are cubic paths there, so the
    // SVG holds `C` commands; the TikZ text writes them as `.. controls .. and ..`.
    void exportsWriteCubicSegments()
    {
        CatmullRomTab tab;
        showTab(tab);
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("cr.svg"));
        QVERIFY(exportSvg(*tab.exportView(), file, QStringLiteral("test")).isEmpty());
        QFile svg(file);
        QVERIFY(svg.open(QIODevice::ReadOnly));
        const QString content = QString::fromUtf8(svg.readAll());
        QVERIFY(content.contains(QRegularExpression(QStringLiteral("\\sd=\"M[^\"]*C"))));
        const QString tikz = tab.tikz();
        // One path per τ, each of three segments: at least 9 Bézier segments.
        QVERIFY2(tikz.count(QStringLiteral(".. controls")) >= 9, qPrintable(tikz));
        QVERIFY(tikz.contains(QRegularExpression(
            QStringLiteral("\\.\\. controls \\([0-9.-]+,[0-9.-]+\\) and \\([0-9.-]+,[0-9.-]+\\) \\.\\. \\("))));
    }

    // TikzWriter's cubic paths: the picture holds the curve, not its control polygon. The arch
    // (0, 0), (0, 10), (10, 10), (10, 0) is 10 wide and, at t = 1/2, 3/4 · 10 high.
    void tikzBezierPathKeepsTheCurvesExtent()
    {
        TikzWriter w;
        w.bezierSegments({{Point(0, 0), Point(0, 10), Point(10, 10), Point(10, 0)}}, Qt::black, 1.0);
        const QString tex = w.str();
        const QRegularExpression box(QStringLiteral("\\\\path \\(([0-9.]+),([0-9.]+)\\) rectangle \\(([0-9.]+),([0-9.]+)\\);"));
        const auto m = box.match(tex);
        QVERIFY2(m.hasMatch(), qPrintable(tex));
        const double width = m.captured(3).toDouble() - m.captured(1).toDouble();
        const double height = m.captured(4).toDouble() - m.captured(2).toDouble();
        QVERIFY2(std::fabs(height / width - 0.75) < 1e-3, qPrintable(tex));
        QVERIFY(tex.contains(QStringLiteral(".. controls")));
        QVERIFY(tex.contains(QStringLiteral("overlay")));
        QCOMPARE(int(tex.count(QStringLiteral(".. controls"))), 1);
    }

    void curvaturePlotIsASavedUndoableSetting()
    {
        CatmullRomTab tab;
        QCheckBox* box = nullptr;
        for (QCheckBox* b : tab.findChildren<QCheckBox*>())
            if (b->text().contains(QStringLiteral("κ(s)")))
                box = b;
        QVERIFY(box);
        QVERIFY(box->focusPolicy() & Qt::TabFocus);
        const int steps = tab.undoStack()->count();
        box->click();
        QVERIFY(tab.settings().curvaturePlot);
        QCOMPARE(tab.undoStack()->count(), steps + 1);
        const QJsonObject saved = tab.saveState();
        QCOMPARE(saved.value(QStringLiteral("curvature_plot")), QJsonValue(true));
        CatmullRomTab other;
        QString error;
        QVERIFY2(other.loadState(QJsonDocument::fromJson(QJsonDocument(saved).toJson()).object(), &error), qPrintable(error));
        QVERIFY(other.settings().curvaturePlot);
        QCOMPARE(other.blendingPlot()->graphCount(), 3);
        tab.undoStack()->undo();
        QVERIFY(!tab.settings().curvaturePlot);
        QVERIFY(!box->isChecked());
        QCOMPARE(tab.blendingPlot()->graphCount(), 4); // the blending functions again
        // A document without the key (older files) keeps the blending functions.
        QJsonObject old = saved;
        old.remove(QStringLiteral("curvature_plot"));
        QVERIFY(other.loadState(old, &error));
        QVERIFY(!other.settings().curvaturePlot);
    }

    void csvHasTheCurvatureWhenPlotted()
    {
        CatmullRomTab tab;
        QVERIFY(!tab.csv().contains(QStringLiteral("kappa")));
        tab.setCurvaturePlot(true);
        const QStringList lines = tab.csv().split(QLatin1Char('\n'));
        const int header = int(lines.indexOf(QStringLiteral("curve,tau,ends,segment,s,kappa")));
        QVERIFY(header > 0);
        int rows = 0;
        for (int i = header + 1; i < lines.size() && !lines[i].isEmpty(); ++i, ++rows)
            QCOMPARE(int(lines[i].count(QLatin1Char(','))), 5); // no decimal commas, in any locale
        QCOMPARE(rows, 3 * 3 * CatmullRomScene::kSamplesPerSegment);
        QVERIFY(lines.contains(
            QStringLiteral("catmull-rom,1/2,open,1,0,%1")
                .arg(QString::fromStdString(granota::formatDouble(*tab.scene().curves[1].curvature.samples[0][0].kappa)))));
    }

    // The side panel's Bézier points of the spline's graph are those of the spline with the
    // ends chosen, not always the natural one (it solved a natural spline of its own there).
    // Points (0,0), (1,1), (2,0): symmetric about x = 1, so s′(1) = 0. Clamped with s′(0) = 0,
    // the first piece is the Hermite cubic 3x² − 2x³ and its graph's b1 = b0 + (1, s′(0))/3 =
    // (1/3, 0); natural (s″(0) = 0) it is 3x/2 − x³/2, b1 = (1/3, 1/2). By hand, not by the code.
    void splineBezierPointsFollowTheChosenEnds()
    {
        const std::vector<Point> points{{0, 0}, {1, 1}, {2, 0}};
        CatmullRomSettings s;
        s.spline = true;
        s.splineEnds = SplineEnds::Clamped;
        const auto panel = [&] {
            return CatmullRomReport::html(points, s, computeScene(points, s), computeAnalysis(smallRationalPoints(points), s));
        };
        const QString clamped = panel();
        QVERIFY2(clamped.contains(QStringLiteral("(1/3, 0)")), qPrintable(clamped));
        QVERIFY(!clamped.contains(QStringLiteral("(1/3, 1/2)")));
        s.splineEnds = SplineEnds::Natural;
        const QString natural = panel();
        QVERIFY(natural.contains(QStringLiteral("(1/3, 1/2)")));
        QVERIFY(!natural.contains(QStringLiteral("(1/3, 0)")));
    }


    // Alt+letter: no two controls of the tab share one, in either language.
    // Matlab Rep_CatmullRom with puntvis = false: the points q_i (handles, labels, polygon) leave the
    // canvas, the PNG export (File ▸ Export) and the TikZ; the curves through them stay. One undo
    // step; "control_points" round-trips, absent means shown.
    void pointsCanBeHidden()
    {
        CatmullRomTab tab;
        showTab(tab);
        const auto png = [&tab] {
            QTemporaryDir dir;
            const QString file = dir.filePath(QStringLiteral("c.png"));
            const QString error = granota::ui::exportPng(*tab.exportView(), file);
            return error.isEmpty() ? QImage(file) : QImage();
        };
        const auto near = [](const QColor& a, const QColor& b) {
            return std::abs(a.red() - b.red()) + std::abs(a.green() - b.green()) + std::abs(a.blue() - b.blue()) < 40;
        };
        const granota::Point q1 = tab.pointEditor()->points()[1];
        const QPoint at = tab.canvas()->view().toScreen(q1).toPoint(); // a 96-DPI PNG has the canvas's pixels
        const QColor handle = tab.canvas()->style().handle;
        const QImage shown = png();
        QVERIFY(!shown.isNull());
        QVERIFY(near(shown.pixelColor(at), handle));
        QVERIFY(tab.tikz().contains(QStringLiteral("q_{1}")));
        QCheckBox* box = nullptr;
        for (QCheckBox* b : tab.findChildren<QCheckBox*>())
            if (b->text() == QStringLiteral("Poin&ts"))
                box = b;
        QVERIFY(box);
        const int steps = tab.undoStack()->count();
        box->click();
        QCOMPARE(tab.undoStack()->count(), steps + 1);
        QCOMPARE(tab.saveState().value(QStringLiteral("control_points")).toBool(true), false);
        const QImage hidden = png();
        QVERIFY(!near(hidden.pixelColor(at), handle));
        // The curves still pass through q1 (Catmull-Rom interpolates): the colour of one of them is there.
        bool curve = false;
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx)
                for (const Rational& tau : tab.settings().taus)
                    curve = curve || near(hidden.pixelColor(at + QPoint(dx, dy)), tensionColour(tau));
        QVERIFY(curve);
        const QString tex = tab.tikz();
        QVERIFY(!tex.contains(QStringLiteral("q_{")));
        QVERIFY(tex.contains(QStringLiteral("tau = 1/2")));
        QCOMPARE(tab.pointEditor()->pick(at), -1);

        const QJsonObject state = tab.saveState();
        CatmullRomTab other;
        QString error;
        QVERIFY2(other.loadState(QJsonDocument::fromJson(QJsonDocument(state).toJson()).object(), &error), qPrintable(error));
        QCOMPARE(other.saveState(), state);
        QVERIFY(!other.settings().controlPoints);
        QJsonObject old = state;
        old.remove(QStringLiteral("control_points"));
        QVERIFY2(other.loadState(old, &error), qPrintable(error));
        QVERIFY(other.settings().controlPoints);
        QJsonObject bad = state;
        bad.insert(QStringLiteral("control_points"), QStringLiteral("no"));
        QVERIFY(!other.loadState(bad, &error));

        tab.undoStack()->undo();
        QVERIFY(tab.settings().controlPoints && box->isChecked());
        QVERIFY(near(png().pixelColor(at), handle));
        tab.undoStack()->redo();
        QVERIFY(!tab.settings().controlPoints && !box->isChecked());
    }

    void mnemonicsDoNotClash_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("ca") << QStringLiteral("ca");
    }
    void mnemonicsDoNotClash()
    {
        QFETCH(QString, language);
        QVERIFY(granota::ui::setLanguage(language, false));
        {
            CatmullRomTab tab;
            tab.retranslate();
            QMap<QChar, QString> seen;
            QStringList clashes;
            auto add = [&](const QString& text) {
                const QChar m = mnemonic(text);
                if (m.isNull())
                    return;
                if (seen.contains(m))
                    clashes << QStringLiteral("%1: “%2” and “%3”").arg(m, seen[m], text);
                seen[m] = text;
            };
            for (QAbstractButton* b : tab.findChildren<QAbstractButton*>())
                add(b->text());
            for (QLabel* l : tab.findChildren<QLabel*>())
                if (l->buddy())
                    add(l->text());
            for (QGroupBox* g : tab.findChildren<QGroupBox*>())
                add(g->title());
            QVERIFY(seen.size() >= 8);
            QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QStringLiteral("; "))));
        }
        QVERIFY(granota::ui::setLanguage(QStringLiteral("en"), false));
    }
};

GRANOTA_TEST_MAIN(TestGuiCatmullRom)
#include "test_gui_catmull_rom.moc"
