// Signed curvature, the unit normal and the osculating circle of a Bézier curve, with the
// undefined cases (c′ = 0) explicit and an exact form for rational input.
#include "core/curves/bezier/curvature.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <random>

using namespace granota;

namespace {

std::vector<RPoint> rpts(std::initializer_list<std::pair<int, int>> list)
{
    std::vector<RPoint> out;
    for (auto [x, y] : list)
        out.emplace_back(Rational(x), Rational(y));
    return out;
}

/// The usual cubic approximation of the quarter circle of radius r centred at the origin,
/// from (r,0) to (0,r): inner control points at distance k r, k = 4(√2 − 1)/3.
std::vector<Point> quarterCircle(double r)
{
    const double k = 4.0 * (std::sqrt(2.0) - 1.0) / 3.0;
    return {{r, 0}, {r, k * r}, {k * r, r}, {0, r}};
}

} // namespace

class TestCurvature : public QObject {
    Q_OBJECT
private slots:
    // (0,0),(0,1),(1,1),(1,0) at t = 0: c′ = (0,3), c″ = (6,−6), κ = −18/27 = −2/3 (turning right),
    // normal (−1,0), radius 3/2, centre (0,0) + (−1,0)·(−3/2) = (3/2, 0).
    void knownValueAtStart()
    {
        const std::vector<Point> p{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
        const CurvatureAt k = curvatureAt(p, 0.0);
        QVERIFY(k.curvature);
        QCOMPARE(*k.curvature, -2.0 / 3.0);
        QCOMPARE(k.tangent.x, 0.0);
        QCOMPARE(k.tangent.y, 3.0);
        QVERIFY(k.normal);
        QCOMPARE(k.normal->x, -1.0);
        QCOMPARE(k.normal->y, 0.0);
        QVERIFY(k.radius && k.center);
        QCOMPARE(*k.radius, 1.5);
        QCOMPARE(k.center->x, 1.5);
        QVERIFY(std::abs(k.center->y) < 1e-15);
        // Symmetric curve: κ(1) = κ(0), and at t = 1/2 the tangent is (3/2·…, 0) turning right.
        QCOMPARE(*curvatureAt(p, 1.0).curvature, -2.0 / 3.0);
        QVERIFY(*curvatureAt(p, 0.5).curvature < 0);

        const ExactCurvature e = exactCurvatureAt(rpts({{0, 0}, {0, 1}, {1, 1}, {1, 0}}), Rational(0));
        QCOMPARE(e.numerator, Rational(-18));
        QCOMPARE(e.speedSquared, Rational(9));
        QCOMPARE(*exactCurvatureText(e), std::string("-2/3"));
    }

    // (0,0),(1,1),(2,0) at 0: c′ = (2,2), c″ = (0,−4), κ = −8/(8·2√2) = −√2/4: not rational.
    void exactIrrationalText()
    {
        const ExactCurvature e = exactCurvatureAt(rpts({{0, 0}, {1, 1}, {2, 0}}), Rational(0));
        QCOMPARE(*exactCurvatureText(e), std::string("-√2/4"));
        QCOMPARE(*curvatureAt({{0, 0}, {1, 1}, {2, 0}}, 0.0).curvature, -std::sqrt(2.0) / 4.0);
        // Reversed, the curve turns left: the sign flips.
        QCOMPARE(*exactCurvatureText(exactCurvatureAt(rpts({{2, 0}, {1, 1}, {0, 0}}), Rational(0))), std::string("√2/4"));
    }

    // The exact form and the double one agree on random rational curves and parameters.
    void exactAgreesWithDouble()
    {
        std::mt19937 rng(7);
        std::uniform_int_distribution<int> c(-20, 20);
        for (int trial = 0; trial < 200; ++trial) {
            const int n = 2 + trial % 6;
            std::vector<RPoint> rp;
            for (int i = 0; i <= n; ++i)
                rp.emplace_back(Rational(c(rng)), Rational(c(rng)));
            const Rational t = frac(trial % 17, 16);
            const ExactCurvature e = exactCurvatureAt(rp, t);
            const CurvatureAt k = curvatureAt(toDouble(rp), toDouble(t));
            if (e.speedSquared == 0) {
                QVERIFY(!k.curvature);
                QVERIFY(!exactCurvatureText(e));
                continue;
            }
            const double expected = toDouble(e.numerator) / std::pow(toDouble(e.speedSquared), 1.5);
            QVERIFY(k.curvature);
            QVERIFY2(std::abs(*k.curvature - expected) <= 1e-12 * std::max(1.0, std::abs(expected)),
                     qPrintable(QString::number(trial)));
        }
    }

    // A circle-like arc: κ ≈ 1/r. At t = 0 the formula gives exactly κ r = 2(1 − k)/(3k²)
    // (κ(0) = (n−1)/n · |ΔP_0 × ΔP_1| / |ΔP_0|³); everywhere the approximation keeps κ r within
    // 3 % of 1, turning left, with the centre near the origin. The same holds scaled by 1e±150,
    // where |c′|³ alone would overflow or underflow.
    void circleLikeArc()
    {
        const double k = 4.0 * (std::sqrt(2.0) - 1.0) / 3.0;
        for (double r : {1.0, 7.5, 1e150, 1e-150}) {
            const auto p = quarterCircle(r);
            const CurvatureAt a = curvatureAt(p, 0.0);
            QVERIFY(a.curvature);
            QVERIFY(std::abs(*a.curvature * r - 2 * (1 - k) / (3 * k * k)) < 1e-14);
            for (int j = 0; j <= 64; ++j) {
                const CurvatureAt c = curvatureAt(p, j / 64.0);
                QVERIFY(c.curvature && c.radius && c.center && c.normal);
                QVERIFY(std::isfinite(*c.curvature) && std::isfinite(*c.radius));
                QVERIFY(*c.curvature > 0);
                QVERIFY(std::abs(*c.curvature * r - 1) < 0.03);
                QVERIFY(std::abs(*c.radius / r - 1) < 0.03);
                QVERIFY(norm(*c.center) < 0.03 * r);
                QVERIFY(std::abs(norm(*c.normal) - 1) < 1e-15);
                QVERIFY(std::abs(dot(*c.normal, c.tangent)) <= 1e-15 * norm(c.tangent));
            }
        }
    }

    // Collinear control points: κ = 0 exactly (also with decimals that do not round exactly),
    // radius and centre infinite (nullopt), the normal still defined.
    void straight()
    {
        for (const std::vector<Point>& p :
             {std::vector<Point>{{0, 0}, {1, 1}, {3, 3}, {4, 4}},
              std::vector<Point>{{0.1, 0.2}, {0.3, 0.6}, {0.7, 1.4}, {0.2, 0.4}}, std::vector<Point>{{0, 0}, {1, 0}}}) {
            for (double t : {0.0, 0.3, 0.5, 1.0}) {
                const CurvatureAt c = curvatureAt(p, t);
                QVERIFY(c.curvature);
                QCOMPARE(*c.curvature, 0.0);
                QVERIFY(!c.radius);
                QVERIFY(!c.center);
                QVERIFY(c.normal);
            }
        }
    }

    // The cusp of (0,0),(1,1),(0,1),(1,0) at t = 1/2 (c′(1/2) = 0): undefined, not 0, not NaN.
    // Next to it κ is large but finite.
    void cusp()
    {
        const std::vector<Point> p{{0, 0}, {1, 1}, {0, 1}, {1, 0}};
        const CurvatureAt c = curvatureAt(p, 0.5);
        QVERIFY(!c.curvature);
        QVERIFY(!c.normal);
        QVERIFY(!c.radius);
        QVERIFY(!c.center);
        QCOMPARE(c.tangent.x, 0.0);
        QCOMPARE(c.tangent.y, 0.0);
        const ExactCurvature e = exactCurvatureAt(rpts({{0, 0}, {1, 1}, {0, 1}, {1, 0}}), frac(1, 2));
        QCOMPARE(e.speedSquared, Rational(0));
        QVERIFY(!exactCurvatureText(e));
        const CurvatureAt near = curvatureAt(p, 0.5 + 1e-6);
        QVERIFY(near.curvature && std::isfinite(*near.curvature));
        QVERIFY(std::abs(*near.curvature) > 1e3);
    }

    // Control points near ±1e308 whose c′(1/2) is small: (−1e308, 0), (1e308, 1e308),
    // (0, 1e308), (7, 0). c′(1/2) = 3/4 (P_3 + P_2 − P_1 − P_0) = (21/4, 0) exactly (the big
    // terms cancel), but a double rounds it by about 1e292: the floating test called it a
    // cusp (κ undefined). The expected values are the Rational ones of exactCurvatureAt:
    // |c′|³ = (21/4)³ since c′ is (21/4, 0), so κ = (x′y″ − y′x″)/(21/4)³.
    void smallTangentAmongHugePoints()
    {
        const std::vector<Point> p{{-1e308, 0}, {1e308, 1e308}, {0, 1e308}, {7, 0}};
        const Rational half = frac(1, 2);
        const ExactCurvature e = exactCurvatureAt(toRational(p), half);
        QCOMPARE(e.speedSquared, Rational(frac(21, 4) * frac(21, 4)));
        const Rational cubed = frac(21, 4) * frac(21, 4) * frac(21, 4);
        const double kappa = toDouble(Rational(e.numerator / cubed));
        QVERIFY(kappa < -1e307 && std::isfinite(kappa)); // −6e308 · 16/441 ≈ −2.2e307
        const CurvatureAt c = curvatureAt(p, 0.5);
        QCOMPARE(c.tangent.x, 5.25);
        QCOMPARE(c.tangent.y, 0.0);
        QVERIFY(c.exact);
        QVERIFY(!curvatureAt(p, 0.25).exact); // where the doubles tell, they answer
        QVERIFY(c.curvature);
        QVERIFY2(std::fabs(*c.curvature - kappa) <= 1e-14 * std::fabs(kappa), qPrintable(QString::number(*c.curvature)));
        QVERIFY(c.normal);
        QCOMPARE(c.normal->x, 0.0); // left of (21/4, 0): (0, 1)
        QCOMPARE(c.normal->y, 1.0);
        QVERIFY(c.radius && *c.radius > 0 && std::isfinite(*c.radius));
        // An exact zero stays a cusp: the curve of cusp() scaled to the same size.
        const std::vector<Point> q{{0, 0}, {1e308, 1e308}, {0, 1e308}, {1e308, 0}};
        QVERIFY(!curvatureAt(q, 0.5).curvature);
    }

    // Coincident end control points: c′(0) = 0 (κ undefined there), defined inside.
    // A single repeated point: nothing is defined.
    void coincidentPoints()
    {
        const std::vector<Point> p{{0, 0}, {0, 0}, {1, 1}, {2, 0}};
        QVERIFY(!curvatureAt(p, 0.0).curvature);
        QVERIFY(curvatureAt(p, 0.5).curvature);
        QVERIFY(curvatureAt(p, 1.0).curvature);
        for (const std::vector<Point>& q : {std::vector<Point>{{3, 4}}, std::vector<Point>{{3, 4}, {3, 4}, {3, 4}}}) {
            const CurvatureAt c = curvatureAt(q, 0.25);
            QVERIFY(!c.curvature && !c.normal && !c.radius && !c.center);
            QCOMPARE(c.point.x, 3.0);
            QCOMPARE(c.point.y, 4.0);
        }
    }

    // Huge and tiny curves: the same shape gives κ scaled by exactly 1/scale, and nothing
    // non-finite anywhere (also at degree 30 with coordinates near 1e300).
    void scaleInvariance()
    {
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> u(-1, 1);
        std::vector<Point> p;
        for (int i = 0; i <= 30; ++i)
            p.emplace_back(u(rng), u(rng));
        for (double s : {1e300, 1e-300, 0x1p-1070}) {
            std::vector<Point> q;
            for (const Point& a : p)
                q.emplace_back(a.x * s, a.y * s);
            for (int j = 0; j <= 20; ++j) {
                const CurvatureAt c = curvatureAt(q, j / 20.0);
                QVERIFY(isFinite(c.point) && isFinite(c.tangent));
                if (c.curvature)
                    QVERIFY(std::isfinite(*c.curvature));
                if (c.radius)
                    QVERIFY(std::isfinite(*c.radius) && c.center && isFinite(*c.center));
            }
        }
        for (double s : {0x1p400, 0x1p-400}) { // powers of two: the scaled curve is exact
            std::vector<Point> q;
            for (const Point& a : p)
                q.emplace_back(a.x * s, a.y * s);
            const CurvatureAt c1 = curvatureAt(p, 0.3), c2 = curvatureAt(q, 0.3);
            QVERIFY(c1.curvature && c2.curvature);
            QCOMPARE(*c2.curvature * s, *c1.curvature);
        }
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestCurvature)
#include "test_curvature.moc"
