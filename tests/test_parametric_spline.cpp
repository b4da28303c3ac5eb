// The parametric C² spline (Def 2.1 in full, parametric_spline.h) and the cyclic tridiagonal
// solver under its closed form. How each expected value is found, independently of the code:
//  - continuity is checked from the segments' own coefficients (p, p′, p″, p‴ at s = 0 and
//    s = 1, divided by h, h², h³ for the global u): a property, not a second solve;
//  - the diamond's periodic spline was solved by hand (its symmetry gives M_1 = M_3 = 0);
//  - a cubic polynomial curve's segments are its Taylor expansions at the knots (Polynomial::shifted);
//  - chord lengths of 3-4-5 and 7-24-25 steps are integers; cumulative sums by hand;
//  - the cyclic solver's answer is put back into the system (exact residual 0).
#include "core/curves/splines/cyclic_tridiagonal_system.h"
#include "core/curves/splines/parametric_spline.h"
#include "core/exact/rational.h"
#include "tests/rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <limits>
#include <random>

using namespace granota;
using granota::testing::pts;

static char* toString(const Rational& v) { return qstrdup(granota::toString(v).c_str()); }
namespace granota {
static char* toString(const Vec2<Rational>& p)
{
    return qstrdup(("(" + granota::toString(p.x) + ", " + granota::toString(p.y) + ")").c_str());
}
} // namespace granota

Q_DECLARE_METATYPE(granota::ParametricEnds)

namespace {

using RV = Vec2<Rational>;
using Coefficients = std::array<RV, 4>;

Rational q(long n, long d = 1) { return frac(n, d); }

/// The k-th derivative (k ≤ 3) of a segment at its local s = 0 or s = 1, in the local s.
RV derivativeAt(const Coefficients& c, int k, bool atEnd)
{
    // d^k/ds^k Σ c_j s^j = Σ_{j≥k} j!/(j−k)! c_j s^{j−k}.
    static const int falling[4][4] = {{1, 1, 1, 1}, {0, 1, 2, 3}, {0, 0, 2, 6}, {0, 0, 0, 6}};
    RV sum(q(0), q(0));
    for (int j = k; j <= 3; ++j)
        if (atEnd || j == k)
            sum += Rational(falling[k][j]) * c[static_cast<std::size_t>(j)];
    return sum;
}

/// The k-th derivative in the global u: d/du = (1/h) d/ds.
RV globalDerivativeAt(const ParametricSpline<Rational>& s, std::size_t segment, int k, bool atEnd)
{
    const Rational h = s.knots[segment + 1] - s.knots[segment];
    Rational scale(1);
    for (int j = 0; j < k; ++j)
        scale /= h;
    return scale * derivativeAt(s.segments[segment], k, atEnd);
}

/// The highest order r ≤ 3 with p^(j) continuous for j ≤ r where segment `i` meets the next
/// one (`wrap`: the last meets the first), −1 when the points differ.
int joinOrder(const ParametricSpline<Rational>& s, std::size_t i, std::size_t next)
{
    int order = -1;
    for (int k = 0; k <= 3; ++k) {
        if (globalDerivativeAt(s, i, k, true) != globalDerivativeAt(s, next, k, false))
            return order;
        order = k;
    }
    return order;
}

/// The points P_i of a curve at u = 0, 1, …, n.
std::vector<RV> sampleCurve(const Vec2<Polynomial<Rational>>& p, int n)
{
    std::vector<RV> out;
    for (int u = 0; u <= n; ++u)
        out.emplace_back(p.x(Rational(u)), p.y(Rational(u)));
    return out;
}

} // namespace

