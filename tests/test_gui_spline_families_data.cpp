// The Catmull-Rom tab's families "C² spline in the plane" and "function data" (issue 37,
// docs/spline-families.md): the d3-shape #38 data's overshoot measured against a natural
// spline solved here by hand, the monotone schemes' zero, the closed spline through a
// square's corners against its closed form, clamped tangents, the translated refusals, and
// the families' settings through their JSON.
#include "core/exact/polynomial_text.h"
#include "ui/catmull_rom/catmull_rom_tab.h"
#include "ui/catmull_rom/function_data_curves.h"
#include "ui/catmull_rom/function_data_panel.h"
#include "ui/catmull_rom/plane_spline_curves.h"
#include "ui/catmull_rom/plane_spline_panel.h"
#include "ui/catmull_rom/spline_family_examples.h"
#include "ui/catmull_rom/spline_family_panels.h"
#include "ui/common/exact_panel.h"
#include "ui/common/number_text.h"
#include "ui/common/point_editor.h"

#include <QCheckBox>
#include <QComboBox>
#include <QJsonDocument>
#include <QLabel>
#include <QLineEdit>
#include <QSignalSpy>
#include <QPushButton>
#include <QTableWidget>
#include <QUndoStack>
#include <QTest>
#include "tests/test_main.h"

#include <array>
#include <cmath>
#include <vector>

using namespace granota;
using namespace granota::ui;

namespace {

/// d3-shape #38's data.
const std::vector<Point> kD3Data{{0, 224}, {100, 200}, {107, 180}, {502, 300}, {580, 120}, {607, 148}, {900, 400}};

/// The natural spline's second derivatives M_0..M_k through `data`, solved here by the Thomas
/// algorithm on h_{i−1}M_{i−1} + 2(h_{i−1} + h_i)M_i + h_iM_{i+1} = 6(Δ_i − Δ_{i−1}), M_0 = M_k = 0
/// (the textbook system, written out again so that the core's solver is not its own witness).
std::vector<double> handNaturalSecondDerivatives(const std::vector<Point>& data)
{
    const std::size_t k = data.size() - 1;
    std::vector<double> h(k), delta(k);
    for (std::size_t i = 0; i < k; ++i) {
        h[i] = data[i + 1].x - data[i].x;
        delta[i] = (data[i + 1].y - data[i].y) / h[i];
    }
    const std::size_t n = k - 1;
    std::vector<double> a(n), b(n), c(n), r(n);
    for (std::size_t j = 0; j < n; ++j) {
        a[j] = h[j];
        b[j] = 2 * (h[j] + h[j + 1]);
        c[j] = h[j + 1];
        r[j] = 6 * (delta[j + 1] - delta[j]);
    }
    for (std::size_t j = 1; j < n; ++j) {
        const double w = a[j] / b[j - 1];
        b[j] -= w * c[j - 1];
        r[j] -= w * r[j - 1];
    }
    std::vector<double> m(k + 1, 0.0);
    for (std::size_t j = n; j-- > 0;)
        m[j + 1] = (r[j] - (j + 1 < n ? c[j] * m[j + 2] : 0.0)) / b[j];
    return m;
}

} // namespace

