// The `stable` solver (XPBD with substeps): exact area, stiff and extreme settings,
// recovery, grabbing, obstacles, many bodies, chains, determinism and energy.
#include "core/base/math_constants.h"
#include "core/softbody/scenes/frog_params.h"
#include "core/softbody/polygon_geometry.h"
#include "core/softbody/regular_polygon.h"
#include "core/softbody/xpbd/xpbd_broad_phase.h"
#include "core/softbody/xpbd/xpbd_chain.h"
#include "core/softbody/xpbd/xpbd_constraints.h"
#include "core/softbody/xpbd/xpbd_world.h"

#include <QtTest>
#include "tests/test_main.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace granota;

namespace {

const double kInf = std::numeric_limits<double>::infinity();

XpbdWorld makeWorld(const XpbdParams& params = {})
{
    Expected<XpbdWorld> w = XpbdWorld::create(params);
    if (!w)
        qFatal("%s", w.error().message.c_str());
    return std::move(w).value();
}

int addRegular(XpbdWorld& world, Point centre, double radius, int sides, double target = -1, Point v = {},
               const BodyOptions& options = {})
{
    const auto shape = regularPolygon(centre, radius, sides);
    const Expected<int> b = world.addBody(shape, target < 0 ? trapezoidArea(shape) : target, v, options);
    if (!b)
        qFatal("%s", b.error().message.c_str());
    return b.value();
}

bool finiteAndInside(const XpbdWorld& world)
{
    const double w = world.params().width, h = world.params().height;
    for (const Point& p : world.positions())
        if (!isFinite(p) || p.x < 0 || p.x > w - 1 || p.y < 0 || p.y > h - 1)
            return false;
    for (const Point& v : world.velocities())
        if (!isFinite(v))
            return false;
    return std::isfinite(world.kineticEnergy()) && std::isfinite(world.potentialEnergy());
}

// Independent of the solver's own checks: brute force over all edge pairs.
bool properCross(Point p, Point q, Point a, Point b)
{
    const auto side = [](Point o, Point d, Point r) { return cross(d - o, r - o); };
    const double d1 = side(a, b, p), d2 = side(a, b, q), d3 = side(p, q, a), d4 = side(p, q, b);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

bool selfIntersects(const std::vector<Point>& v)
{
    const int n = int(v.size());
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            if (j == i + 1 || (i == 0 && j == n - 1))
                continue;
            if (properCross(v[i], v[(i + 1) % n], v[j], v[(j + 1) % n]))
                return true;
        }
    return false;
}

double distanceToBoundary(const std::vector<Point>& poly, Point p)
{
    double best = kInf;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Point a = poly[i], b = poly[(i + 1) % poly.size()];
        const Point ab = b - a;
        const double t = std::clamp(dot(p - a, ab) / std::max(dot(ab, ab), 1e-300), 0.0, 1.0);
        best = std::min(best, distance(p, a + Point(t * ab.x, t * ab.y)));
    }
    return best;
}

/// How deep the deepest vertex of one body lies inside another, px (0 if none does).
double worstPenetration(const XpbdWorld& world)
{
    double worst = 0;
    for (int a = 0; a < world.bodyCount(); ++a) {
        const auto pa = world.bodyVertices(a);
        for (int b = 0; b < world.bodyCount(); ++b) {
            if (a == b)
                continue;
            const auto pb = world.bodyVertices(b);
            for (const Point& p : pa)
                if (pointInPolygon(p, pb))
                    worst = std::max(worst, distanceToBoundary(pb, p));
        }
    }
    return worst;
}

double floorY(const XpbdWorld& w) { return w.params().height - 1; }

} // namespace

class TestXpbdSolver : public QObject {
    Q_OBJECT
private slots:
    // --- Validation -------------------------------------------------------------------
    void defaultsFollowTheFrog()
    {
        const XpbdParams a = xpbdParamsFrom(FrogParams{});
        const XpbdParams b;
        QCOMPARE(a.gravity, b.gravity);
        QCOMPARE(a.damping, b.damping);
        QCOMPARE(a.velmax, b.velmax);
        QCOMPARE(a.width, b.width);
        QCOMPARE(a.height, b.height);
        QCOMPARE(b.gravity, Point(0, 0.75));
        QVERIFY(validateXpbdParams(b).ok());
        // A compliance from a period: k = m ω², α = 1/k.
        QVERIFY(std::abs(complianceForPeriod(2 * M_PI, 2) - 0.5) < 1e-12);
    }

    void badParamsAreRejected_data()
    {
        QTest::addColumn<int>("which");
        const char* names[] = {"substeps 0",  "negative compliance", "zero width",          "negative height",
                               "NaN gravity", "friction above 1",    "NaN area compliance", "velmax 0",
                               "dt 0",        "restitution 2",       "recovery 0",          "infinite width"};
        for (int i = 0; i < 12; ++i)
            QTest::newRow(names[i]) << i;
    }
    void badParamsAreRejected()
    {
        QFETCH(int, which);
        XpbdParams p;
        switch (which) {
        case 0: p.substeps = 0; break;
        case 1: p.edgeCompliance = -1; break;
        case 2: p.width = 0; break;
        case 3: p.height = -5; break;
        case 4: p.gravity.y = std::nan(""); break;
        case 5: p.damping.x = 1.5; break;
        case 6: p.areaCompliance = std::nan(""); break;
        case 7: p.velmax = 0; break;
        case 8: p.dt = 0; break;
        case 9: p.restitution = 2; break;
        case 10: p.recoveryRate = 0; break;
        case 11: p.width = kInf; break;
        }
        const auto r = XpbdWorld::create(p);
        QVERIFY(!r.ok());
        QVERIFY(!r.error().message.empty());
        // A live change to the same bad values is refused and changes nothing.
        XpbdWorld w = makeWorld();
        QVERIFY(!w.setParams(p).ok());
        QCOMPARE(w.params().width, XpbdParams{}.width);
        QCOMPARE(w.params().substeps, XpbdParams{}.substeps);
    }

    void badBodiesAreRejected_data()
    {
        QTest::addColumn<int>("which");
        const char* names[] = {"two vertices", "NaN vertex", "negative area",     "NaN area",
                               "collinear",    "bow tie",    "infinite velocity", "zero mass"};
        for (int i = 0; i < 8; ++i)
            QTest::newRow(names[i]) << i;
    }
    void badBodiesAreRejected()
    {
        QFETCH(int, which);
        XpbdWorld w = makeWorld();
        std::vector<Point> shape = regularPolygon({640, 360}, 50, 6);
        double target = 5000;
        Point v;
        BodyOptions o;
        switch (which) {
        case 0: shape.resize(2); break;
        case 1: shape[3].x = std::nan(""); break;
        case 2: target = -1; break;
        case 3: target = std::nan(""); break;
        case 4: shape = {{0, 0}, {1, 1}, {2, 2}, {3, 3}}; break;
        case 5: shape = {{0, 0}, {100, 100}, {100, 0}, {0, 100}}; break;
        case 6: v.x = kInf; break;
        case 7: o.mass = 0; break;
        }
        const auto r = w.addBody(shape, target, v, o);
        QVERIFY(!r.ok());
        QVERIFY(!r.error().message.empty());
        QCOMPARE(w.bodyCount(), 0);
        QCOMPARE(w.particleCount(), 0);
    }

