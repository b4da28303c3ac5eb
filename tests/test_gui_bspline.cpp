// The B-spline tab (docs/tabs.md, issue 36): it opens on a clamped cubic; de Boor's net has
// p + 1, p, …, 1 points at u and ends on the point the Cox–de Boor sum gives; a dragged knot
// stops at its neighbour; knot insertion adds a point and leaves the curve as it was (the old
// curve evaluated by the core); an inserted knot is removed again exactly and a needed knot is
// not; degree elevation keeps the curve; undo restores each; a document round-trips and a
// refused one changes nothing; Ex 2.2 as a B-spline is De Casteljau's curve; the circle example
// lies on x² + y² = 1.
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bsplines/de_boor.h"
#include "core/io/worked_examples.h"
#include "ui/bsplines/bspline_examples.h"
#include "ui/bsplines/bspline_report.h"
#include "ui/bsplines/bspline_tab.h"
#include "ui/bsplines/knot_ruler.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/exact_panel.h"
#include "ui/common/point_editor.h"
#include "gui_timeouts.h"

#include <QJsonArray>
#include <QMouseEvent>
#include <QTest>
#include <QUndoStack>
#include "tests/test_main.h"

#include <cmath>

Q_DECLARE_METATYPE(granota::RPoint)

using namespace granota;
using namespace granota::ui;

namespace {

/// N_{i,p}(u) straight from the Cox–de Boor recursion as de Boor wrote it (0/0 = 0), with
/// half-open spans: the test's own, independent of the core's triangle (bspline_basis.h).
Rational coxDeBoor(const std::vector<Rational>& k, int i, int p, const Rational& u)
{
    const auto K = [&](int j) { return k[static_cast<std::size_t>(j)]; };
    if (p == 0)
        return K(i) <= u && u < K(i + 1) ? Rational(1) : Rational(0);
    Rational value(0);
    if (K(i + p) != K(i))
        value += (u - K(i)) / (K(i + p) - K(i)) * coxDeBoor(k, i, p - 1, u);
    if (K(i + p + 1) != K(i + 1))
        value += (K(i + p + 1) - u) / (K(i + p + 1) - K(i + 1)) * coxDeBoor(k, i + 1, p - 1, u);
    return value;
}

/// c(u) = Σ N_{i,p}(u) P_i, for u inside the domain (not at its end).
RPoint sumOfBasis(const BSplineCurve<Rational>& c, const Rational& u)
{
    RPoint sum(Rational(0), Rational(0));
    for (int i = 0; i < c.pointCount(); ++i) {
        const Rational n = coxDeBoor(c.knots, i, c.degree, u);
        sum.x += n * c.points[static_cast<std::size_t>(i)].x;
        sum.y += n * c.points[static_cast<std::size_t>(i)].y;
    }
    return sum;
}

void showTab(BSplineTab& tab)
{
    tab.resize(1280, 760);
    tab.show();
    QVERIFY(waitExposed(&tab));
}

void sendMouse(QWidget* w, QEvent::Type type, QPointF at, Qt::MouseButtons buttons)
{
    QMouseEvent e(type, at, w->mapToGlobal(at), type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton, buttons,
                  Qt::NoModifier);
    QCoreApplication::sendEvent(w, &e);
}

/// The curve's samples at `count` values of u over its domain, by the core.
std::vector<Point> samples(const BSplineCurve<double>& c, int count)
{
    std::vector<Point> out;
    for (int j = 0; j < count; ++j)
        out.push_back(bsplinePoint(c, c.domainStart() + (c.domainEnd() - c.domainStart()) * j / (count - 1)));
    return out;
}

double maxDistance(const std::vector<Point>& a, const std::vector<Point>& b)
{
    double d = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        d = std::max(d, std::hypot(a[i].x - b[i].x, a[i].y - b[i].y));
    return d;
}

std::vector<Rational> rationals(std::initializer_list<std::pair<long, long>> list)
{
    std::vector<Rational> out;
    for (const auto& [p, q] : list)
        out.push_back(frac(p, q));
    return out;
}

} // namespace