class TestGuiSplineFamiliesData : public QObject {
    Q_OBJECT

private slots:
    void d3NaturalSplineOvershootsByAbout98()
    {
        const FunctionDataScene scene = computeFunctionDataScene(kD3Data, FunctionDataSettings{}, false);
        QVERIFY(scene.error.isEmpty());
        QCOMPARE(scene.curves.size(), std::size_t(4));
        const FunctionDataCurveShape& natural = scene.curves[0];
        QCOMPARE(natural.curve, FunctionDataCurve::Natural);

        // The piece on [107, 502] from the hand-solved M_i: s(x) = y_2 + b t + M_2/2 t² + (M_3 − M_2)/(6h) t³,
        // t = x − 107; its minimum where s′ changes sign from − to +, found by bisection.
        const std::vector<double> m = handNaturalSecondDerivatives(kD3Data);
        const double x0 = 107, h = 502 - 107, y0 = 180, y1 = 300;
        const double b = (y1 - y0) / h - h * (2 * m[2] + m[3]) / 6;
        const auto s = [&](double t) { return y0 + b * t + m[2] / 2 * t * t + (m[3] - m[2]) / (6 * h) * t * t * t; };
        const auto ds = [&](double t) { return b + m[2] * t + (m[3] - m[2]) / (2 * h) * t * t; };
        QVERIFY(ds(0) < 0); // it leaves 180 downwards: the dip d3-shape #38 reports
        double lo = 0, hi = h;
        for (int j = 1; j <= 1000; ++j) // the first sign change of s′ on a grid of 1000 steps
            if (ds(h * j / 1000) >= 0) {
                lo = h * (j - 1) / 1000;
                hi = h * j / 1000;
                break;
            }
        QVERIFY(hi < h);
        for (int iteration = 0; iteration < 200; ++iteration) {
            const double mid = (lo + hi) / 2;
            (ds(mid) < 0 ? lo : hi) = mid;
        }
        const double expected = y0 - s((lo + hi) / 2);
        QVERIFY2(std::fabs(expected - 98) < 1, qPrintable(QString::number(expected))); // "about 98"

        QCOMPARE(natural.overshoot.size(), std::size_t(6));
        QVERIFY(!natural.overshoot[2].above);
        QVERIFY2(std::fabs(natural.overshoot[2].amount - expected) < 1e-6,
                 qPrintable(QStringLiteral("%1 vs %2").arg(natural.overshoot[2].amount).arg(expected)));
        QVERIFY(std::fabs(x0 + h * natural.overshoot[2].at - (x0 + (lo + hi) / 2)) < 1e-6);
        // The largest of the curve is that dip, and it is shaded.
        QCOMPARE(natural.largestInterval, 2);
        QCOMPARE(natural.largestOvershoot, natural.overshoot[2].amount);
        QVERIFY(!natural.overshootRegions.empty());
    }

    void d3MonotoneSchemesMeasureZero()
    {
        const FunctionDataScene scene = computeFunctionDataScene(kD3Data, FunctionDataSettings{}, false);
        QCOMPARE(scene.curves.size(), std::size_t(4));
        for (const FunctionDataCurveShape& shape : scene.curves) {
            if (shape.curve != FunctionDataCurve::FritschCarlson && shape.curve != FunctionDataCurve::Steffen)
                continue;
            // Both stay within each pair of neighbouring data values (monotone_spline.h proves it
            // per piece): every interval measures 0, nothing is shaded.
            QCOMPARE(shape.largestOvershoot, 0.0);
            QCOMPARE(shape.largestInterval, -1);
            QVERIFY(shape.overshootRegions.empty());
            // And the curve does interpolate the data (so 0 is not an empty measure).
            QCOMPARE(shape.segments.size(), kD3Data.size() - 1);
            for (std::size_t i = 0; i < shape.segments.size(); ++i)
                QVERIFY(std::fabs(shape.segments[i].y(1.0) - kD3Data[i + 1].y) < 1e-9);
        }
        // Catmull-Rom τ = 1/2 overshoots these data too (it is C¹ with chord-like tangents).
        QVERIFY(scene.curves[1].largestOvershoot > 0);
    }

    void functionDataCurvesCanBeHidden()
    {
        FunctionDataSettings settings;
        settings.shown = {false, true, false, true};
        const FunctionDataScene scene = computeFunctionDataScene(kD3Data, settings, true);
        QCOMPARE(scene.curves.size(), std::size_t(2));
        QCOMPARE(scene.curves[0].curve, FunctionDataCurve::CatmullRom);
        QCOMPARE(scene.curves[1].curve, FunctionDataCurve::Steffen);
        QVERIFY(!scene.curves[1].curvature.samples.empty());
    }

    void functionDataRefusesNonIncreasingX()
    {
        std::vector<Point> points = kD3Data;
        std::swap(points[2], points[3]);
        const FunctionDataScene scene = computeFunctionDataScene(points, FunctionDataSettings{}, false);
        QCOMPARE(scene.error,
                 FunctionDataCurves::tr("The points are not data y(x): their abscissae must increase strictly from q0 to qn. "
                                        "Move a point, or choose another family: the points are kept."));
        QVERIFY(scene.curves.empty());
    }