class TestParametricSpline : public QObject {
    Q_OBJECT

private slots:
    void periodicIsC2AtEveryKnotIncludingTheWrap_data()
    {
        QTest::addColumn<int>("seed");
        QTest::addColumn<int>("count");
        QTest::addColumn<int>("parameters");
        for (int seed = 1; seed <= 4; ++seed)
            for (int count : {3, 4, 7})
                QTest::addRow("seed %d, %d points", seed, count) << seed << count << int(SplineParameters::Uniform);
    }
    void periodicIsC2AtEveryKnotIncludingTheWrap()
    {
        QFETCH(int, seed);
        QFETCH(int, count);
        std::mt19937 rng(static_cast<unsigned>(seed));
        const auto points = testing::randomRational(rng, count - 1);
        const auto s = parametricSpline(points, ParametricEnds::Periodic, SplineParameters::Uniform);
        QVERIFY2(s.ok(), s.ok() ? "" : s.error().message.c_str());
        const std::size_t n = points.size();
        QCOMPARE(s->segments.size(), n);
        QCOMPARE(s->knots.size(), n + 1);
        for (std::size_t i = 0; i < n; ++i) {
            QCOMPARE(s->segments[i][0], points[i]); // interpolation
            const std::size_t next = (i + 1) % n;
            QVERIFY2(joinOrder(*s, i, next) >= 2, qPrintable(QString("knot %1").arg(next)));
        }
    }

    void periodicChordParametersAreC2InTheGlobalParameter()
    {
        // Steps 5, 5, 6 (3-4-5 triangles): rational chord lengths, so exact; C² in u, where
        // the local derivatives differ because the steps do.
        const auto points = pts({{0, 0}, {3, 4}, {6, 0}});
        const auto s = parametricSpline(points, ParametricEnds::Periodic, SplineParameters::Chord);
        QVERIFY(s.ok());
        QCOMPARE(s->knots, (std::vector<Rational>{q(0), q(5), q(10), q(16)}));
        for (std::size_t i = 0; i < 3; ++i)
            QVERIFY(joinOrder(*s, i, (i + 1) % 3) >= 2);
    }

    void periodicDiamondByHand()
    {
        // x = 0, 1, 2, 1 periodic, uniform: M_{i−1} + 4M_i + M_{i+1} = 6(x_{i+1} − 2x_i + x_{i−1})
        // gives right sides 12, 0, −12, 0; symmetry M_1 = M_3 = 0, so M_0 = 3, M_2 = −3.
        // Segment 0: c_1 = (x_1 − x_0) − (2M_0 + M_1)/6 = 0, c_2 = M_0/2 = 3/2, c_3 = (M_1 − M_0)/6 = −1/2.
        // y = 0, 1, 0, −1 is x turned by a quarter: M^y = 0, 3, 0, −3.
        const auto s = parametricSpline(pts({{0, 0}, {1, 1}, {2, 0}, {1, -1}}), ParametricEnds::Periodic,
                                        SplineParameters::Uniform);
        QVERIFY(s.ok());
        QCOMPARE(s->segments[0][0], RV(q(0), q(0)));
        QCOMPARE(s->segments[0][1], RV(q(0), q(3, 2)));
        QCOMPARE(s->segments[0][2], RV(q(3, 2), q(0)));
        QCOMPARE(s->segments[0][3], RV(q(-1, 2), q(-1, 2)));
        // The closing segment from (1, −1) back to (0, 0).
        QCOMPARE(s->segments[3][1], RV(q(-3, 2), q(0)));
        QCOMPARE(s->segments[3][2], RV(q(0), q(3, 2)));
    }

    void periodicChordAgreesWithScipy()
    {
        // scipy 1.10: CubicSpline(u, P + [P_0], bc_type='periodic', axis=0) with u the
        // cumulative chord lengths; its c[3 − k, i]·h_i^k are the local-s coefficients below.
        const std::vector<Point> points{{0, 0}, {2, 1}, {3, 3}, {1, 4}, {-1, 2}};
        const double expected[5][4][2] = {
            {{0, 0},
             {1.8011680308555793, -0.60841314763186383},
             {0.44585265909477056, 2.2650150160696572},
             {-0.24702068995034973, -0.65660186843779322}},
            {{2, 1},
             {1.9518112791940709, 1.9518112791940707},
             {-0.29520941075627838, 0.2952094107562796},
             {-0.65660186843779256, -0.2470206899503502}},
            {{3, 3},
             {-0.6084131476318636, 1.8011680308555793},
             {-2.2650150160696572, -0.4458526590947709},
             {0.87342816370152043, -0.35531537176080846}},
            {{1, 4},
             {-3.1852467863717364, -0.19793758731237485},
             {0.56843116005584715, -2.4188780390035154},
             {0.61681562631588904, 0.61681562631588982}},
            {{-1, 2},
             {-0.15648340261638788, -2.5181586886666159},
             {1.5117987743771968, -0.35526947503490458},
             {-0.35531537176080868, 0.87342816370152043}},
        };
        const auto s = parametricSpline(points, ParametricEnds::Periodic, SplineParameters::Chord);
        QVERIFY(s.ok());
        QCOMPARE(s->segments.size(), std::size_t(5));
        for (std::size_t i = 0; i < 5; ++i)
            for (std::size_t k = 0; k < 4; ++k) {
                // Coefficients of size ≤ 4 from two different solvers: agreement to 1e-12.
                QVERIFY(std::abs(s->segments[i][k].x - expected[i][k][0]) < 1e-12);
                QVERIFY(std::abs(s->segments[i][k].y - expected[i][k][1]) < 1e-12);
            }
    }