class TestGuiBSpline : public QObject {
    Q_OBJECT
private slots:
    void opensOnAClampedCubic()
    {
        BSplineTab tab;
        showTab(tab);
        QCOMPARE(tab.key(), QStringLiteral("bspline"));
        QCOMPARE(tab.pointEditor()->points().size(), std::size_t(6));
        QCOMPARE(tab.scene().degree(), 3);
        // Clamped, n = 5, p = 3: four zeros, i/(n − p + 1) = 1/3, 2/3, four ones (the definition).
        QCOMPARE(tab.knots(), rationals({{0, 1}, {0, 1}, {0, 1}, {0, 1}, {1, 3}, {2, 3}, {1, 1}, {1, 1}, {1, 1}, {1, 1}}));
        QVERIFY(tab.scene().valid());
        QVERIFY(!tab.scene().samples.empty());
        QCOMPARE(tab.knotRuler()->knots().size(), std::size_t(10));
    }

    void deBoorLevelsAtU()
    {
        BSplineTab tab;
        showTab(tab);
        tab.setU(frac(1, 2));
        const BSplineScene& s = tab.scene();
        QVERIFY(s.exactNet.has_value());
        // u = 1/2 lies in [u_4, u_5) = [1/3, 2/3): span 4, points P_1…P_4.
        QCOMPARE(s.span(), 4);
        QCOMPARE(static_cast<int>(s.exactNet->levels.size()), 4);
        for (int r = 0; r <= 3; ++r)
            QCOMPARE(static_cast<int>(s.exactNet->levels[static_cast<std::size_t>(r)].size()), 4 - r);
        // Level 0 is the span's p + 1 control points.
        for (int i = 0; i < 4; ++i)
            QCOMPARE(s.exactNet->levels[0][static_cast<std::size_t>(i)], s.exact.points[static_cast<std::size_t>(1 + i)]);
        // The last level is c(u) = Σ N_{i,3}(u) P_i, by the test's own Cox–de Boor recursion.
        QCOMPARE(s.exactNet->point(), sumOfBasis(s.exact, frac(1, 2)));
        // The drawn net is that exact net rounded.
        QCOMPARE(s.net.levels.size(), std::size_t(4));
        QCOMPARE(s.net.point().x, toDouble(s.exactNet->point().x));
        // Degree 2: three levels, 3, 2, 1.
        QVERIFY(tab.setDegree(2));
        QCOMPARE(tab.scene().exactNet->levels.size(), std::size_t(3));
        QCOMPARE(tab.scene().exactNet->levels.back().size(), std::size_t(1));
    }

    void draggingAKnotStopsAtItsNeighbour()
    {
        BSplineTab tab;
        showTab(tab);
        KnotRuler* ruler = tab.knotRuler();
        const int undoBefore = tab.undoStack()->count();
        // Knot u_4 = 1/3 dragged far beyond u_5 = 2/3 (to where 0.95 is drawn).
        const double y = ruler->height() / 2.0;
        const QPointF from(ruler->toX(1.0 / 3.0), y);
        sendMouse(ruler, QEvent::MouseButtonPress, from, Qt::LeftButton);
        sendMouse(ruler, QEvent::MouseMove, from + QPointF(5, 0), Qt::LeftButton);
        sendMouse(ruler, QEvent::MouseMove, QPointF(ruler->toX(0.8), y), Qt::LeftButton);
        sendMouse(ruler, QEvent::MouseMove, QPointF(ruler->toX(0.95), y), Qt::LeftButton);
        sendMouse(ruler, QEvent::MouseButtonRelease, QPointF(ruler->toX(0.95), y), Qt::NoButton);
        // It met its neighbour and stopped there: a double knot 2/3, the order kept.
        QCOMPARE(tab.knots()[4], frac(2, 3));
        QCOMPARE(tab.knots()[5], frac(2, 3));
        const std::vector<Rational> knots = tab.knots();
        QVERIFY(std::is_sorted(knots.begin(), knots.end()));
        QVERIFY(tab.scene().valid());
        // The whole drag is one undo step.
        QCOMPARE(tab.undoStack()->count(), undoBefore + 1);
        tab.undoStack()->undo();
        QCOMPARE(tab.knots()[4], frac(1, 3));

        // Dragged left past u_3 = 0 (a clamped end of multiplicity p + 1 = 4): it may not meet it
        // (multiplicity 5), so it stays short of it and the knots stay valid.
        const QPointF at(ruler->toX(1.0 / 3.0), y);
        sendMouse(ruler, QEvent::MouseButtonPress, at, Qt::LeftButton);
        sendMouse(ruler, QEvent::MouseMove, at - QPointF(5, 0), Qt::LeftButton);
        sendMouse(ruler, QEvent::MouseMove, QPointF(ruler->toX(-0.5), y), Qt::LeftButton);
        sendMouse(ruler, QEvent::MouseButtonRelease, QPointF(ruler->toX(-0.5), y), Qt::NoButton);
        QVERIFY(tab.knots()[4] > 0);
        QVERIFY(tab.knots()[4] < frac(1, 3));
        QVERIFY(tab.scene().valid());
    }

