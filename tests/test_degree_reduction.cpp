// Degree reduction in L²([0, 1]): undoes degree elevation exactly, satisfies the normal
// equations exactly, and beats other curves of the lower degree.
#include "core/curves/bezier/bernstein.h"
#include "core/curves/bezier/degree_elevation.h"
#include "core/curves/bezier/degree_reduction.h"
#include "rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <random>

using namespace granota;
using granota::testing::randomRational;

namespace {

/// √∫|c − r|² by composite Simpson on 2000 intervals (an independent check of the error).
double numericL2(const std::vector<Point>& c, const std::vector<Point>& r)
{
    const int N = 2000;
    double s = 0;
    for (int j = 0; j <= N; ++j) {
        const double t = double(j) / N;
        const Point d = bezierBernstein(c, t) - bezierBernstein(r, t);
        s += (j == 0 || j == N ? 1 : (j % 2 ? 4 : 2)) * dot(d, d);
    }
    return std::sqrt(s / (3.0 * N));
}

} // namespace

class TestDegreeReduction : public QObject {
    Q_OBJECT
private slots:
    // Elevate then reduce gives back the original exactly, with error 0 and exact = true.
    void undoesElevation()
    {
        std::mt19937 rng(11);
        for (int n = 0; n <= 9; ++n) {
            const auto p = randomRational(rng, n);
            const auto r = reduceDegree(elevateDegree(p));
            QVERIFY(r.ok());
            QVERIFY(r->points == p);
            QVERIFY(r->exact);
            QCOMPARE(r->error, 0.0);
        }
        // Doubles: an elevation whose points are exact in binary (3 → 4: quarters) comes back
        // exactly too.
        const std::vector<Point> d{{0, 0}, {1, 2}, {4, -2}, {3, 3}};
        const auto rd = reduceDegree(elevateDegree(d));
        QVERIFY(rd.ok() && rd->exact);
        QVERIFY(rd->points == d);
        QCOMPARE(rd->error, 0.0);
    }

    // A cubic that is not an elevation: the normal equations ∫ (c − r) B_i^2 = 0 hold exactly
    // (the residual is orthogonal to every quadratic Bernstein polynomial), and the error is
    // the L² distance and is smaller than that of other quadratics: the chord-like curve
    // through P_0, (3P_1 + 3P_2 − P_0 − P_3)/4, P_3 and small changes of the optimum.
    void cubicToQuadratic()
    {
        std::vector<RPoint> p;
        for (auto [x, y] : std::vector<std::pair<int, int>>{{0, 0}, {0, 1}, {1, 1}, {1, 0}})
            p.emplace_back(Rational(x), Rational(y));
        const auto r = reduceDegree(p);
        QVERIFY(r.ok());
        QVERIFY(!r->exact);
        QCOMPARE(int(r->points.size()), 3);
        const auto e = elevateDegree(r->points);
        // ∫ B_k^3 B_i^2 = C(3,k) C(2,i) / (6 C(5, k+i)).
        for (int i = 0; i <= 2; ++i) {
            RPoint s(Rational(0), Rational(0));
            for (int k = 0; k <= 3; ++k) {
                Rational w = binomial(3, k) * binomial(2, i) / (Rational(6) * binomial(5, k + i));
                w.canonicalize();
                s += w * (p[std::size_t(k)] - e[std::size_t(k)]);
            }
            QCOMPARE(s, RPoint(Rational(0), Rational(0)));
        }
        // Symmetric curve: the optimum is symmetric, (0, y0), (1/2, y1), (1, y0).
        QCOMPARE(r->points[0].x + r->points[2].x, Rational(1));
        QCOMPARE(r->points[1].x, frac(1, 2));

        const std::vector<Point> c = toDouble(p);
        const std::vector<Point> q = toDouble(r->points);
        QVERIFY(std::abs(numericL2(c, q) - r->error) < 1e-9);
        QVERIFY(r->error > 0);
        std::vector<std::vector<Point>> others{{c[0], Point(0.5, 1.25), c[3]}};
        for (int i = 0; i < 3; ++i)
            for (double dx : {-0.01, 0.01}) {
                auto o = q;
                o[std::size_t(i)].x += dx;
                others.push_back(o);
                o = q;
                o[std::size_t(i)].y += dx;
                others.push_back(o);
            }
        for (const auto& o : others)
            QVERIFY(numericL2(c, o) > r->error);

        // The double version agrees with the exact one.
        const auto rd = reduceDegree(c);
        QVERIFY(rd.ok() && !rd->exact);
        for (int i = 0; i < 3; ++i)
            QVERIFY(distance(rd->points[std::size_t(i)], q[std::size_t(i)]) < 1e-14);
        QVERIFY(std::abs(rd->error - r->error) < 1e-14);
    }

    // Degree 1 → 0: the constant closest in L² is the mean of c, (P_0 + P_1)/2.
    void lineToPoint()
    {
        std::vector<RPoint> p{RPoint(Rational(0), Rational(2)), RPoint(Rational(4), Rational(0))};
        const auto r = reduceDegree(p);
        QVERIFY(r.ok());
        QCOMPARE(r->points.size(), std::size_t(1));
        QCOMPARE(r->points[0], RPoint(Rational(2), Rational(1)));
        // ∫|c − mean|² = |P_1 − P_0|²/12 = 20/12.
        QVERIFY(std::abs(r->error - std::sqrt(20.0 / 12)) < 1e-15);
    }

    // Degree 0: nothing to reduce, an error, not a crash; too high or non-finite for doubles.
    void refusals()
    {
        const auto r = reduceDegree(std::vector<RPoint>{RPoint(Rational(1), Rational(2))});
        QVERIFY(!r.ok());
        QCOMPARE(r.error().code, ErrorCode::TooFewPoints);
        QVERIFY(!reduceDegree(std::vector<Point>{{1, 2}}).ok());
        QVERIFY(!reduceDegree(std::vector<Point>{{0, 0}, {NAN, 1}}).ok());
        QVERIFY(!reduceDegree(std::vector<Point>(42, Point(1, 1))).ok());
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestDegreeReduction)
#include "test_degree_reduction.moc"