    void badRegularBodiesAreRejected_data()
    {
        QTest::addColumn<int>("sides");
        QTest::addColumn<double>("radius");
        QTest::addColumn<double>("cx");
        QTest::newRow("2 sides") << 2 << 50.0 << 100.0;
        QTest::newRow("-4 sides") << -4 << 50.0 << 100.0;
        QTest::newRow("radius 0") << 10 << 0.0 << 100.0;
        QTest::newRow("negative radius") << 10 << -3.0 << 100.0;
        QTest::newRow("NaN radius") << 10 << std::nan("") << 100.0;
        QTest::newRow("infinite centre") << 10 << 50.0 << kInf;
    }
    void badRegularBodiesAreRejected()
    {
        QFETCH(int, sides);
        QFETCH(double, radius);
        QFETCH(double, cx);
        XpbdWorld w = makeWorld();
        const auto r = w.addRegularBody({cx, 300}, radius, sides, 1000, {});
        QVERIFY(!r.ok());
        QVERIFY(!r.error().message.empty());
        QCOMPARE(w.bodyCount(), 0);
        QVERIFY(w.addRegularBody({100, 300}, 50, 3, 1000, {}).ok());
    }

    void otherOrientationIsAccepted()
    {
        XpbdWorld w = makeWorld();
        auto shape = regularPolygon({640, 300}, 60, 7);
        std::reverse(shape.begin(), shape.end());
        const auto b = w.addBody(shape, 8000, {});
        QVERIFY(b.ok());
        QVERIFY(w.area(b.value()) > 0);
    }

    // --- The area constraint --------------------------------------------------------------
    void areaGradientMatchesFiniteDifference_data()
    {
        QTest::addColumn<int>("shape");
        QTest::newRow("regular decagon") << 0;
        QTest::newRow("irregular heptagon") << 1;
        QTest::newRow("concave L") << 2;
    }
    void areaGradientMatchesFiniteDifference()
    {
        QFETCH(int, shape);
        std::vector<Point> p;
        if (shape == 0)
            p = regularPolygon({640, 360}, 120, 10);
        else if (shape == 1)
            p = {{10, 3}, {40, 8}, {55, 30}, {44, 61}, {20, 70}, {3, 52}, {-4, 20}};
        else
            p = {{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}};
        const int n = int(p.size());
        const double eps = 1e-5;
        for (int i = 0; i < n; ++i) {
            const Point g = areaGradient(p[(i + n - 1) % n], p[(i + 1) % n]);
            for (int axis = 0; axis < 2; ++axis) {
                auto plus = p, minus = p;
                (axis == 0 ? plus[i].x : plus[i].y) += eps;
                (axis == 0 ? minus[i].x : minus[i].y) -= eps;
                const double fd = (signedArea(plus.data(), n) - signedArea(minus.data(), n)) / (2 * eps);
                QVERIFY2(std::abs(fd - (axis == 0 ? g.x : g.y)) < 1e-6 * (1 + std::abs(fd)),
                         qPrintable(QString("vertex %1 axis %2: fd %3").arg(i).arg(axis).arg(fd)));
            }
        }
        // The shoelace area is the trapezoid sum of §4.5, and for regularPolygon it is
        // positive with the gradient pointing out of the body.
        QVERIFY(std::abs(signedArea(p.data(), n) - trapezoidArea(p)) < 1e-9 * std::abs(trapezoidArea(p)));
        if (shape == 0) {
            QVERIFY(signedArea(p.data(), n) > 0);
            for (int i = 0; i < n; ++i)
                QVERIFY(dot(areaGradient(p[(i + n - 1) % n], p[(i + 1) % n]), p[i] - Point(640, 360)) > 0);
        }
    }

    void areaHeldAtRest_data()
    {
        QTest::addColumn<int>("sides");
        QTest::addColumn<double>("radius");
        QTest::addColumn<double>("target"); // < 0: the rest area
        for (int sides : {3, 10, 57})
            for (double r : {30.0, 120.0})
                QTest::newRow(qPrintable(QString("%1 sides, r %2").arg(sides).arg(r))) << sides << r << -1.0;
        QTest::newRow("thesis frog: r 120, target 20000") << 10 << 120.0 << 20000.0;
        QTest::newRow("57 sides, r 120, target 20000") << 57 << 120.0 << 20000.0;
    }
    void areaHeldAtRest()
    {
        QFETCH(int, sides);
        QFETCH(double, radius);
        QFETCH(double, target);
        XpbdWorld w = makeWorld();
        const int b = addRegular(w, {640, 360}, radius, sides, target);
        for (int i = 0; i < 600; ++i)
            w.step();
        const double err = w.areaErrorPercent(b);
        qInfo("area error at rest: %+.4f %% (area %.1f, target %.1f), max edge stretch %.4f, kinetic %.2e", err, w.area(b),
              w.targetArea(b), w.maxEdgeStretch(b), w.kineticEnergy());
        QVERIFY2(std::abs(err) < 1.0, qPrintable(QString::number(err)));
        QVERIFY(w.isValid(b));
        QVERIFY(!w.recovering(b));
        QVERIFY(w.kineticEnergy() < 1e-3); // at rest indeed
        // It rests on the floor.
        const auto v = w.bodyVertices(b);
        const double lowest = std::max_element(v.begin(), v.end(), [](Point a, Point c) { return a.y < c.y; })->y;
        QVERIFY(std::abs(lowest - floorY(w)) < 1e-6);
    }