    // Issue 36: the tab takes 1000 control points (BSplineModel::kMaxPoints; 200 before). Its
    // exact panel lists the first and last 12 of the 998 distinct knots (0, i/997, 1: the clamped
    // definition) around a row of "…", and a point dragged across the canvas leaves the panel
    // showing the final curve once the drag ends (the panel follows a drag on a timer).
    void thousandPoints()
    {
        BSplineTab tab;
        showTab(tab);
        std::vector<Point> points;
        for (int i = 0; i < 1000; ++i)
            points.emplace_back(i / 20.0, 4 * std::sin(i / 14.0));
        tab.pointEditor()->setPoints(points, QStringLiteral("thousand"));
        QCOMPARE(tab.pointEditor()->points().size(), std::size_t(1000));
        QVERIFY(tab.scene().valid());
        QCOMPARE(tab.scene().bezier.size(), std::size_t(997));
        const QString panel = tab.exactPanel()->plainText();
        QVERIFY(panel.contains(QStringLiteral("11/997")));
        QVERIFY(panel.contains(QStringLiteral("986/997")));
        QVERIFY(panel.contains(QStringLiteral("…\t…\t…")));

        CurveCanvas* canvas = tab.canvas();
        const QPointF from = canvas->view().toScreen(tab.pointEditor()->points()[500]);
        sendMouse(canvas, QEvent::MouseButtonPress, from, Qt::LeftButton);
        sendMouse(canvas, QEvent::MouseMove, from + QPointF(0, 10), Qt::LeftButton);
        sendMouse(canvas, QEvent::MouseMove, from + QPointF(0, 40), Qt::LeftButton);
        sendMouse(canvas, QEvent::MouseButtonRelease, from + QPointF(0, 40), Qt::NoButton);
        QVERIFY(tab.pointEditor()->points() != points); // a point moved
        // The same report typeset apart from the tab: what the panel shows now.
        ExactPanel fresh;
        fresh.setContent(bsplineReportHtml(tab.scene()));
        QCOMPARE(tab.exactPanel()->plainText(), fresh.plainText());
    }

    void insertionKeepsTheCurve()
    {
        BSplineTab tab;
        showTab(tab);
        const BSplineCurve<double> before = tab.scene().curve;
        const BSplineCurve<Rational> exactBefore = tab.scene().exact;
        const std::vector<Point> pointsBefore = tab.pointEditor()->points();
        QVERIFY(tab.insertKnot(frac(1, 2)));
        QCOMPARE(tab.pointEditor()->points().size(), pointsBefore.size() + 1);
        QCOMPARE(tab.knots().size(), std::size_t(11));
        QCOMPARE(tab.previousPolygon(), pointsBefore);
        // The same curve: 201 samples of the old curve and the new one by the core (doubles), and
        // exactly at rational parameters.
        QVERIFY(maxDistance(samples(before, 201), samples(tab.scene().curve, 201)) < 1e-12);
        for (const Rational& u : rationals({{0, 1}, {1, 7}, {1, 3}, {1, 2}, {5, 8}, {2, 3}, {99, 100}, {1, 1}}))
            QCOMPARE(bsplinePoint(tab.scene().exact, u), bsplinePoint(exactBefore, u));
        // Undo: the points and the knots as they were, and the old polygon no longer drawn.
        tab.undoStack()->undo();
        QCOMPARE(tab.pointEditor()->points(), pointsBefore);
        QCOMPARE(tab.knots().size(), std::size_t(10));
        QVERIFY(tab.previousPolygon().empty());
        tab.undoStack()->redo();
        QCOMPARE(tab.pointEditor()->points().size(), pointsBefore.size() + 1);
    }

