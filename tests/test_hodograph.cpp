// The hodograph c′ as a Bézier curve of degree n − 1 (and c″ by applying it twice), exact for
// rational points: checked against the derivative of the power-basis form of the same curve.
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bezier/hodograph.h"
#include "core/curves/bezier/power_basis.h"
#include "core/exact/rational.h"
#include "rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <random>

using namespace granota;
using granota::testing::pts;
using RPoly = Polynomial<Rational>;

namespace {

Vec2<RPoly> derivative(const Vec2<RPoly>& c) { return Vec2<RPoly>(c.x.derivative(), c.y.derivative()); }

} // namespace

class TestHodograph : public QObject {
    Q_OBJECT
private slots:
    // Ex 2.2's quartic: c(t) = (2 − 12t − 6t² + 52t³ − 43t⁴, …). Its hodograph, rewritten in
    // powers of t, must be exactly c′(t) = (−12 − 12t + 156t² − 172t³, …), and twice c″.
    void thesisExample22()
    {
        const auto p = pts({{2, 3}, {-1, 8}, {-5, -3}, {3, 0}, {-7, -2}});
        const auto c = bezierToPowerBasis(p);
        QCOMPARE(c.x, RPoly({2, -12, -6, 52, -43})); // the thesis's x(t), Ex 2.2
        const auto d = hodograph(p);
        QCOMPARE(d.size(), std::size_t(4));
        // 4 (P_1 − P_0) = 4 (−3, 5)
        QCOMPARE(d[0], RPoint(Rational(-12), Rational(20)));
        const auto dc = bezierToPowerBasis(d);
        QCOMPARE(dc.x, RPoly({-12, -12, 156, -172}));
        QCOMPARE(dc.x, derivative(c).x);
        QCOMPARE(dc.y, derivative(c).y);
        const auto dd = hodograph(d);
        QCOMPARE(dd.size(), std::size_t(3));
        const auto ddc = bezierToPowerBasis(dd);
        QCOMPARE(ddc.x, derivative(derivative(c)).x);
        QCOMPARE(ddc.y, derivative(derivative(c)).y);
    }

    // Random rational curves of several degrees: the power form of the hodograph is the
    // derivative of the power form, and at a rational t it agrees with De Casteljau's tangent.
    void randomRationalCurves()
    {
        std::mt19937 rng(15);
        std::uniform_int_distribution<int> num(-50, 50), den(1, 9);
        for (int n = 1; n <= 9; ++n) {
            std::vector<RPoint> p;
            for (int i = 0; i <= n; ++i)
                p.emplace_back(frac(num(rng), den(rng)), frac(num(rng), den(rng)));
            const auto d = hodograph(p);
            QCOMPARE(int(d.size()), n);
            QCOMPARE(bezierToPowerBasis(d).x, derivative(bezierToPowerBasis(p)).x);
            QCOMPARE(bezierToPowerBasis(d).y, derivative(bezierToPowerBasis(p)).y);
            const Rational t = frac(2, 7);
            QCOMPARE(deCasteljauPoint(d, t), deCasteljau(p, t).tangent());
        }
    }

    // Degree 0: c′ ≡ 0, given as the single point (0,0), and a line's c″ is (0,0) too.
    void degenerate()
    {
        const auto single = hodograph(pts({{3, 4}}));
        QCOMPARE(single.size(), std::size_t(1));
        QCOMPARE(single[0], RPoint(Rational(0), Rational(0)));
        const auto line = hodograph(pts({{0, 0}, {2, 1}}));
        QCOMPARE(line, pts({{2, 1}}));
        QCOMPARE(hodograph(line), pts({{0, 0}}));
        const std::vector<Point> dp = hodograph(std::vector<Point>{{0, 0}, {0, 1}, {1, 1}, {1, 0}});
        QCOMPARE(dp[1].x, 3.0); // 3 (P_2 − P_1) = (3, 0)
        QCOMPARE(dp[1].y, 0.0);
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestHodograph)
#include "test_hodograph.moc"