    // --- Stiff and extreme settings (docs/extreme-cases.md) ----------------------------------------------
    void extremeSettingsStayFiniteAndInside_data()
    {
        QTest::addColumn<int>("which");
        const char* names[] = {"rigid (all compliance 0)",
                               "large steps (dt 25)",
                               "huge gravity 1e4",
                               "target area 0",
                               "target area 1e9",
                               "3 sides",
                               "200 sides",
                               "friction 0",
                               "friction 1",
                               "partly outside the frame",
                               "10x10 frame, 100 px body",
                               "1 substep",
                               "sideways gravity, bouncy",
                               "inverted rigid, huge velocity"};
        for (int i = 0; i < 14; ++i)
            QTest::newRow(names[i]) << i;
    }
    void extremeSettingsStayFiniteAndInside()
    {
        QFETCH(int, which);
        XpbdParams p;
        Point centre{640, 360};
        double radius = 120;
        int sides = 10;
        double target = -1;
        Point v0 = FrogParams{}.v0;
        switch (which) {
        case 0: p.edgeCompliance = p.areaCompliance = p.bendCompliance = p.linkCompliance = p.grabCompliance = 0; break;
        case 1: p.dt = 25; break;
        case 2:
            p.gravity = {0, 1e4};
            p.velmax = kInf;
            break;
        case 3: target = 0; break;
        case 4: target = 1e9; break;
        case 5: sides = 3; break;
        case 6: sides = 200; break;
        case 7:
            p.damping = {1, 1};
            p.wallFriction = p.contactFriction = 0;
            break;
        case 8:
            p.damping = {0, 0};
            p.wallFriction = p.contactFriction = 1;
            break;
        case 9: centre = {30, 700}; break;
        case 10:
            p.width = p.height = 10;
            centre = {5, 5};
            radius = 100;
            break;
        case 11: p.substeps = 1; break;
        case 12:
            p.gravity = {3, -2};
            p.restitution = 1;
            p.velmax = kInf;
            break;
        case 13:
            p.edgeCompliance = p.areaCompliance = 0;
            p.velmax = kInf;
            v0 = {1e6, -3e5};
            break;
        }
        XpbdWorld w = makeWorld(p);
        const int b = addRegular(w, centre, radius, sides, target, v0, BodyOptions{10, which == 0 || which == 6, true});
        // A second body and a pendulum, so that contacts and chains see the same extremes.
        addRegular(w, {centre.x + 200, centre.y - 100}, radius / 2, sides, target < 0 ? -1 : target, v0);
        ChainDef chain;
        chain.anchor.point = {centre.x - 150, 100};
        chain.joints = {chain.anchor.point, chain.anchor.point + Point(40, 0), chain.anchor.point + Point(80, 0)};
        chain.limits = {{-M_PI / 2, M_PI / 2, AngleReference::World}, {-M_PI / 4, M_PI / 4, AngleReference::Parent}};
        QVERIFY(w.addChain(chain).ok());
        if (which == 13) {
            auto inverted = w.bodyVertices(b);
            for (Point& q : inverted)
                q.x = 2 * centre.x - q.x;
            QVERIFY(w.setBodyVertices(b, inverted).ok());
            QVERIFY(w.setBodyVelocity(b, v0).ok());
        }
        for (int i = 0; i < 1000; ++i) {
            w.step();
            if (!finiteAndInside(w))
                QFAIL(qPrintable(QString("left the frame or not finite at step %1").arg(i)));
            if (i == 500) { // grab and throw, also far outside the window
                w.press(w.centroid(b));
                w.move({-1e9, 1e12});
            }
            if (i == 520)
                w.release();
        }
        QCOMPARE(w.particleCount(), sides + sides + 3);
        qInfo("kinetic energy after 1000 steps: %.3g", w.kineticEnergy());
    }

    // --- Recovery ---------------------------------------------------------------------
    void recoversFromBadStates_data()
    {
        QTest::addColumn<int>("which");
        QTest::addColumn<int>("sides");
        const char* names[] = {"squashed flat", "squashed onto a line", "mirrored (inside out)", "hard fling into a wall",
                               "tangled (figure eight)"};
        for (int i = 0; i < 5; ++i)
            for (int sides : {10, 31})
                QTest::newRow(qPrintable(QString("%1, %2 sides").arg(names[i]).arg(sides))) << i << sides;
    }
    void recoversFromBadStates()
    {
        QFETCH(int, which);
        QFETCH(int, sides);
        XpbdParams p;
        p.velmax = kInf;
        XpbdWorld w = makeWorld(p);
        const int b = addRegular(w, {640, 500}, 100, sides, 20000);
        for (int i = 0; i < 200; ++i)
            w.step();
        auto v = w.bodyVertices(b);
        const Point c = w.centroid(b);
        switch (which) {
        case 0: // pressed flat against the floor: 2 % of its height left
            for (Point& q : v)
                q.y = floorY(w) - 0.02 * (floorY(w) - q.y);
            break;
        case 1:
            for (Point& q : v)
                q.y = floorY(w);
            break;
        case 2:
            for (Point& q : v)
                q.x = 2 * c.x - q.x;
            break;
        case 3: break;
        case 4: // swap two halves' order: the outline crosses itself
            std::reverse(v.begin() + sides / 4, v.begin() + 3 * sides / 4);
            break;
        }
        QVERIFY(w.setBodyVertices(b, v).ok());
        if (which == 3) {
            QVERIFY(w.setBodyVelocity(b, {5000, -800}).ok());
            w.step(); // into the wall: flattened against it in one step
        }
        QVERIFY(!w.isValid(b));
        int recoveredAt = -1;
        bool matched = false; // did shape matching have to step in?
        for (int i = 0; i < 600; ++i) {
            w.step();
            QVERIFY(finiteAndInside(w));
            matched = matched || w.recovering(b);
            if (recoveredAt < 0 && !w.recovering(b) && w.isValid(b))
                recoveredAt = i;
        }
        const auto after = w.bodyVertices(b);
        qInfo("valid again after %d steps (shape matching used: %s); area error then %+.3f %%", recoveredAt + 1,
              matched ? "yes" : "no", w.areaErrorPercent(b));
        QVERIFY(recoveredAt >= 0);
        QVERIFY(!w.recovering(b));
        QVERIFY(w.area(b) > 0);
        QVERIFY2(std::abs(w.areaErrorPercent(b)) < 1.0, qPrintable(QString::number(w.areaErrorPercent(b))));
        QVERIFY(!selfIntersects(after));
    }

    void restingBodyDoesNotDrift_data()
    {
        QTest::addColumn<int>("sides");
        QTest::addColumn<double>("radius");
        QTest::newRow("frog") << 10 << 120.0;
        QTest::newRow("triangle") << 3 << 60.0;
        QTest::newRow("57 sides") << 57 << 40.0;
    }
    void restingBodyDoesNotDrift()
    {
        QFETCH(int, sides);
        QFETCH(double, radius);
        XpbdWorld w = makeWorld();
        const int b = addRegular(w, {500, 500}, radius, sides, 20000 * (radius / 120) * (radius / 120));
        for (int i = 0; i < 300; ++i)
            w.step();
        const Point c0 = w.centroid(b);
        const double a0 = w.orientation(b);
        for (int i = 0; i < 2000; ++i)
            w.step();
        const double drift = distance(w.centroid(b), c0);
        const double turn = std::abs(wrapAngle(w.orientation(b) - a0));
        qInfo("drift over 2000 steps: %.2e px, turn %.2e rad", drift, turn);
        QVERIFY(drift < 0.05);
        QVERIFY(turn < 1e-3);
    }