    void closedSplineThroughSquareIsSymmetric()
    {
        // Closed uniform spline through the corners P_i of the unit square, centre c: by the
        // symmetry M_i = 3(c − P_i) solves M_{i−1} + 4M_i + M_{i+1} = 6(P_{i+1} − 2P_i + P_{i−1})
        // (P_{i−1} + P_{i+1} = 2c), and the midpoint formula p(1/2) = (P_i + P_{i+1})/2 − (M_i + M_{i+1})/16
        // gives c + 11/8·(m_i − c), m_i the edge's midpoint: at 11/16 from the centre.
        const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        PlaneSplineSettings settings;
        settings.ends = ParametricEnds::Periodic;
        const PlaneSplineScene scene = computePlaneSplineScene(square, settings, false);
        QVERIFY2(scene.spline.error.isEmpty(), qPrintable(scene.spline.error));
        QCOMPARE(scene.spline.bezier.size(), std::size_t(4));
        QCOMPARE(scene.spline.knots.size(), std::size_t(5));
        const Point centre(0.5, 0.5);
        for (const auto& b : scene.spline.bezier) {
            const Point mid = (b[0] + 3.0 * b[1] + 3.0 * b[2] + b[3]) * (1.0 / 8); // B(1/2)
            QVERIFY2(std::fabs(std::hypot(mid.x - centre.x, mid.y - centre.y) - 11.0 / 16) < 1e-12,
                     qPrintable(QStringLiteral("(%1, %2)").arg(mid.x).arg(mid.y)));
        }
        // Closed: the last segment ends where the first starts.
        const Point gap = scene.spline.bezier.back()[3] - scene.spline.bezier.front()[0];
        QVERIFY(std::hypot(gap.x, gap.y) < 1e-12);
        // The comparison is the closed Catmull-Rom curve of the same 4 points.
        QCOMPARE(scene.catmullRom.bezier.size(), std::size_t(4));
    }

    void clampedEndsHaveTheAskedTangents()
    {
        PlaneSplineSettings settings;
        settings.ends = ParametricEnds::Clamped;
        settings.startTangent = RPoint(Rational(2), frac(-1, 2));
        settings.endTangent = RPoint(Rational(0), Rational(3));
        const std::vector<Point> points{{0, 0}, {1, 2}, {3, 1}, {4, 4}};
        const PlaneSplineScene scene = computePlaneSplineScene(points, settings, false);
        QVERIFY(scene.spline.error.isEmpty());
        // With uniform parameters (h = 1) the tangent at a Bézier end is 3(b_1 − b_0), 3(b_3 − b_2).
        const auto& first = scene.spline.bezier.front();
        const auto& last = scene.spline.bezier.back();
        const Point start = 3.0 * (first[1] - first[0]), end = 3.0 * (last[3] - last[2]);
        QVERIFY(std::fabs(start.x - 2) < 1e-12 && std::fabs(start.y + 0.5) < 1e-12);
        QVERIFY(std::fabs(end.x) < 1e-12 && std::fabs(end.y - 3) < 1e-12);
    }

    void planeSplineRefusalsAreTranslatedSentences()
    {
        PlaneSplineSettings closed;
        closed.ends = ParametricEnds::Periodic;
        QCOMPARE(computePlaneSplineScene({{0, 0}, {1, 1}}, closed, false).spline.error,
                 PlaneSplineCurves::tr("A closed C² spline needs at least 3 points."));
        PlaneSplineSettings chord;
        chord.parameters = SplineParameters::Chord;
        const PlaneSplineScene repeated = computePlaneSplineScene({{0, 0}, {1, 1}, {1, 1}, {2, 0}}, chord, false);
        QCOMPARE(repeated.spline.error, PlaneSplineCurves::tr("Points q%1 and q%2 coincide: %3 parameters need distinct "
                                                              "consecutive points (use uniform parameters, or move one).")
                                            .arg(1)
                                            .arg(2)
                                            .arg(planeSplineParametersLabel(SplineParameters::Chord)));
        QVERIFY(repeated.spline.bezier.empty());
        // Uniform parameters take the same points.
        QVERIFY(computePlaneSplineScene({{0, 0}, {1, 1}, {1, 1}, {2, 0}}, PlaneSplineSettings{}, false).spline.error.isEmpty());
    }

