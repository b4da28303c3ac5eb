// Continuity at the knots of piecewise curves (§2.3; knot_continuity.h) and the graph of a
// function spline as parametric segments (function_spline_segments.h). Expected values come
// from formulas independent of the code: the Hermite form of a cubic segment, quadratic
// reproduction by uniform Catmull-Rom curves with τ = 1/2, the invariance of G^k under
// reparametrization.
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/cubic_spline.h"
#include "core/curves/splines/function_spline_segments.h"
#include "core/curves/splines/knot_continuity.h"
#include "core/exact/rational.h"

#include <QRandomGenerator>
#include <QtTest>
#include "tests/test_main.h"

#include <cmath>

using namespace granota;

namespace {

RPoint rp(long x, long y) { return RPoint(Rational(x), Rational(y)); }
using RSegment = Vec2<Polynomial<Rational>>;
RSegment line(const RPoint& from, const RPoint& velocity)
{
    return RSegment(Polynomial<Rational>({from.x, velocity.x}), Polynomial<Rational>({from.y, velocity.y}));
}

std::vector<RPoint> ex213Points() { return {rp(3, 5), rp(2, 2), rp(6, 0), rp(8, 3), rp(7, 5)}; }

} // namespace

class TestKnotContinuity : public QObject {
    Q_OBJECT
private slots:
    // A uniform Catmull-Rom curve is C¹ at every knot (Prop 2.3); its second derivative jumps
    // by what the Hermite form of each segment gives: with T_i = τ(q_{i+1} − q_{i−1}),
    // p″(0) = 6(P₂ − P₁) − 4T₁ − 2T₂ and p″(1) = −6(P₂ − P₁) + 2T₁ + 4T₂.
    void catmullRomIsC1WithTheHermiteJumpOfTheSecondDerivative()
    {
        const auto q = ex213Points();
        const Rational tau = frac(1, 2);
        const auto segs = catmullRomSegments(q, tau, CatmullRomMode::Open);
        QVERIFY(static_cast<bool>(segs));
        const auto knots = knotContinuity(*segs);
        QCOMPARE(knots.size(), segs->size() - 1);
        // Open ends repeat the end points (Def 2.10, option 2).
        auto Q = [&](int i) { return q[static_cast<std::size_t>(std::clamp(i, 0, 4))]; };
        auto T = [&](int i) { return RPoint(tau * (Q(i + 1).x - Q(i - 1).x), tau * (Q(i + 1).y - Q(i - 1).y)); };
        const Rational six(6), four(4), two(2);
        int notC2 = 0;
        for (const auto& k : knots) {
            const int i = k.toSegment; // the knot q_i, between segments from q_{i−1} and from q_i
            QVERIFY(k.equal[0]);
            QVERIFY(k.equal[1]);
            QCOMPARE(k.left[1], T(i));
            const RPoint left = RPoint(-six * (Q(i).x - Q(i - 1).x) + two * T(i - 1).x + four * T(i).x,
                                       -six * (Q(i).y - Q(i - 1).y) + two * T(i - 1).y + four * T(i).y);
            const RPoint right = RPoint(six * (Q(i + 1).x - Q(i).x) - four * T(i).x - two * T(i + 1).x,
                                        six * (Q(i + 1).y - Q(i).y) - four * T(i).y - two * T(i + 1).y);
            QCOMPARE(k.left[2], left);
            QCOMPARE(k.right[2], right);
            QCOMPARE(k.equal[2], left == right);
            QCOMPARE(k.parametricOrder(), left == right ? 2 : 1);
            QVERIFY(k.g1); // C¹ with a non-zero tangent
            QCOMPARE(*k.tangentTurn, 0.0);
            notC2 += left == right ? 0 : 1;
            // G² means equal curvature; the doubles agree with the verdict.
            QVERIFY(k.curvatureLeft && k.curvatureRight);
            QCOMPARE(k.g2, std::fabs(*k.curvatureLeft - *k.curvatureRight) < 1e-12);
        }
        QCOMPARE(notC2, static_cast<int>(knots.size())); // Ex 2.13: no knot is C²
    }