    void clampedEndsGiveTheAskedTangents_data()
    {
        QTest::addColumn<int>("parameters");
        QTest::addRow("uniform") << int(SplineParameters::Uniform);
        QTest::addRow("chord") << int(SplineParameters::Chord);
    }
    void clampedEndsGiveTheAskedTangents()
    {
        QFETCH(int, parameters);
        // Steps 5, 6, 25 (3-4-5 and 7-24-25): rational chord lengths.
        const auto points = pts({{0, 0}, {3, 4}, {3, 10}, {10, 34}});
        const RV start(q(2, 3), q(-5)), end(q(7), q(1, 9));
        const auto s = parametricSpline(points, ParametricEnds::Clamped, SplineParameters(parameters), start, end);
        QVERIFY2(s.ok(), s.ok() ? "" : s.error().message.c_str());
        QCOMPARE(globalDerivativeAt(*s, 0, 1, false), start);
        QCOMPARE(globalDerivativeAt(*s, 2, 1, true), end);
        for (std::size_t i = 0; i < 2; ++i)
            QVERIFY(joinOrder(*s, i, i + 1) >= 2);
        QCOMPARE(s->segments[2][0] + s->segments[2][1] + s->segments[2][2] + s->segments[2][3], points[3]);
    }

    void naturalEndsHaveNoSecondDerivative()
    {
        std::mt19937 rng(7);
        const auto points = testing::randomRational(rng, 5);
        const auto s = parametricSpline(points, ParametricEnds::Natural, SplineParameters::Uniform);
        QVERIFY(s.ok());
        QCOMPARE(derivativeAt(s->segments.front(), 2, false), RV(q(0), q(0)));
        QCOMPARE(derivativeAt(s->segments.back(), 2, true), RV(q(0), q(0)));
        for (std::size_t i = 0; i + 1 < s->segments.size(); ++i) {
            QCOMPARE(s->segments[i][0], points[i]);
            QCOMPARE(joinOrder(*s, i, i + 1), 2); // C², and (random data) not C³
        }
    }

    void notAKnotIsC3AtTheSecondAndLastButOneKnots()
    {
        std::mt19937 rng(11);
        const auto points = testing::randomRational(rng, 6); // 7 points, 6 segments
        const auto s = parametricSpline(points, ParametricEnds::NotAKnot, SplineParameters::Uniform);
        QVERIFY(s.ok());
        const std::size_t last = s->segments.size() - 1;
        QCOMPARE(joinOrder(*s, 0, 1), 3);
        QCOMPARE(joinOrder(*s, last - 1, last), 3);
        for (std::size_t i = 1; i + 1 < last; ++i)
            QVERIFY(joinOrder(*s, i, i + 1) >= 2);
    }