    // --- Grabbing -----------------------------------------------------------------------
    void grabMovesReleasesAndKeepsVertices_data()
    {
        QTest::addColumn<int>("anchors");
        QTest::newRow("above the grab point (§4.7)") << int(GrabMode::Above);
        QTest::newRow("frog anchors {0, 1, N-1}") << int(GrabMode::Anchors);
        QTest::newRow("all vertices (§4.6)") << int(GrabMode::All);
    }
    void grabMovesReleasesAndKeepsVertices()
    {
        QFETCH(int, anchors);
        XpbdParams p;
        p.grabMode = GrabMode(anchors);
        XpbdWorld w = makeWorld(p);
        const int b = addRegular(w, {400, 500}, 80, 10, 14000);
        for (int i = 0; i < 200; ++i)
            w.step();
        const int n = w.particleCount();

        QVERIFY(!w.press({1200, 100}));       // outside the body
        QVERIFY(!w.press({-50, -2000}));      // outside the window
        QVERIFY(!w.press({std::nan(""), 3})); // not a point
        QCOMPARE(w.grabbedBody(), -1);

        const Point start = w.centroid(b);
        QVERIFY(w.press(start));
        QCOMPARE(w.grabbedBody(), b);
        QVERIFY(!w.grabAnchorParticles().empty());
        QVERIFY(!w.press(start)); // one body at a time
        const Point goal{900, 200};
        for (int i = 0; i < 100; ++i) { // drag the mouse there over 100 steps, then hold
            const double f = std::min(1.0, i / 50.0);
            w.move(start + Point((goal.x - start.x) * f, (goal.y - start.y) * f));
            w.step();
            QVERIFY(finiteAndInside(w));
        }
        const Point held = w.centroid(b);
        QVERIFY2(distance(held, goal) < 0.5 * distance(start, goal),
                 qPrintable(QString("held at %1, %2").arg(held.x).arg(held.y)));
        w.release();
        QCOMPARE(w.grabbedBody(), -1);
        for (int i = 0; i < 30; ++i)
            w.step();
        QVERIFY(w.centroid(b).y > held.y + 50); // falls
        for (int i = 0; i < 400; ++i)
            w.step();
        QCOMPARE(w.particleCount(), n);
        QVERIFY(finiteAndInside(w));
        QVERIFY(w.isValid(b));
    }

    void releaseKeepsTheMouseVelocity()
    {
        XpbdParams p;
        p.gravity = {0, 0};
        p.damping = {1, 1};
        p.velmax = kInf;
        XpbdWorld w = makeWorld(p);
        const int b = addRegular(w, {300, 360}, 50, 10);
        QVERIFY(w.press({300, 360}));
        for (int i = 1; i <= 20; ++i) {
            w.move({300 + 4.0 * i, 360});
            w.step();
        }
        w.release();
        Point mean;
        for (int i = 0; i < 10; ++i)
            mean += w.velocities()[std::size_t(w.bodyRange(b).first + i)];
        QVERIFY(std::abs(mean.x / 10 - 4) < 1e-9);
        QVERIFY(std::abs(mean.y / 10) < 1e-9);
    }

    void grabbingWhileTheMouseLeavesTheWindow()
    {
        XpbdWorld w = makeWorld();
        const int b = addRegular(w, {640, 360}, 100, 10);
        QVERIFY(w.press({640, 360}));
        w.move({1e12, -1e12});
        QVERIFY(w.mouse().x <= w.params().width - 1 && w.mouse().y >= 0);
        for (int i = 0; i < 300; ++i)
            w.step();
        QVERIFY(finiteAndInside(w));
        w.move({std::nan(""), kInf}); // ignored
        w.step();
        w.release();
        for (int i = 0; i < 300; ++i)
            w.step();
        QVERIFY(finiteAndInside(w));
        QVERIFY(w.isValid(b));
    }

    // --- Obstacles and other bodies (§5.2.1, §5.2.2) ---------------------------------------
    void restsOnObstacles_data()
    {
        QTest::addColumn<int>("which");
        QTest::newRow("thick segment") << 0;
        QTest::newRow("slanted segment") << 1;
        QTest::newRow("convex polygon") << 2;
        QTest::newRow("concave polygon (U)") << 3;
        QTest::newRow("thin spike") << 4;
        QTest::newRow("segment of no thickness") << 5;
    }
    void restsOnObstacles()
    {
        QFETCH(int, which);
        XpbdWorld w = makeWorld();
        std::vector<Point> poly;
        double top = 0;
        switch (which) {
        case 0:
            QVERIFY(w.addSegmentObstacle({400, 400}, {900, 400}, 3).ok());
            top = 397;
            break;
        case 1:
            QVERIFY(w.addSegmentObstacle({400, 330}, {900, 460}, 3).ok());
            top = 330;
            break;
        case 2:
            poly = {{450, 400}, {850, 400}, {800, 550}, {500, 550}};
            top = 400;
            break;
        case 3: // a cup: the body falls in and rests on its bottom
            poly = {{450, 380}, {500, 380}, {500, 500}, {780, 500}, {780, 380}, {830, 380}, {830, 560}, {450, 560}};
            top = 500;
            break;
        case 4:
            poly = {{630, 350}, {650, 350}, {641, 250}};
            top = 250;
            break;
        case 5:
            QVERIFY(w.addSegmentObstacle({400, 400}, {900, 400}, 0).ok());
            top = 400;
            break;
        }
        if (!poly.empty())
            QVERIFY(w.addPolygonObstacle(poly).ok());
        const int b = addRegular(w, {640, 120}, 70, 12, 12000);
        double deepest = 0;
        for (int i = 0; i < 800; ++i) {
            w.step();
            QVERIFY(finiteAndInside(w));
            const auto v = w.bodyVertices(b);
            for (const Point& q : v) {
                if (!poly.empty() && pointInPolygon(q, poly))
                    deepest = std::max(deepest, distanceToBoundary(poly, q));
                if (which <= 1 || which == 5) { // below the segment's centre line, within its span
                    const Point a = w.obstaclePoints(0)[0], c = w.obstaclePoints(0)[1];
                    if (q.x > a.x && q.x < c.x) {
                        const double yLine = a.y + (q.x - a.x) / (c.x - a.x) * (c.y - a.y);
                        if (q.y > yLine)
                            deepest = std::max(deepest, q.y - yLine);
                    }
                }
            }
            // No obstacle corner stays inside the body either.
            for (int o = 0; o < w.obstacleCount(); ++o)
                for (const Point& c : w.obstaclePoints(o))
                    if (i > 5 && pointInPolygon(c, v))
                        deepest = std::max(deepest, distanceToBoundary(v, c));
        }
        qInfo("deepest penetration %.3f px; centroid y %.1f", deepest, w.centroid(b).y);
        QVERIFY(deepest < 1.0);
        if (which != 1 && which != 4) { // it slides off a slope and a spike; elsewhere it rests on top
            QVERIFY(w.centroid(b).y < top);
            QVERIFY(w.kineticEnergy() < 0.05);
        }
        QVERIFY(w.isValid(b));
    }