    void overshootTableListsEachCurve()
    {
        const FunctionDataScene scene = computeFunctionDataScene(kD3Data, FunctionDataSettings{}, false);
        FunctionDataPanel panel;
        panel.showSettings(FunctionDataSettings{}, scene, kD3Data);
        QTableWidget* table = panel.overshootTable();
        QCOMPARE(table->rowCount(), 4);
        QCOMPARE(table->item(0, 0)->text(), functionDataCurveLabel(FunctionDataCurve::Natural));
        // The natural spline's row: 98.25 (the first test's value, to 4 digits) on [107, 502].
        QCOMPARE(table->item(0, 1)->text(), displaySignificant(scene.curves[0].largestOvershoot, 4));
        QVERIFY(table->item(0, 1)->text().startsWith(QStringLiteral("98")));
        QVERIFY(table->item(0, 2)->text().contains(QStringLiteral("107")));
        QCOMPARE(table->item(2, 1)->text(), displaySignificant(0.0, 4));
        QCOMPARE(table->item(2, 2)->text(), QStringLiteral("—"));
        QVERIFY(panel.errorLabel()->isHidden());

        // Unticking Steffen asks for the same settings without it, nothing else.
        QSignalSpy asked(&panel, &FunctionDataPanel::changeRequested);
        panel.curveCheck(FunctionDataCurve::Steffen)->click();
        QCOMPARE(asked.count(), 1);
        FunctionDataSettings expected;
        expected.shown[3] = false;
        QVERIFY(asked.at(0).at(0).value<FunctionDataSettings>() == expected);
    }

    void planePanelRefusesABadTangentAndKeepsTheShownOne()
    {
        PlaneSplinePanel panel;
        PlaneSplineSettings clamped;
        clamped.ends = ParametricEnds::Clamped;
        panel.showSettings(clamped, computePlaneSplineScene({{0, 0}, {1, 1}, {2, 0}}, clamped, false));
        QVERIFY(panel.tangentEdits()[0]->isEnabled());
        QSignalSpy asked(&panel, &PlaneSplinePanel::changeRequested);
        QSignalSpy refused(&panel, &PlaneSplinePanel::refused);
        panel.tangentEdits()[1]->setText(QStringLiteral("abc"));
        emit panel.tangentEdits()[1]->editingFinished();
        QCOMPARE(refused.count(), 1);
        QCOMPARE(asked.count(), 0);
        QCOMPARE(panel.tangentEdits()[1]->text(), QStringLiteral("0"));
        panel.tangentEdits()[1]->setText(QStringLiteral("-1/2"));
        emit panel.tangentEdits()[1]->editingFinished();
        QCOMPARE(asked.count(), 1);
        const auto after = asked.at(0).at(0).value<PlaneSplineSettings>();
        QCOMPARE(after.startTangent.y, frac(-1, 2));
        // The ends from the keyboard: the combo box's next item is not-a-knot.
        panel.endsCombo()->setFocus();
        QTest::keyClick(panel.endsCombo(), Qt::Key_Down);
        QCOMPARE(asked.count(), 2);
        QCOMPARE(asked.at(1).at(0).value<PlaneSplineSettings>().ends, ParametricEnds::NotAKnot);
        // Natural ends: the tangents are not asked for.
        panel.showSettings(PlaneSplineSettings{}, PlaneSplineScene{});
        QVERIFY(!panel.tangentEdits()[0]->isEnabled());
    }