    // τ = 1/2 reproduces quadratics in the uniform parameter: through q_i = (i, i²) the
    // interior segments are (u, u²) exactly, so their knots are C² and G²; the end segments
    // (repeated end points) are not.
    void catmullRomThroughAParabolaIsC2Inside()
    {
        std::vector<RPoint> q;
        for (long i = 0; i <= 6; ++i)
            q.push_back(rp(i, i * i));
        const auto segs = catmullRomSegments(q, frac(1, 2), CatmullRomMode::Open);
        QVERIFY(static_cast<bool>(segs));
        const auto knots = knotContinuity(*segs);
        QCOMPARE(knots.size(), std::size_t(5));
        for (std::size_t j = 0; j < knots.size(); ++j) {
            const bool inside = j >= 1 && j + 1 < knots.size();
            QCOMPARE(knots[j].parametricOrder(), inside ? 2 : 1);
            QCOMPARE(knots[j].geometricOrder(), inside ? 2 : 1);
            if (inside)
                QCOMPARE(knots[j].left[2], rp(0, 2));
        }
    }

    // Def 2.3's spline is C² in x; drawn as its graph with h_i = x_{i+1} − x_i it is C² and
    // G² at every knot, exactly. In the local parameters alone (h = 1) unequal intervals
    // break C¹, but not G¹ or G²: geometric continuity does not see the parametrization.
    void cubicSplineGraphIsC2AndG2()
    {
        const std::vector<RPoint> pts{rp(0, 0), rp(1, 2), rp(3, 1), rp(4, 3), rp(7, -1)};
        const auto spline = naturalCubicSpline(pts);
        QVERIFY(static_cast<bool>(spline));
        const auto graph = functionSplineSegments(*spline);
        QCOMPARE(graph.intervals, (std::vector<Rational>{Rational(1), Rational(2), Rational(1), Rational(3)}));
        for (const auto& k : knotContinuity(graph.segments, graph.intervals)) {
            QCOMPARE(k.parametricOrder(), 2);
            QCOMPARE(k.geometricOrder(), 2);
        }
        const auto local = knotContinuity(graph.segments);
        QCOMPARE(local[0].parametricOrder(), 0); // h = 1 against h = 2
        for (const auto& k : local)
            QCOMPARE(k.geometricOrder(), 2);
    }

    // The segments trace the graph: segment i at u is (x, s(x)) with x = x_i + h_i u.
    void functionSplineSegmentsTraceTheGraph()
    {
        const std::vector<RPoint> pts{rp(-2, 1), rp(1, 3), rp(2, 1), rp(6, -1)};
        const auto spline = naturalCubicSpline(pts);
        QVERIFY(static_cast<bool>(spline));
        const auto graph = functionSplineSegments(*spline);
        QCOMPARE(graph.segments.size(), std::size_t(3));
        QRandomGenerator g(215);
        for (int i = 0; i < 3; ++i)
            for (int r = 0; r < 20; ++r) {
                const Rational u = frac(static_cast<long>(g.bounded(0, 97)), 96);
                const Rational x = spline->knots[std::size_t(i)] + graph.intervals[std::size_t(i)] * u;
                const auto& seg = graph.segments[std::size_t(i)];
                QCOMPARE(seg.x(u), x);
                QCOMPARE(seg.y(u), spline->evaluatePiece(i, x));
            }
        // Doubles (local storage) agree with the rational pieces.
        std::vector<Point> dp;
        for (const auto& p : pts)
            dp.push_back(Point(toDouble(p.x), toDouble(p.y)));
        const auto dspline = naturalCubicSpline(dp);
        QVERIFY(static_cast<bool>(dspline) && dspline->localOrigin);
        const auto dgraph = functionSplineSegments(*dspline);
        for (int i = 0; i < 3; ++i)
            for (double u : {0.0, 0.3, 1.0}) {
                const double x = toDouble(graph.segments[std::size_t(i)].x(Rational(0))) +
                                 toDouble(graph.intervals[std::size_t(i)]) * u;
                QVERIFY(std::fabs(dgraph.segments[std::size_t(i)].y(u) - dspline->evaluatePiece(i, x)) < 1e-12);
            }
    }