    void bodiesDoNotInterpenetrate_data()
    {
        QTest::addColumn<int>("count");
        QTest::addColumn<int>("sides");
        QTest::newRow("two decagons") << 2 << 10;
        QTest::newRow("two triangles") << 2 << 3;
        QTest::newRow("50 decagons") << 50 << 10;
        QTest::newRow("50 mixed") << 50 << 0;
    }
    void bodiesDoNotInterpenetrate()
    {
        QFETCH(int, count);
        QFETCH(int, sides);
        XpbdWorld w = makeWorld();
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> jitter(-10, 10);
        for (int k = 0; k < count; ++k) {
            const int n = sides > 0 ? sides : 3 + k % 9;
            const double r = count == 2 ? 90 : 28 + (k % 4) * 4;
            const Point c = count == 2 ? Point(620 + 40 * k, 300 - 220 * k)
                                       : Point(100 + (k % 10) * 110 + jitter(rng), 80 + (k / 10) * 75 + jitter(rng));
            addRegular(w, c, r, n);
        }
        int maxPairs = 0;
        double worstDuring = 0;
        for (int i = 0; i < 1500; ++i) {
            w.step();
            QVERIFY(finiteAndInside(w));
            maxPairs = std::max(maxPairs, int(w.contactPairs().size()));
            if (count == 2 || i % 50 == 0)
                worstDuring = std::max(worstDuring, worstPenetration(w));
        }
        QVERIFY(maxPairs > 0); // they did meet
        const double pen = worstPenetration(w);
        qInfo("worst penetration while falling and colliding: %.3f px", worstDuring);
        QVERIFY(worstDuring < 2.0);
        int invalid = 0;
        for (int k = 0; k < count; ++k)
            invalid += w.isValid(k) ? 0 : 1;
        double worstArea = 0;
        for (int k = 0; k < count; ++k)
            worstArea = std::max(worstArea, std::abs(w.areaErrorPercent(k)));
        qInfo("worst penetration after settling: %.3f px; worst area error %.3f %%; pairs %d; kinetic %.2e", pen, worstArea,
              int(w.contactPairs().size()), w.kineticEnergy());
        QVERIFY(pen < 0.5);
        QCOMPARE(invalid, 0);
        QVERIFY(worstArea < 2.0);
    }

    void broadPhaseMatchesBruteForce_data()
    {
        QTest::addColumn<int>("count");
        QTest::addColumn<int>("seed");
        QTest::newRow("10") << 10 << 1;
        QTest::newRow("300") << 300 << 2;
        QTest::newRow("1000 with giants") << 1000 << 3;
    }
    void broadPhaseMatchesBruteForce()
    {
        QFETCH(int, count);
        QFETCH(int, seed);
        std::mt19937 rng(seed);
        const double side = 40 * std::sqrt(double(count)); // about one box in four meets another
        std::uniform_real_distribution<double> pos(0, side), size(5, 60), huge(300, 900);
        std::vector<Aabb> boxes;
        for (int i = 0; i < count; ++i) {
            Aabb b;
            b.minX = pos(rng);
            b.minY = pos(rng) * 0.6;
            const double s = (count > 500 && i % 100 == 0) ? huge(rng) : size(rng);
            b.maxX = b.minX + s;
            b.maxY = b.minY + s * 0.7;
            boxes.push_back(b);
        }
        boxes.push_back(Aabb()); // an empty box meets nothing
        std::vector<BodyPair> grid, brute;
        UniformGridBroadPhase phase;
        phase.findPairs(boxes, grid);
        bruteForcePairs(boxes, brute);
        const std::size_t found = grid.size();
        std::sort(grid.begin(), grid.end());
        QVERIFY(std::adjacent_find(grid.begin(), grid.end()) == grid.end()); // no pair twice
        std::sort(brute.begin(), brute.end());
        QCOMPARE(found, brute.size());
        QVERIFY(grid == brute);
        QVERIFY(!brute.empty());
    }

    // --- Chains (§4.13–4.15) ----------------------------------------------------------------
    void pendulumKeepsLengthsAndLimits_data()
    {
        QTest::addColumn<int>("reference"); // -1: no limits
        QTest::addColumn<double>("limit");
        QTest::newRow("free") << -1 << 0.0;
        QTest::newRow("relative ±45°") << int(AngleReference::Parent) << M_PI / 4;
        QTest::newRow("relative ±10°") << int(AngleReference::Parent) << M_PI / 18;
        QTest::newRow("absolute ±60° (seed)") << int(AngleReference::World) << M_PI / 3;
    }
    void pendulumKeepsLengthsAndLimits()
    {
        QFETCH(int, reference);
        QFETCH(double, limit);
        XpbdParams p;
        p.damping = {0.999, 0.999};
        XpbdWorld w = makeWorld(p);
        ChainDef def;
        def.anchor.point = {640, 200};
        // Three moving joints hanging straight down, within every limit.
        def.joints = {{640, 200}, {640, 260}, {640, 300}, {640, 330}};
        const std::vector<double> lengths{60, 40, 30};
        if (reference >= 0)
            def.limits.assign(3, AngleLimit{-limit, limit, AngleReference(reference)});
        const int c = w.addChain(def).value();
        // Kick it sideways and swing the anchor around, as the seed's nail follows the mouse.
        double worstLength = 0, worstAngle = 0;
        for (int i = 0; i < 1500; ++i) {
            w.moveChainAnchor(c, {640 + 200 * std::sin(i * 0.05), 140 + 60 * std::cos(i * 0.031)});
            w.step();
            const auto j = w.chainJoints(c);
            for (int k = 0; k < 3; ++k) {
                worstLength = std::max(worstLength, std::abs(distance(j[k], j[k + 1]) - lengths[k]) / lengths[k]);
                if (reference < 0)
                    continue;
                const double a = reference == int(AngleReference::World) || k == 0
                                     ? seedAngle(j[k + 1] - j[k])
                                     : wrapAngle(seedAngle(j[k + 1] - j[k]) - seedAngle(j[k] - j[k - 1]));
                worstAngle = std::max(worstAngle, std::abs(a) - limit);
            }
        }
        qInfo("worst relative length error %.2e, worst angle beyond the limit %.2e rad", worstLength, worstAngle);
        QVERIFY(worstLength < 0.01);
        QVERIFY(worstAngle < 0.02);
        QVERIFY(finiteAndInside(w));
    }

