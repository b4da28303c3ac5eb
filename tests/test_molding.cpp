// Molding: c(t) moves to the target exactly (Rational) by the minimum-norm change of the
// control points.
#include "core/curves/bezier/bernstein.h"
#include "core/curves/bezier/molding.h"
#include "rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <random>

using namespace granota;
using granota::testing::randomRational;

namespace {

Rational squaredChange(const std::vector<RPoint>& a, const std::vector<RPoint>& b)
{
    Rational s(0);
    for (std::size_t i = 0; i < a.size(); ++i) {
        const RPoint d = b[i] - a[i];
        s += d.x * d.x + d.y * d.y;
    }
    return s;
}

} // namespace

class TestMolding : public QObject {
    Q_OBJECT
private slots:
    // After molding, c(t) is the target exactly, for every degree and rational t in [0, 1].
    void reachesTargetExactly()
    {
        std::mt19937 rng(5);
        for (int n = 0; n <= 10; ++n)
            for (const Rational& t : {Rational(0), frac(1, 3), frac(1, 2), frac(5, 7), Rational(1)}) {
                const auto p = randomRational(rng, n);
                const RPoint target(frac(3, 2), frac(-7, 5));
                const auto q = moldCurve(p, t, target);
                QCOMPARE(q.size(), p.size());
                QCOMPARE(bezierBernstein(q, t), target);
            }
    }

    // Minimum norm: moving only the control point with the largest B_i^n(t) (the nearest one)
    // by Δ/B_i^n(t) also meets the constraint but costs more, and so does the minimum-norm
    // change plus any ΔP in the constraint's null space (Σ B_i ΔP_i = 0).
    void minimumNorm()
    {
        std::mt19937 rng(9);
        for (int n = 1; n <= 8; ++n) {
            const auto p = randomRational(rng, n);
            const Rational t = frac(2, 5);
            const RPoint target(Rational(4), Rational(1));
            const auto q = moldCurve(p, t, target);
            const Rational best = squaredChange(p, q);

            const auto b = bernsteinAll(n, t);
            std::size_t k = 0;
            for (std::size_t i = 1; i < b.size(); ++i)
                if (b[i] > b[k])
                    k = i;
            auto one = p;
            const RPoint delta = target - bezierBernstein(p, t);
            one[k] += Rational(1 / b[k]) * delta;
            QCOMPARE(bezierBernstein(one, t), target);
            QVERIFY(squaredChange(p, one) > best);

            // A null-space direction: move P_0 by B_1 e and P_1 by −B_0 e.
            auto other = q;
            const RPoint e(Rational(1), frac(-1, 3));
            other[0] += b[1] * e;
            other[1] += Rational(-b[0]) * e;
            QCOMPARE(bezierBernstein(other, t), target);
            QVERIFY(squaredChange(p, other) > best);
        }
    }

    // At the ends only the end control point moves (B_0^n(0) = 1, the others 0); doubles
    // reach the target to rounding.
    void endsAndDoubles()
    {
        const std::vector<Point> p{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
        const auto q = moldCurve(p, 0.0, Point(0.5, -0.5));
        QCOMPARE(q[0].x, 0.5);
        QCOMPARE(q[0].y, -0.5);
        for (std::size_t i = 1; i < 4; ++i)
            QVERIFY(q[i] == p[i]);
        const auto r = moldCurve(p, 0.3, Point(2.0, 3.0));
        const Point c = bezierBernstein(r, 0.3);
        QVERIFY(std::abs(c.x - 2) < 1e-14 && std::abs(c.y - 3) < 1e-14);
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestMolding)
#include "test_molding.moc"