    void tabDrawsTheFamilyAndSavesItsSettings()
    {
        CatmullRomTab tab;
        tab.setFamily(CurveFamily::FunctionData);
        QVERIFY(!tab.splinePanels()->isHidden());
        QVERIFY(!tab.splinePanels()->dataPanel()->isHidden());
        QVERIFY(tab.splinePanels()->planePanel()->isHidden());
        // The family's example: d3-shape #38's data, one undo step for the points and settings.
        const int count = tab.undoStack()->count();
        tab.splinePanels()->exampleButton()->click();
        QCOMPARE(tab.undoStack()->count(), count + 1);
        QCOMPARE(tab.pointEditor()->points(), d3Shape38ExamplePoints());
        QCOMPARE(tab.scene().functionData.curves.size(), std::size_t(4));
        QVERIFY(std::fabs(tab.scene().functionData.curves[0].largestOvershoot - 98.25) < 0.01);
        QCOMPARE(tab.legend().entries.size(), std::size_t(4));
        // A curve hidden from the panel: one undo step, and back.
        tab.splinePanels()->dataPanel()->curveCheck(FunctionDataCurve::Natural)->click();
        QCOMPARE(tab.scene().functionData.curves.size(), std::size_t(3));
        QCOMPARE(tab.undoStack()->count(), count + 2);
        tab.undoStack()->undo();
        QCOMPARE(tab.scene().functionData.curves.size(), std::size_t(4));
        QVERIFY(tab.splinePanels()->dataPanel()->curveCheck(FunctionDataCurve::Natural)->isChecked());

        // The plane spline: its example closes the frog's outline points.
        tab.setFamily(CurveFamily::PlaneSpline);
        QVERIFY(tab.splinePanels()->dataPanel()->isHidden());
        tab.splinePanels()->exampleButton()->click();
        QCOMPARE(tab.pointEditor()->points(), frogOutlineExamplePoints());
        QVERIFY(tab.settings().planeSpline.ends == ParametricEnds::Periodic);
        QCOMPARE(tab.scene().planeSpline.spline.bezier.size(), frogOutlineExamplePoints().size());
        QCOMPARE(tab.scene().planeSpline.catmullRom.bezier.size(), frogOutlineExamplePoints().size());

        // Save and load: the family and its settings come back.
        PlaneSplineSettings plane = tab.settings().planeSpline;
        plane.parameters = SplineParameters::Centripetal;
        plane.startTangent = RPoint(frac(1, 2), Rational(3));
        CatmullRomSettings changed = tab.settings();
        changed.planeSpline = plane;
        changed.functionData.shown = {false, true, true, false};
        emit tab.splinePanels()->changeRequested(changed, QStringLiteral("test"));
        const QJsonObject saved = QJsonDocument::fromJson(QJsonDocument(tab.saveState()).toJson()).object();
        CatmullRomTab other;
        QString error;
        QVERIFY2(other.loadState(saved, &error), qPrintable(error));
        QVERIFY(other.settings() == tab.settings());
        QVERIFY(other.settings().family == CurveFamily::PlaneSpline);
        QVERIFY(other.settings().planeSpline == plane);
        QCOMPARE(other.settings().functionData.shown, (std::array<bool, 4>{false, true, true, false}));
        // A bad value in the family's settings is refused with its key, and nothing is lost.
        QJsonObject bad = saved;
        QJsonObject badPlane = bad.value(QStringLiteral("plane_spline")).toObject();
        badPlane.insert(QStringLiteral("ends"), QStringLiteral("loose"));
        bad.insert(QStringLiteral("plane_spline"), badPlane);
        const QJsonObject before = other.saveState();
        QVERIFY(!other.loadState(bad, &error));
        QCOMPARE(other.saveState(), before);
    }

    // The families' exports are cubic Bézier segments (TikZ `.. controls ..`), and the function
    // data's overshoot is filled (one filled polygon per overshooting interval and curve).
    void exportsWriteTheFamiliesAsCubicSegments()
    {
        CatmullRomTab tab;
        tab.setFamily(CurveFamily::FunctionData);
        tab.splinePanels()->exampleButton()->click();
        std::size_t regions = 0;
        for (const auto& shape : tab.scene().functionData.curves)
            regions += shape.overshootRegions.size();
        QVERIFY(regions >= 2); // the natural spline's dips and bumps at least
        const QString tikz = tab.tikz();
        QVERIFY2(tikz.count(QStringLiteral(".. controls")) >= 4 * 6, qPrintable(tikz)); // 4 curves, 6 intervals
        const auto fills = std::size_t(tikz.count(QStringLiteral(", fill=")));
        QVERIFY2(fills >= regions, qPrintable(tikz));
        CatmullRomSettings unshaded = tab.settings();
        unshaded.functionData.shadeOvershoot = false;
        emit tab.splinePanels()->changeRequested(unshaded, QStringLiteral("test"));
        QCOMPARE(std::size_t(tab.tikz().count(QStringLiteral(", fill="))), fills - regions);

        tab.setFamily(CurveFamily::PlaneSpline);
        tab.splinePanels()->exampleButton()->click();
        const QString plane = tab.tikz();
        QVERIFY2(plane.count(QStringLiteral(".. controls")) >= 2 * 10, qPrintable(plane)); // spline and Catmull-Rom
        QVERIFY(plane.contains(QStringLiteral("C2 spline in the plane")));
    }