    void frogLegsOnTheStableSolver()
    {
        // The final frog (§4.16) on the stable solver: a 10-vertex body with four two-link
        // legs hanging from the shoulders Annex II computes.
        const FrogParams frog;
        XpbdWorld w = makeWorld(xpbdParamsFrom(frog));
        const int b = addRegular(w, frog.center, frog.radius, frog.sides, frog.targetArea, frog.v0);
        for (int leg = 0; leg < 4; ++leg) {
            const ChainAnchor a = frogLegAnchor(b, leg, frog.sides);
            QVERIFY(w.addChain(frogLegChain(frog.legs[std::size_t(leg)], a, w.anchorPoint(a))).ok());
        }
        // Front right sits 4/5 of the way from vertex 2 to vertex 8, as posDreDav.
        const auto v = w.bodyVertices(b);
        const Point expected = v[8] - Point((v[8].x - v[2].x) / 5, (v[8].y - v[2].y) / 5);
        QVERIFY(distance(w.chainJoints(0)[0], expected) < 1e-9);
        // Rigid legs, so their lengths must hold: tightly at rest and while dragged; at the
        // landings, where a straight leg is rammed between the falling body and the floor,
        // one pass per substep leaves a transient error of a few per cent.
        double calm = 0, impact = 0, worstShoulder = 0;
        for (int i = 0; i < 1000; ++i) {
            if (i == 300)
                QVERIFY(w.press(w.centroid(b)));
            if (i > 300 && i < 400)
                w.move({640 + 3.0 * (i - 300), 200});
            if (i == 400)
                w.release();
            w.step();
            QVERIFY(finiteAndInside(w));
            double worst = 0;
            for (int leg = 0; leg < 4; ++leg) {
                const auto j = w.chainJoints(leg);
                const LegParams& lp = frog.legs[std::size_t(leg)];
                worst = std::max({worst, std::abs(distance(j[0], j[1]) - lp.upper) / lp.upper,
                                  std::abs(distance(j[1], j[2]) - lp.lower) / lp.lower});
                worstShoulder = std::max(worstShoulder, distance(j[0], w.anchorPoint(frogLegAnchor(b, leg, 10))));
            }
            const bool landing = (i >= 20 && i < 150) || (i >= 400 && i < 600);
            (landing ? impact : calm) = std::max(landing ? impact : calm, worst);
        }
        qInfo("legs: worst length error %.2e at rest and dragged, %.2e at landings; shoulder offset %.1e px; "
              "body area error %+.3f %%",
              calm, impact, worstShoulder, w.areaErrorPercent(b));
        QVERIFY(calm < 0.01);
        QVERIFY(impact < 0.1);
        QVERIFY(worstShoulder < 1e-9);
        QVERIFY(std::abs(w.areaErrorPercent(b)) < 1.0);
    }

    void frogLegsNeverActOnTheBody()
    {
        // Annex II (§4.16): the legs hang from the body and never act on it. On the stable
        // solver too: the frog's body moves bit for bit as the same body without legs, landing,
        // resting and dragged — legs that carried it would stand it up and tip it over.
        const FrogParams frog;
        const auto run = [&frog](bool legs) {
            XpbdWorld w = makeWorld(xpbdParamsFrom(frog));
            const int b = addRegular(w, frog.center, frog.radius, frog.sides, frog.targetArea, frog.v0);
            for (int leg = 0; legs && leg < 4; ++leg) {
                const ChainAnchor a = frogLegAnchor(b, leg, frog.sides);
                if (!w.addChain(frogLegChain(frog.legs[std::size_t(leg)], a, w.anchorPoint(a))).ok())
                    return std::vector<Point>{};
            }
            for (int i = 0; i < 600; ++i) {
                if (i == 300)
                    w.press(w.centroid(b) + Point(30, 10)); // off centre: a turning drag
                if (i > 300 && i < 400)
                    w.move({640 + 3.0 * (i - 300), 300});
                if (i == 400)
                    w.release();
                w.step();
            }
            return w.bodyVertices(b);
        };
        const auto with = run(true), without = run(false);
        QCOMPARE(with.size(), std::size_t(frog.sides));
        QCOMPARE(without.size(), with.size());
        QVERIFY(std::memcmp(with.data(), without.data(), with.size() * sizeof(Point)) == 0);

        // Such a chain cannot measure its first limit from the body it does not act on.
        XpbdWorld w = makeWorld();
        const int b = addRegular(w, {640, 360}, 80, 10);
        ChainDef tail = frogLegChain(frog.legs[0], frogLegAnchor(b, 0, 10), w.anchorPoint(frogLegAnchor(b, 0, 10)));
        tail.limits[0].reference = AngleReference::Parent;
        QVERIFY(!w.addChain(tail).ok());
        tail.pullsBody = true;
        QVERIFY(w.addChain(tail).ok());
    }

    void bendingKeepsOtherShapes()
    {
        // §5.2.3: a body that is not a regular polygon — an L — keeps its form when the
        // angles between consecutive edges are constrained, and sags without them.
        std::vector<Point> l;
        for (int i = 0; i <= 6; ++i)
            l.push_back({500 + 20.0 * i, 300}); // top, left to right
        for (int i = 1; i <= 3; ++i)
            l.push_back({620, 300 + 20.0 * i}); // down the right
        for (int i = 1; i <= 3; ++i)
            l.push_back({620 - 20.0 * i, 360}); // back left
        for (int i = 1; i <= 6; ++i)
            l.push_back({560, 360 + 20.0 * i}); // down the leg
        for (int i = 1; i <= 3; ++i)
            l.push_back({560 - 20.0 * i, 480}); // foot
        for (int i = 1; i <= 8; ++i)
            l.push_back({500, 480 - 22.5 * i}); // up the left side
        l.pop_back();                           // (500, 300) is vertex 0
        QVERIFY(!selfIntersects(l));
        const auto deviation = [&](bool bending) {
            XpbdWorld w = makeWorld();
            const int b = w.addBody(l, trapezoidArea(l), {}, BodyOptions{10, bending, true}).value();
            for (int i = 0; i < 600; ++i)
                w.step();
            // RMS distance to the best-fitting copy of the rest shape (shape matching's goal).
            const auto v = w.bodyVertices(b);
            const Point c = w.centroid(b);
            const double th = w.orientation(b);
            Point rc;
            for (const Point& p : l)
                rc += p;
            rc = Point(rc.x / l.size(), rc.y / l.size());
            double sum = 0;
            for (std::size_t i = 0; i < l.size(); ++i) {
                const Point r = l[i] - rc;
                const Point g(c.x + std::cos(th) * r.x - std::sin(th) * r.y, c.y + std::sin(th) * r.x + std::cos(th) * r.y);
                sum += dot(v[i] - g, v[i] - g);
            }
            if (!w.isValid(b) || std::abs(w.areaErrorPercent(b)) >= 1.0)
                return -1.0; // not a valid body at the right area: fail below
            return std::sqrt(sum / l.size());
        };
        const double with = deviation(true), without = deviation(false);
        QVERIFY(with >= 0 && without >= 0);
        qInfo("RMS deviation from the rest shape at rest: %.2f px with bending, %.2f px without", with, without);
        QVERIFY(with < 6.0);
        QVERIFY(with < 0.25 * without);
    }

    void targetAreaChangesLive()
    {
        XpbdWorld w = makeWorld();
        const int b = w.addRegularBody({640, 400}, 120, 10, 20000, {}).value();
        for (int i = 0; i < 300; ++i)
            w.step();
        QVERIFY(std::abs(w.areaErrorPercent(b)) < 1.0);
        QVERIFY(w.setTargetArea(b, 35000).ok());
        QVERIFY(!w.setTargetArea(b, -1).ok());
        QVERIFY(!w.setTargetArea(7, 100).ok());
        for (int i = 0; i < 300; ++i)
            w.step();
        QCOMPARE(w.targetArea(b), 35000.0);
        QVERIFY(std::abs(w.areaErrorPercent(b)) < 1.0);
    }