    void notAKnotReproducesACubicCurve()
    {
        // p(u) = (u³ − 2u + 1, −u³/3 + 2u² + 5) sampled at u = 0..5: the not-a-knot spline is p
        // itself, so segment i is p(i + s) = p(i) + p′(i)s + p″(i)/2 s² + p‴/6 s³ (Taylor).
        using RP = Polynomial<Rational>;
        const Vec2<RP> p(RP{q(1), q(-2), q(0), q(1)}, RP{q(5), q(0), q(2), q(-1, 3)});
        const auto s = parametricSpline(sampleCurve(p, 5), ParametricEnds::NotAKnot, SplineParameters::Uniform);
        QVERIFY(s.ok());
        QCOMPARE(s->segments.size(), std::size_t(5));
        for (int i = 0; i < 5; ++i) {
            const RP x = p.x.shifted(Rational(i)), y = p.y.shifted(Rational(i));
            for (int k = 0; k < 4; ++k)
                QCOMPARE(s->segments[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)],
                         RV(x.coefficient(k), y.coefficient(k)));
        }
    }

    void chordKnotsAreTheCumulativeDistances()
    {
        // Steps 5, 6, 5: knots 0, 5, 11, 16; centripetal √5, √6, √5.
        const std::vector<Point> points{{0, 0}, {3, 4}, {3, 10}, {0, 6}};
        const auto chord = splineKnots(points, SplineParameters::Chord, false);
        QVERIFY(chord.ok());
        QCOMPARE(*chord, (std::vector<double>{0, 5, 11, 16}));
        const auto centripetal = splineKnots(points, SplineParameters::Centripetal, false);
        QVERIFY(centripetal.ok());
        const double r5 = std::sqrt(5.0), r6 = std::sqrt(6.0);
        const std::vector<double> expected{0, r5, r5 + r6, 2 * r5 + r6};
        for (std::size_t i = 0; i < expected.size(); ++i)
            QVERIFY(std::abs((*centripetal)[i] - expected[i]) < 1e-14);
        // Closed: one more step back to P_0, of length 6.
        const auto closed = splineKnots(points, SplineParameters::Chord, true);
        QVERIFY(closed.ok());
        QCOMPARE(closed->back(), 22.0);
        // The spline's knots are these knots.
        const auto s = parametricSpline(points, ParametricEnds::Natural, SplineParameters::Chord);
        QVERIFY(s.ok());
        QCOMPARE(s->knots, *chord);
    }

    void exactKnotsWhenTheLengthsAreRational()
    {
        const auto points = pts({{0, 0}, {7, 24}, {7, 33}});
        const auto centripetal = splineKnots(points, SplineParameters::Centripetal, false); // √25, √9
        QVERIFY(centripetal.ok());
        QCOMPARE(*centripetal, (std::vector<Rational>{q(0), q(5), q(8)}));
        const auto irrational = parametricSpline(pts({{0, 0}, {1, 1}, {2, 0}}), ParametricEnds::Natural, SplineParameters::Chord);
        QVERIFY(!irrational.ok());
        QCOMPARE(irrational.error().code, ErrorCode::NotRational);
    }

    void doublesAgreeWithTheExactSpline_data()
    {
        QTest::addColumn<ParametricEnds>("ends");
        QTest::addRow("natural") << ParametricEnds::Natural;
        QTest::addRow("clamped") << ParametricEnds::Clamped;
        QTest::addRow("not-a-knot") << ParametricEnds::NotAKnot;
        QTest::addRow("periodic") << ParametricEnds::Periodic;
    }
    void doublesAgreeWithTheExactSpline()
    {
        QFETCH(ParametricEnds, ends);
        std::mt19937 rng(3);
        const auto exactPoints = testing::randomRational(rng, 8);
        std::vector<Point> points;
        for (const auto& p : exactPoints)
            points.emplace_back(toDouble(p.x), toDouble(p.y));
        const auto exact = parametricSpline(exactPoints, ends, SplineParameters::Uniform, RV(q(1), q(2)), RV(q(-3), q(1, 2)));
        const auto floating = parametricSpline(points, ends, SplineParameters::Uniform, Point(1, 2), Point(-3, 0.5));
        QVERIFY(exact.ok() && floating.ok());
        QCOMPARE(floating->segments.size(), exact->segments.size());
        for (std::size_t i = 0; i < exact->segments.size(); ++i)
            for (std::size_t k = 0; k < 4; ++k) {
                // Coordinates of size ≤ 30: a few units in the last place of 30 is well under 1e-12.
                QVERIFY(std::abs(floating->segments[i][k].x - toDouble(exact->segments[i][k].x)) < 1e-12);
                QVERIFY(std::abs(floating->segments[i][k].y - toDouble(exact->segments[i][k].y)) < 1e-12);
            }
    }

    void refusals()
    {
        const auto one = parametricSpline(std::vector<Point>{{0, 0}}, ParametricEnds::Natural, SplineParameters::Uniform);
        QCOMPARE(one.error().code, ErrorCode::TooFewPoints);
        const auto two = parametricSpline(std::vector<Point>{{0, 0}, {1, 0}}, ParametricEnds::Periodic,
                                          SplineParameters::Uniform);
        QCOMPARE(two.error().code, ErrorCode::TooFewPoints);
        QVERIFY(two.error().message.find("at least 3") != std::string::npos);
        const std::vector<Point> repeated{{0, 0}, {1, 1}, {1, 1}, {2, 0}};
        for (SplineParameters p : {SplineParameters::Chord, SplineParameters::Centripetal}) {
            const auto r = parametricSpline(repeated, ParametricEnds::Natural, p);
            QCOMPARE(r.error().code, ErrorCode::InvalidInput);
            QVERIFY(r.error().message.find("P_1 and P_2 coincide") != std::string::npos);
        }
        // Uniform parameters take a repeated point (a segment that stays put).
        QVERIFY(parametricSpline(repeated, ParametricEnds::Natural, SplineParameters::Uniform).ok());
        // Closed: the step back from the last point to the first counts too.
        const auto wrap = parametricSpline(std::vector<Point>{{0, 0}, {1, 1}, {2, 0}, {0, 0}}, ParametricEnds::Periodic,
                                           SplineParameters::Chord);
        QCOMPARE(wrap.error().code, ErrorCode::InvalidInput);
        const auto noTangent = parametricSpline(repeated, ParametricEnds::Clamped, SplineParameters::Uniform, Point(1, 0));
        QCOMPARE(noTangent.error().code, ErrorCode::InvalidInput);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const auto notFinite = parametricSpline(std::vector<Point>{{0, 0}, {nan, 1}, {2, 0}}, ParametricEnds::Natural,
                                                SplineParameters::Uniform);
        QCOMPARE(notFinite.error().code, ErrorCode::InvalidInput);
        const auto badTangent = parametricSpline(repeated, ParametricEnds::Clamped, SplineParameters::Uniform, Point(nan, 0),
                                                 Point(0, 0));
        QCOMPARE(badTangent.error().code, ErrorCode::InvalidInput);
        const auto huge = parametricSpline(std::vector<Point>{{0, 0}, {1e308, 1e308}, {-1e308, 1e308}}, ParametricEnds::Periodic,
                                           SplineParameters::Uniform);
        QCOMPARE(huge.error().code, ErrorCode::OutOfRange);
    }

    void cyclicSolverSolvesTheSystem_data()
    {
        QTest::addColumn<int>("n");
        for (int n : {3, 4, 9})
            QTest::addRow("n = %d", n) << n;
    }
    void cyclicSolverSolvesTheSystem()
    {
        // Random rational coefficients (not diagonally dominant); the answer put back into
        // the cyclic rows must give the right side exactly.
        QFETCH(int, n);
        std::mt19937 rng(static_cast<unsigned>(n));
        std::uniform_int_distribution<int> num(-9, 9), den(1, 5);
        const auto r = [&] { return frac(num(rng), den(rng)); };
        const auto size = static_cast<std::size_t>(n);
        std::vector<Rational> sub(size), diag(size), super(size), rhs(size);
        for (std::size_t i = 0; i < size; ++i) {
            sub[i] = r();
            diag[i] = r() + Rational(20); // keeps the system regular (dominant), not its pivots
            super[i] = r();
            rhs[i] = r();
        }
        const auto x = solveCyclicTridiagonal(sub, diag, super, rhs);
        QVERIFY(x.has_value());
        for (std::size_t i = 0; i < size; ++i) {
            const Rational row = sub[i] * (*x)[(i + size - 1) % size] + diag[i] * (*x)[i] + super[i] * (*x)[(i + 1) % size];
            QCOMPARE(row, rhs[i]);
        }
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestParametricSpline)
#include "test_parametric_spline.moc"