    // The same line at two speeds: C⁰, not C¹, but G¹ and G² (κ = 0 on both sides). A corner
    // of 90°: C⁰ only, the tangent turns by π/2.
    void speedChangeAndCorner()
    {
        const auto slow = line(rp(0, 0), rp(1, 0));
        const auto fast = line(rp(1, 0), rp(2, 0));
        const auto k = knotContinuity<Rational>({slow, fast}).at(0);
        QCOMPARE(k.parametricOrder(), 0);
        QCOMPARE(k.geometricOrder(), 2);
        QCOMPARE(k.jump(1), rp(1, 0));
        QCOMPARE(*k.curvatureLeft, 0.0);

        const auto up = line(rp(1, 0), rp(0, 1));
        const auto c = knotContinuity<Rational>({slow, up}).at(0);
        QCOMPARE(c.parametricOrder(), 0);
        QCOMPARE(c.geometricOrder(), 0);
        QVERIFY(std::fabs(*c.tangentTurn - M_PI / 2) < 1e-15);
        // A gap: not even C⁰.
        const auto apart = line(rp(2, 0), rp(1, 0));
        QCOMPARE(knotContinuity<Rational>({slow, apart}).at(0).parametricOrder(), -1);
    }

    // Where a tangent vanishes (a cusp at the knot) the direction, the curvature and the
    // turn are undefined: no G¹, no value, never 0 or NaN.
    void vanishingTangentIsNotG1()
    {
        // (1 − (1 − s)², 0)·… : x(s) = 2s − s², x′(1) = 0.
        const RSegment stop(Polynomial<Rational>({Rational(0), Rational(2), Rational(-1)}), Polynomial<Rational>({Rational(0)}));
        const auto go = line(rp(1, 0), rp(1, 0));
        const auto k = knotContinuity<Rational>({stop, go}).at(0);
        QVERIFY(k.equal[0]);
        QVERIFY(!k.g1);
        QVERIFY(!k.curvatureLeft);
        QVERIFY(k.curvatureRight.has_value());
        QVERIFY(!k.tangentTurn);
        QCOMPARE(k.geometricOrder(), 0);
        // Doubles decide "zero" relative to the segment: 1e-14 of its size still counts.
        const Vec2<Polynomial<double>> dstop(Polynomial<double>({0.0, 2.0, -1.0 + 1e-14}), Polynomial<double>({0.0}));
        const Vec2<Polynomial<double>> dgo(Polynomial<double>({1.0 + 1e-14, 1.0}), Polynomial<double>({0.0}));
        const auto d = knotContinuity<double>({dstop, dgo}, {}, false, 1e-12).at(0);
        QVERIFY(!d.g1);
        QVERIFY(!d.curvatureLeft);
    }

    // Closed loop: the last knot joins the last segment to the first; centripetal spacing is
    // C¹ in the knot parameter (intervals h_i = |q_{i+1} − q_i|^½) and only G¹ in the local s.
    void centripetalIsC1InTheKnotParameter()
    {
        const std::vector<Point> q{{0, 0}, {1, 0}, {5, 2}, {6, 6}, {2, 6}}; // h: 1, √20, √17, 4, √40
        const auto segs = catmullRomSegments(q, 0.5, CatmullRomMode::Closed, 0.5);
        QVERIFY(static_cast<bool>(segs));
        QCOMPARE(segs->size(), q.size());
        std::vector<double> h;
        for (std::size_t i = 0; i < q.size(); ++i)
            h.push_back(std::sqrt(distance(q[i], q[(i + 1) % q.size()])));
        const auto global = knotContinuity(*segs, h, true, 1e-12);
        const auto local = knotContinuity(*segs, {}, true, 1e-12);
        QCOMPARE(global.size(), q.size());
        QCOMPARE(global.back().fromSegment, 4);
        QCOMPARE(global.back().toSegment, 0);
        int localC1 = 0;
        for (std::size_t j = 0; j < global.size(); ++j) {
            QCOMPARE(global[j].parametricOrder(), 1);
            QVERIFY(global[j].g1);
            QVERIFY(local[j].g1);
            localC1 += local[j].equal[1] ? 1 : 0;
        }
        QCOMPARE(localC1, 0); // every interval differs from its neighbour's
    }

    void fewerThanTwoSegmentsHaveNoKnots()
    {
        QVERIFY(knotContinuity<Rational>({}).empty());
        QVERIFY(knotContinuity<Rational>({line(rp(0, 0), rp(1, 1))}).empty());
        QCOMPARE(knotContinuity<Rational>({line(rp(0, 0), rp(0, 0))}, {}, true).size(), std::size_t(1));
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestKnotContinuity)
#include "test_knot_continuity.moc"