    // The CSV of the two families: each curve's samples and, for function data, the overshoot
    // per interval. On d3-shape #38's data the natural spline's third interval [107, 502]
    // overshoots by about 98 (solved by hand in d3NaturalSplineOvershootsByAbout98), Fritsch–
    // Carlson by 0 on every interval; the first sample is the first datum (0, 224) at t = 0. The
    // closed spline through the unit square passes, half way along its first segment, at 11/16
    // from the centre below the edge (0,0)–(1,0): (1/2, 1/2 − 11/16) = (1/2, −3/16) (the closed
    // form of closedSplineThroughSquareIsSymmetric).
    void csvWritesTheFamiliesSamples()
    {
        CatmullRomTab tab;
        tab.setFamily(CurveFamily::FunctionData);
        tab.splinePanels()->exampleButton()->click();
        QVERIFY(tab.pointEditor()->points() == kD3Data);
        const QStringList lines = tab.csv().split(QLatin1Char('\n'));
        const auto row = [&lines](const QString& start) {
            for (const QString& line : lines)
                if (line.startsWith(start))
                    return line.split(QLatin1Char(','));
            return QStringList();
        };
        QVERIFY2(lines.contains(QStringLiteral("curve,segment,t,x,y")), qPrintable(lines.join(QLatin1Char('\n')).left(600)));
        QCOMPARE(row(QStringLiteral("natural,1,0,")),
                 (QStringList{QStringLiteral("natural"), QStringLiteral("1"), QStringLiteral("0"), QStringLiteral("0"),
                              QStringLiteral("224")}));
        QVERIFY(lines.contains(QStringLiteral("curve,interval,overshoot")));
        const QStringList afterHeader = lines.mid(int(lines.indexOf(QStringLiteral("curve,interval,overshoot"))));
        QStringList natural;
        for (const QString& line : afterHeader)
            if (line.startsWith(QStringLiteral("natural,3,")))
                natural = line.split(QLatin1Char(','));
        QCOMPARE(natural.size(), 3);
        QVERIFY2(std::fabs(natural[2].toDouble() - 98) < 1, qPrintable(natural.join(QLatin1Char(','))));
        for (int i = 1; i <= 6; ++i)
            QVERIFY(afterHeader.contains(QStringLiteral("fritsch_carlson,%1,0").arg(i)));

        tab.setFamily(CurveFamily::PlaneSpline);
        tab.pointEditor()->setPoints({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, QStringLiteral("square"));
        CatmullRomSettings periodic = tab.settings();
        periodic.planeSpline.ends = ParametricEnds::Periodic;
        emit tab.splinePanels()->changeRequested(periodic, QStringLiteral("test"));
        const QStringList plane = tab.csv().split(QLatin1Char('\n'));
        QStringList middle;
        for (const QString& line : plane)
            if (line.startsWith(QStringLiteral("c2-spline,1,0.5,")))
                middle = line.split(QLatin1Char(','));
        QCOMPARE(middle.size(), 5);
        QVERIFY2(std::fabs(middle[3].toDouble() - 0.5) < 1e-9 && std::fabs(middle[4].toDouble() + 3.0 / 16) < 1e-9,
                 qPrintable(middle.join(QLatin1Char(','))));
        QVERIFY(plane.contains(QStringLiteral("knot,u")));
    }

    // The exact panel lists the C² spline in the plane's segments exactly. The closed uniform
    // spline through the unit square (0,0), (1,0), (1,1), (0,1), solved by hand: the tangents D_i
    // satisfy D_{i−1} + 4D_i + D_{i+1} = 3(P_{i+1} − P_{i−1}); by the square's symmetry D_{i±1} are
    // D_i turned by ±90°, so they cancel and D_i = 3/4 (P_{i+1} − P_{i−1}): D_0 = (3/4, −3/4),
    // D_1 = (3/4, 3/4). Hermite's form p(s) = P_0 + D_0 s + (3(P_1 − P_0) − 2D_0 − D_1) s² +
    // (2(P_0 − P_1) + D_0 + D_1) s³ gives x = 3/4 s + 3/4 s² − 1/2 s³, y = −3/4 s + 3/4 s²
    // (its middle (1/2, −3/16), as csvWritesTheFamiliesSamples reads).
    void exactPanelListsThePlaneSplineSegments()
    {
        CatmullRomTab tab;
        tab.setFamily(CurveFamily::PlaneSpline);
        tab.pointEditor()->setPoints({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, QStringLiteral("square"));
        CatmullRomSettings periodic = tab.settings();
        periodic.planeSpline.ends = ParametricEnds::Periodic;
        emit tab.splinePanels()->changeRequested(periodic, QStringLiteral("test"));
        auto* panel = tab.findChild<ExactPanel*>();
        QVERIFY(panel);
        const QString text = panel->plainText();
        const auto expected = [](std::vector<Rational> c) {
            return QString::fromStdString(toText(Polynomial<Rational>(std::move(c)), "s"));
        };
        const QString x = expected({Rational(0), frac(3, 4), frac(3, 4), frac(-1, 2)});
        const QString y = expected({Rational(0), frac(-3, 4), frac(3, 4)});
        QVERIFY2(text.contains(x) && text.contains(y), qPrintable(x + QStringLiteral(" | ") + y + QStringLiteral("\n") + text));
        // With chord-length parameters the panel gives no table (a chord length is in general a square
        // root), only the sentence.
        CatmullRomSettings chord = tab.settings();
        chord.planeSpline.parameters = SplineParameters::Chord;
        emit tab.splinePanels()->changeRequested(chord, QStringLiteral("test"));
        QVERIFY(!panel->plainText().contains(x));
    }

    void settingsRoundTripThroughJson()
    {
        PlaneSplineSettings plane;
        plane.ends = ParametricEnds::Clamped;
        plane.parameters = SplineParameters::Centripetal;
        plane.startTangent = RPoint(frac(1, 3), Rational(-2));
        plane.endTangent = RPoint(Rational(0), Rational(5));
        plane.catmullRomToo = false;
        FunctionDataSettings data;
        data.shown = {true, false, true, false};
        data.shadeOvershoot = false;
        QJsonObject planeJson, dataJson;
        writePlaneSplineSettings(plane, planeJson);
        writeFunctionDataSettings(data, dataJson);
        // Through text, as a document is saved and read.
        const QJsonObject planeBack = QJsonDocument::fromJson(QJsonDocument(planeJson).toJson()).object();
        const QJsonObject dataBack = QJsonDocument::fromJson(QJsonDocument(dataJson).toJson()).object();
        QCOMPARE(planeBack.value(QStringLiteral("start_tangent")).toString(), QStringLiteral("1/3, -2"));
        const auto planeRead = readPlaneSplineSettings(planeBack, nullptr);
        const auto dataRead = readFunctionDataSettings(dataBack, nullptr);
        QVERIFY(planeRead && *planeRead == plane);
        QVERIFY(dataRead && *dataRead == data);
        QVERIFY(*planeRead != PlaneSplineSettings{});
        QVERIFY(*dataRead != FunctionDataSettings{});
    }

    void settingsRefuseBadValues_data()
    {
        QTest::addColumn<QString>("json");
        QTest::addColumn<QString>("key");
        QTest::newRow("ends") << QString::fromUtf8(R"({"ends": "loose"})") << QStringLiteral("ends");
        QTest::newRow("ends not text") << QString::fromUtf8(R"({"ends": 3})") << QStringLiteral("ends");
        QTest::newRow("parameters") << QString::fromUtf8(R"({"parameters": "chordal"})") << QStringLiteral("parameters");
        QTest::newRow("tangent one number") << QString::fromUtf8(R"({"start_tangent": "1"})") << QStringLiteral("start_tangent");
        QTest::newRow("tangent too large") << QString::fromUtf8(R"({"end_tangent": "1, 10000001"})")
                                           << QStringLiteral("end_tangent");
        QTest::newRow("tangent as array") << QString::fromUtf8(R"({"end_tangent": [1, 0]})") << QStringLiteral("end_tangent");
        QTest::newRow("flag") << QString::fromUtf8(R"({"catmull_rom_too": "yes"})") << QStringLiteral("catmull_rom_too");
    }
    void settingsRefuseBadValues()
    {
        QFETCH(QString, json);
        QFETCH(QString, key);
        QString problem;
        QVERIFY(!readPlaneSplineSettings(QJsonDocument::fromJson(json.toUtf8()).object(), &problem));
        QCOMPARE(problem, key);
        QVERIFY(!readFunctionDataSettings(QJsonDocument::fromJson(R"({"steffen": 1})").object(), &problem));
        QCOMPARE(problem, QStringLiteral("steffen"));
        QVERIFY(parseTangent(QStringLiteral("−1/2 , 0.25")).has_value());
    }
};

GRANOTA_TEST_MAIN(TestGuiSplineFamiliesData)
#include "test_gui_spline_families_data.moc"