    void removalIsExact()
    {
        BSplineTab tab;
        showTab(tab);
        const std::vector<Point> points = tab.pointEditor()->points();
        const std::vector<Rational> knots = tab.knots();
        // Inserted, then removed: the very points and knots again (geomdl #135 got this wrong).
        QVERIFY(tab.insertKnot(frac(1, 2)));
        const auto inserted = tab.knots();
        const int index = static_cast<int>(std::find(inserted.begin(), inserted.end(), frac(1, 2)) - inserted.begin());
        QVERIFY(tab.removeKnot(index));
        QCOMPARE(tab.pointEditor()->points(), points);
        QCOMPARE(tab.knots(), knots);
        // The curve needs u_4 = 1/3 (the points are not on one cubic across it): refused, unchanged.
        const int undo = tab.undoStack()->count();
        QVERIFY(!tab.removeKnot(4));
        QVERIFY(tab.lastMessage().contains(QStringLiteral("needs")));
        QCOMPARE(tab.knots(), knots);
        QCOMPARE(tab.undoStack()->count(), undo);
    }

    void elevationKeepsTheCurve()
    {
        BSplineTab tab;
        showTab(tab);
        const BSplineCurve<Rational> before = tab.scene().exact;
        QVERIFY(tab.elevateDegree());
        QCOMPARE(tab.scene().degree(), 4);
        // Each of the four distinct knots once more: 14 knots, and 14 − (p + 2) = 9 points (n + p + 2 knots).
        QCOMPARE(tab.knots().size(), before.knots.size() + 4);
        QCOMPARE(tab.pointEditor()->points().size(), std::size_t(9));
        for (const Rational& u : rationals({{0, 1}, {1, 5}, {1, 2}, {3, 4}, {1, 1}}))
            QCOMPARE(bsplinePoint(tab.scene().exact, u), bsplinePoint(before, u));
        tab.undoStack()->undo();
        QCOMPARE(tab.scene().degree(), 3);
        QCOMPARE(tab.scene().exact.points, before.points);
    }

    void documentRoundTrip()
    {
        BSplineTab tab;
        showTab(tab);
        QVERIFY(tab.insertKnot(frac(1, 4)));
        QVERIFY(tab.setWeights(rationals({{1, 1}, {2, 1}, {1, 1}, {1, 2}, {1, 1}, {3, 1}, {1, 1}})));
        tab.setU(frac(3, 5));
        const QJsonObject saved = tab.saveState();
        const BSplineModel model = tab.model();
        const std::vector<Point> points = tab.pointEditor()->points();

        BSplineTab other;
        QString error;
        QVERIFY2(other.loadState(saved, &error), qPrintable(error));
        QCOMPARE(other.pointEditor()->points(), points);
        QVERIFY(other.model() == model);
        QCOMPARE(other.scene().exactNet->point(), tab.scene().exactNet->point());
    }

    void refusedDocumentChangesNothing_data()
    {
        QTest::addColumn<QString>("key");
        QTest::addColumn<QJsonValue>("value");
        QTest::newRow("decreasing knots") << "knots"
                                          << QJsonValue(QJsonArray{"0", "0", "0", "0", "2/3", "1/3", "1", "1", "1", "1"});
        QTest::newRow("too few knots") << "knots" << QJsonValue(QJsonArray{"0", "0", "0", "0", "1", "1", "1", "1"});
        QTest::newRow("a knot five times") << "knots"
                                           << QJsonValue(QJsonArray{"0", "0", "0", "0", "0", "1/2", "1", "1", "1", "1"});
        QTest::newRow("a weight zero") << "weights" << QJsonValue(QJsonArray{"1", "1", "0", "1", "1", "1"});
        QTest::newRow("too few weights") << "weights" << QJsonValue(QJsonArray{"1", "1"});
        QTest::newRow("degree 11") << "degree" << QJsonValue(11);
        QTest::newRow("degree above n") << "degree" << QJsonValue(6);
        QTest::newRow("not a preset") << "knot_preset" << QJsonValue(QStringLiteral("open"));
        QTest::newRow("u not a number") << "u" << QJsonValue(QStringLiteral("half"));
    }