    void wallsBrake()
    {
        // Friction: a body thrown along the floor stops sooner with μ = 1 than with μ = 0.
        const auto slide = [](double mu) {
            XpbdParams p;
            p.wallFriction = mu;
            p.damping = {1, 1};
            XpbdWorld w = makeWorld(p);
            const int b = w.addRegularBody({200, 660}, 50, 10, 7000, {}).value();
            for (int i = 0; i < 100; ++i)
                w.step();
            w.setBodyVelocity(b, {6, 0});
            const double x0 = w.centroid(b).x;
            for (int i = 0; i < 100; ++i)
                w.step();
            return w.centroid(b).x - x0;
        };
        const double icy = slide(0), rough = slide(1);
        qInfo("slide over 100 steps: %.1f px with mu = 0, %.1f px with mu = 1", icy, rough);
        QVERIFY(icy > 500);
        QVERIFY(rough < 0.5 * icy);
    }

    void legLimitsFollowTheBody()
    {
        // A limit measured from the body (AngleReference::Parent on the first link) turns
        // with the body: spin a body with a stiff one-link tail and the tail keeps its angle
        // to the anchor's vertices.
        XpbdParams p;
        p.gravity = {0, 0};
        p.damping = {1, 1};
        p.velmax = kInf;
        XpbdWorld w = makeWorld(p);
        const int b = w.addRegularBody({640, 360}, 80, 10, 18000, {}).value();
        ChainDef tail;
        tail.anchor = ChainAnchor{b, 4, 6, 0.5, {}};
        const Point root = w.anchorPoint(tail.anchor);
        tail.joints = {root, root + Point(0, 50)};
        tail.limits = {{-0.05, 0.05, AngleReference::Parent}};
        tail.jointMass = 0.2;
        const int c = w.addChain(tail).value();
        const auto rest = w.bodyVertices(b);
        const double restRef = seedAngle(rest[6] - rest[4]);
        // Spin: v = ω × (x − c).
        const auto r = w.bodyRange(b);
        std::vector<Point> v;
        for (int i = 0; i < r.count; ++i) {
            const Point d = rest[std::size_t(i)] - Point(640, 360);
            v.push_back({-0.03 * d.y, 0.03 * d.x});
        }
        double worst = 0, turned = 0;
        QVERIFY(w.setBodyVelocities(b, v).ok());
        QVERIFY(!w.setBodyVelocities(b, {{1, 2}}).ok());
        for (int i = 0; i < 300; ++i) {
            w.step();
            const auto x = w.bodyVertices(b);
            const auto j = w.chainJoints(c);
            const double bodyTurn = wrapAngle(seedAngle(x[6] - x[4]) - restRef);
            const double rel = wrapAngle(seedAngle(j[1] - j[0]) - bodyTurn);
            worst = std::max(worst, std::abs(rel) - 0.05);
            turned = std::max(turned, std::abs(bodyTurn));
        }
        qInfo("body turned up to %.2f rad; tail beyond its limit by %.2e rad at most", turned, worst);
        QVERIFY(turned > 1.0);
        QVERIFY(worst < 0.02);
    }

    // --- Determinism and energy ---------------------------------------------------------------
    void deterministic()
    {
        const auto run = [] {
            XpbdWorld w = makeWorld();
            for (int k = 0; k < 12; ++k)
                addRegular(w, {200.0 + 80 * k, 100.0 + 30 * (k % 3)}, 35, 5 + k, -1, {double(k % 3) - 1, 0});
            w.addSegmentObstacle({100, 500}, {800, 560}, 4);
            w.addPolygonObstacle({{900, 600}, {1100, 600}, {1000, 450}});
            ChainDef c;
            c.anchor = frogLegAnchor(0, 0, 5);
            c.joints = {{0, 0}, {0, 30}, {0, 60}};
            w.addChain(c);
            for (int i = 0; i < 500; ++i) {
                if (i == 100)
                    w.press(w.centroid(3));
                if (i > 100 && i < 200)
                    w.move({400.0 + i, 200});
                if (i == 200)
                    w.release();
                w.step();
            }
            return w.positions();
        };
        const auto a = run();
        const auto b = run();
        QCOMPARE(a.size(), b.size());
        QVERIFY(std::memcmp(a.data(), b.data(), a.size() * sizeof(Point)) == 0);
    }

    void energyDoesNotGrowUnderDamping_data()
    {
        QTest::addColumn<int>("which");
        QTest::newRow("one body") << 0;
        QTest::newRow("bouncy body, restitution 0.8") << 1;
        QTest::newRow("soft body") << 2;
        QTest::newRow("pile of 20") << 3;
    }
    void energyDoesNotGrowUnderDamping()
    {
        QFETCH(int, which);
        XpbdParams p;
        if (which == 1)
            p.restitution = 0.8;
        if (which == 2) {
            p.edgeCompliance = 0.05;
            p.areaCompliance = 1e-6;
        }
        XpbdWorld w = makeWorld(p);
        if (which == 3) {
            for (int k = 0; k < 20; ++k)
                addRegular(w, {300.0 + 60 * (k % 8), 100.0 + 70 * (k / 8)}, 28, 8);
        } else {
            addRegular(w, {640, 300}, 100, 10, -1, {6, -4});
        }
        const auto total = [&] { return w.kineticEnergy() + w.potentialEnergy(); };
        for (int i = 0; i < 400; ++i) // settling: the first bounces and contacts
            w.step();
        const double e0 = total();
        double worst = -kInf;
        double previous = e0;
        double worstRise = 0;
        for (int i = 0; i < 1500; ++i) {
            w.step();
            const double e = total();
            worst = std::max(worst, e - e0);
            worstRise = std::max(worstRise, e - previous);
            previous = e;
        }
        const double scale = std::abs(w.gravityEnergy()) + 1;
        qInfo("energy after settling %.6g; largest rise above it %.3e, largest rise in one step %.3e", e0, worst, worstRise);
        QVERIFY(worst <= 1e-6 * scale);
    }

    // ζ is a damping ratio: an edge stretched and let go rings down by e^{−2πζ/√(1−ζ²)} a
    // period, at the damped period T/√(1−ζ²), T = 2π √(α/(w_a + w_b)). The edge is a ring of
    // two (solveEdgeRing's averaged Jacobi) whose twin is as soft as nothing, in steps of 1
    // with T = 200 steps. XPBD's one projection a step is implicit Euler, which damps on its
    // own at ζ₀ = ω h / 2 = π/T (docs/solvers.md#damping): ζ adds to it.
    void edgeDampingRatioIsADampingRatio_data()
    {
        QTest::addColumn<double>("zeta");
        QTest::newRow("ζ = 0") << 0.0;
        QTest::newRow("ζ = 0.05") << 0.05;
        QTest::newRow("ζ = 0.2") << 0.2;
        QTest::newRow("ζ = 0.5") << 0.5;
    }
    void edgeDampingRatioIsADampingRatio()
    {
        QFETCH(double, zeta);
        const double period = 200, mobility = 2; // two vertices of mass 1
        const double alpha = mobility * std::pow(period / (2 * kPi), 2);
        DistanceConstraint ring[2];
        ring[0].a = 0, ring[0].b = 1, ring[0].rest = 100;
        ring[1].a = 1, ring[1].b = 0, ring[1].rest = 100, ring[1].complianceScale = 1e12;
        Point x[2] = {Point(0, 0), Point(110, 0)}, prev[2], v[2], delta[2];
        double dashpot[2] = {0, 0};
        const double w[2] = {1, 1};
        std::vector<double> stretch;
        for (int i = 0; i < 1200; ++i) {
            for (int k = 0; k < 2; ++k) {
                prev[k] = x[k];
                x[k] += v[k];
            }
            solveEdgeRing(ring, 2, x, prev, w, alpha, zeta, dashpot, delta);
            for (int k = 0; k < 2; ++k)
                v[k] = x[k] - prev[k];
            stretch.push_back(distance(x[0], x[1]) - 100);
        }
        // The peaks of the stretch: their ratio and spacing.
        std::vector<std::pair<double, double>> peaks; // (step, stretch)
        for (std::size_t i = 1; i + 1 < stretch.size(); ++i)
            if (stretch[i] > stretch[i - 1] && stretch[i] >= stretch[i + 1] && stretch[i] > 1e-9)
                peaks.emplace_back(double(i), stretch[i]);
        QVERIFY(peaks.size() >= 3);
        const double damped = period / std::sqrt(1 - zeta * zeta);
        const double spacing = (peaks[2].first - peaks[0].first) / 2;
        QVERIFY2(std::abs(spacing - damped) <= 0.03 * damped,
                 qPrintable(QStringLiteral("%1 against %2").arg(spacing).arg(damped)));
        const double decrement = std::log(peaks[0].second / peaks[2].second) / 2;
        const double measured = decrement / std::sqrt(4 * kPi * kPi + decrement * decrement);
        const double own = kPi / period;
        qInfo("ζ = %.2f: measured %.4f, less XPBD's own %.4f: %.4f; period %.1f steps (damped %.1f)", zeta, measured, own,
              measured - own, spacing, damped);
        QVERIFY2(std::abs(measured - own - zeta) <= 0.05 * (zeta + own), qPrintable(QString::number(measured)));
    }

    // The edges' dashpots' loss is booked as damping: a sheared body left to ring in empty
    // space (friction 1, no gravity) loses what the damping loss says it took, and rings
    // down far faster than without them. Soft edges (α = 0.5, an edge of 74 px rings at
    // 38 steps), where XPBD's own damping (ζ₀ = ω h / 2 ≈ 0.01) is small.
    void edgeDashpotsBookWhatTheyTake()
    {
        double left[2] = {0, 0};
        const double zetas[2] = {0, 0.3};
        for (int k = 0; k < 2; ++k) {
            XpbdParams p;
            p.gravity = Point(0, 0);
            p.damping = Point(1, 1);
            p.edgeDampingRatio = zetas[k];
            p.edgeCompliance = 0.5;
            XpbdWorld world = makeWorld(p);
            const int b = addRegular(world, Point(640, 360), 120, 10);
            std::vector<Point> sheared; // the same area, the edges stretched and squeezed
            for (const Point& q : world.bodyVertices(b))
                sheared.push_back(Point(640 + 1.25 * (q.x - 640), 360 + (q.y - 360) / 1.25));
            QVERIFY(world.setBodyVertices(b, sheared).ok());
            const auto total = [&] { return world.kineticEnergy() + world.gravityEnergy() + world.elasticEnergy(); };
            world.step(); // the elastic energy is read from the forces of a step
            const double e1 = total(), d1 = world.dampingLoss();
            for (int i = 0; i < 300; ++i) {
                world.step();
                QCOMPARE(world.contactCount(), 0);
            }
            const double drop = e1 - total(), booked = world.dampingLoss() - d1;
            left[k] = total() / e1;
            qInfo("ζ = %.1f: %.1f of %.1f lost, %.1f booked as damping", zetas[k], drop, e1, booked);
            if (zetas[k] == 0) {
                QCOMPARE(booked, 0.0);
            } else {
                QVERIFY(drop > 0.5 * e1);
                QVERIFY2(std::abs(booked - drop) <= 0.1 * drop,
                         qPrintable(QStringLiteral("%1 against %2").arg(booked).arg(drop)));
            }
        }
        QVERIFY(left[1] < 0.5 * left[0]); // 8 % of the energy left against 32 %
    }

    // The largest stretch of a body, found from L²/L₀² with two square roots, is
    // max |L − L₀| / max(L₀, 1) over its edges, measured edge by edge: on shapes of edges of
    // many lengths (one under 1 px at rest), stretched, squeezed and shaken at random.
    void largestStretchIsTheLargestOfTheEdges()
    {
        std::mt19937 random(16);
        std::uniform_real_distribution<double> shake(-3, 3), scale(0.7, 1.4);
        XpbdWorld world = makeWorld();
        const std::vector<Point> shape{{100, 100}, {260, 100}, {260, 100.6}, {300, 180}, {180, 260}, {90, 200}};
        const int b = world.addBody(shape, trapezoidArea(shape), Point()).value();
        const int n = world.bodyRange(b).count;
        for (int trial = 0; trial < 200; ++trial) {
            std::vector<Point> moved = world.bodyVertices(b);
            const double sx = scale(random), sy = scale(random);
            for (Point& q : moved)
                q = Point(200 + sx * (q.x - 200) + shake(random), 180 + sy * (q.y - 180) + shake(random));
            QVERIFY(world.setBodyVertices(b, moved).ok());
            const std::vector<Point> x = world.bodyVertices(b);
            double expected = 0;
            for (int k = 0; k < n; ++k) {
                const double rest = world.edgeRest(b, k).length;
                expected = std::max(expected, std::abs(distance(x[std::size_t(k)], x[std::size_t((k + 1) % n)]) - rest) /
                                                  std::max(rest, 1.0));
            }
            QVERIFY2(std::abs(world.maxEdgeStretch(b) - expected) <= 1e-12 * (1 + expected),
                     qPrintable(
                         QStringLiteral("%1 against %2").arg(world.maxEdgeStretch(b), 0, 'g', 17).arg(expected, 0, 'g', 17)));
        }
        QVERIFY(world.edgeRest(b, 1).length < 1); // the tiny edge is there
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestXpbdSolver)
#include "test_xpbd_solver.moc"