    void refusedDocumentChangesNothing()
    {
        QFETCH(QString, key);
        QFETCH(QJsonValue, value);
        BSplineTab tab;
        showTab(tab);
        QJsonObject state = tab.saveState();
        state.insert(key, value);
        const QJsonObject before = tab.saveState();
        const int undo = tab.undoStack()->count();
        QString error;
        QVERIFY(!tab.loadState(state, &error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(tab.saveState(), before);
        QCOMPARE(tab.undoStack()->count(), undo);
    }

    void ex22IsDeCasteljausCurve()
    {
        // The B-spline with no interior knot (degree n = 4) is Ex 2.2's Bézier curve: its de Boor
        // point equals De Casteljau's (Def 2.4, the core's other algorithm) at every u tried.
        const auto ex = bsplineExample(BSplineExampleId::Ex22Bezier);
        QVERIFY(ex.has_value());
        BSplineTab tab;
        showTab(tab);
        QVERIFY(tab.loadExample(*findWorkedExample("2.2")));
        QCOMPARE(tab.scene().degree(), 4);
        QCOMPARE(tab.knots(), rationals({{0, 1}, {0, 1}, {0, 1}, {0, 1}, {0, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}}));
        for (const Rational& u : rationals({{0, 1}, {1, 3}, {1, 2}, {4, 5}, {1, 1}})) {
            tab.setU(u);
            QCOMPARE(tab.scene().exactNet->point(), deCasteljau(findWorkedExample("2.2")->points, u).point());
        }
        tab.undoStack()->undo(); // the example is one step, after the u moves
    }

    void circleExampleIsACircle()
    {
        const auto ex = bsplineExample(BSplineExampleId::Circle);
        QVERIFY(ex.has_value());
        QVERIFY(checkBSpline(ex->curve).ok());
        // At u = 1/8 (the middle of the first arc) the rational point (3/5, 4/5): weights (1, 1, 2)
        // on (1, 0), (1, 1), (0, 1) at t = 1/2 give ((1/4 + 1/2)/(5/4), (1/2 + 1/2)/(5/4)) by hand.
        QCOMPARE(bsplinePoint(ex->curve, frac(1, 8)), RPoint(frac(3, 5), frac(4, 5)));
        // Exactly on the circle at every rational u tried.
        for (int j = 0; j <= 24; ++j) {
            const RPoint q = bsplinePoint(ex->curve, frac(j, 24));
            QCOMPARE(q.x * q.x + q.y * q.y, Rational(1));
        }
    }

    void conicPresets_data()
    {
        QTest::addColumn<int>("id");
        QTest::addColumn<RPoint>("middle");
        // c(1/2) = (P0 + 2w P1 + P2)/(2 + 2w) on (0, 0), (2, 3), (4, 0), by hand.
        QTest::newRow("ellipse") << int(BSplineExampleId::Ellipse) << RPoint(Rational(2), Rational(1));
        QTest::newRow("parabola") << int(BSplineExampleId::Parabola) << RPoint(Rational(2), frac(3, 2));
        QTest::newRow("hyperbola") << int(BSplineExampleId::Hyperbola) << RPoint(Rational(2), Rational(2));
        // (1, 0), (1, 1), (0, 1) with weights (1, 1, 2): ((1/4 + 1/2)/(5/4), (1/2 + 1/2)/(5/4)).
        QTest::newRow("quarter circle") << int(BSplineExampleId::QuarterCircle) << RPoint(frac(3, 5), frac(4, 5));
    }

    void conicPresets()
    {
        QFETCH(int, id);
        QFETCH(RPoint, middle);
        BSplineTab tab;
        showTab(tab);
        const int undo = tab.undoStack()->count();
        tab.loadBSplineExample(static_cast<BSplineExampleId>(id));
        QCOMPARE(tab.undoStack()->count(), undo + 1);
        QCOMPARE(tab.scene().degree(), 2);
        QVERIFY(tab.scene().curve.rational());
        QCOMPARE(tab.scene().u, frac(1, 2));
        QCOMPARE(tab.scene().exactNet->point(), middle);
        if (static_cast<BSplineExampleId>(id) == BSplineExampleId::QuarterCircle) {
            // The cubic beside it: its radial error √(1 + (2 − 3k)²/216) − 1 with k = 4(√2 − 1)/3
            // (Goldapp's closed form, derived in test_conic_sections), about 2.7e-4.
            const double k = 4 * (std::sqrt(2.0) - 1) / 3;
            QCOMPARE(tab.scene().cubicCircle.size(), std::size_t(4));
            QVERIFY(std::abs(tab.scene().cubicCircleError - (std::sqrt(1 + (2 - 3 * k) * (2 - 3 * k) / 216) - 1)) < 1e-12);
            QVERIFY(tab.scene().cubicCircleError > 2.7e-4 && tab.scene().cubicCircleError < 2.8e-4);
        }
        tab.undoStack()->undo();
        QCOMPARE(tab.pointEditor()->points().size(), std::size_t(6));
        QVERIFY(!tab.scene().curve.rational());
    }

    void exports()
    {
        BSplineTab tab;
        showTab(tab);
        // A cubic: TikZ draws the curve itself, one `.. controls ..` per span (three spans).
        const QString tex = tab.tikz();
        QCOMPARE(tex.count(QStringLiteral(".. controls")), 3);
        const QStringList lines = tab.csv().split(QLatin1Char('\n'));
        QCOMPARE(lines.front(), QStringLiteral("point,x,y,w"));
        QCOMPARE(lines[1], QStringLiteral("P0,0,0,1"));
        const int knots = static_cast<int>(lines.indexOf(QStringLiteral("knot,u")));
        QVERIFY(knots > 0);
        QCOMPARE(lines[knots + 5], QStringLiteral("u4,1/3"));
        QVERIFY(lines.contains(QStringLiteral("sample,x,y")));
    }

    void playIsOneUndoStep()
    {
        BSplineTab tab;
        showTab(tab);
        const Rational start = tab.model().u;
        const int undo = tab.undoStack()->count();
        tab.setPlaying(true);
        QTRY_VERIFY_WITH_TIMEOUT(tab.scene().u != start, kEventWaitMs); // a frame at least, however slow the machine
        QCOMPARE(tab.undoStack()->count(), undo);                       // nothing while it plays
        QCOMPARE(tab.model().u, start);                                 // nor in the document
        tab.setPlaying(false);
        QCOMPARE(tab.undoStack()->count(), undo + 1);
        QCOMPARE(tab.model().u, tab.scene().u);
        tab.undoStack()->undo();
        QCOMPARE(tab.model().u, start);
    }

    void rulerKeys()
    {
        BSplineTab tab;
        showTab(tab);
        KnotRuler* ruler = tab.knotRuler();
        ruler->setSelected(-1);
        // Right five times from none: knot 0, 1, 2, 3, 4 (= 1/3).
        for (int i = 0; i < 5; ++i)
            QTest::keyClick(ruler, Qt::Key_Right);
        QCOMPARE(ruler->selected(), 4);
        // Shift+Right moves it by a step, one undo step.
        const int undo = tab.undoStack()->count();
        QTest::keyClick(ruler, Qt::Key_Right, Qt::ShiftModifier);
        QVERIFY(tab.knots()[4] > frac(1, 3));
        QCOMPARE(tab.undoStack()->count(), undo + 1);
        // Insert: a knot at u; Delete on the needed knot: refused.
        const std::size_t count = tab.knots().size();
        QTest::keyClick(ruler, Qt::Key_Insert);
        QCOMPARE(tab.knots().size(), count + 1);
    }
};

GRANOTA_TEST_MAIN(TestGuiBSpline)
#include "test_gui_bspline.moc"
