// Rational Bézier curves (rational_bezier.h): weights 1 give the polynomial curve exactly, the
// weights (1, 1, 2) give the unit circle's rational points, the quarter circle with weights
// (1, √2/2, 1) has length π/2 and radius 1, the derivatives against closed forms, the
// subdivision, and the faults checkRationalBezier names.
#include "core/curves/bezier/arc_length.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bezier/rational_bezier.h"
#include "rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <random>

using namespace granota;
using granota::testing::pts;
using granota::testing::randomRational;

namespace {

const double kHalfSqrt2 = std::sqrt(2.0) / 2;

/// The quarter circle of radius 1 from (1, 0) to (0, 1) in standard form: the middle point is
/// the corner where the end tangents meet, and its weight cos(45°) = √2/2 (Farin, §13.5).
std::vector<Point> quarterPoints() { return {Point(1, 0), Point(1, 1), Point(0, 1)}; }
std::vector<double> quarterWeights() { return {1, kHalfSqrt2, 1}; }

/// t = j/m for j = 0..m, several m: rational parameters of varied denominators.
std::vector<Rational> rationalParameters()
{
    std::vector<Rational> out;
    for (int m : {1, 2, 3, 7, 10, 13})
        for (int j = 0; j <= m; ++j)
            out.push_back(frac(j, m));
    return out;
}

} // namespace

class TestRationalBezier : public QObject {
    Q_OBJECT
private slots:
    // With every weight 1 the recurrence divides by w_i^r = 1 only: every level equals
    // Def 2.4's, exactly, and so does the tangent.
    void unitWeightsArePolynomial()
    {
        std::mt19937 rng(36);
        for (int n = 0; n <= 8; ++n) {
            const std::vector<RPoint> P = randomRational(rng, n);
            const std::vector<Rational> ones(P.size(), Rational(1));
            for (const Rational& t : rationalParameters()) {
                const auto rational = rationalDeCasteljau(P, ones, t);
                const auto polynomial = deCasteljau(P, t);
                QCOMPARE(rational.levels.size(), polynomial.levels.size());
                for (std::size_t r = 0; r < polynomial.levels.size(); ++r) {
                    QVERIFY(rational.levels[r] == polynomial.levels[r]);
                    for (const Rational& w : rational.weights[r])
                        QCOMPARE(w, Rational(1));
                }
                QVERIFY(rational.tangent() == polynomial.tangent());
                QVERIFY(rationalBezierPoint(P, ones, t) == polynomial.point());
            }
        }
    }

    // (1,0), (1,1), (0,1) with weights (1, 1, 2):
    //   denominator (1−t)² + 2t(1−t) + 2t² = 1 + t²,
    //   x = ((1−t)² + 2t(1−t)) / (1 + t²) = (1 − t²)/(1 + t²),
    //   y = (2t(1−t) + 2t²) / (1 + t²) = 2t/(1 + t²),
    // the classical rational parametrisation of the unit circle: x² + y² = 1 exactly, and at
    // t = 1/2 the point (3/5, 4/5).
    void weightsOneOneTwoGiveTheCircle()
    {
        const std::vector<RPoint> P = pts({{1, 0}, {1, 1}, {0, 1}});
        const std::vector<Rational> w{1, 1, 2};
        for (const Rational& t : rationalParameters()) {
            const RPoint c = rationalDeCasteljau(P, w, t).point();
            QCOMPARE(Rational(c.x * c.x + c.y * c.y), Rational(1));
            const Rational d = 1 + t * t;
            QCOMPARE(c.x, Rational((1 - t * t) / d));
            QCOMPARE(c.y, Rational(2 * t / d));
            QVERIFY(rationalBezierPoint(P, w, t) == c);
        }
        const RPoint half = rationalDeCasteljau(P, w, Rational(1, 2)).point();
        QCOMPARE(half.x, Rational(3, 5));
        QCOMPARE(half.y, Rational(4, 5));
    }

    // The derivatives of x = (1 − t²)/(1 + t²), y = 2t/(1 + t²) by the quotient rule, by hand:
    //   x′ = −4t/(1+t²)²,            y′ = 2(1 − t²)/(1+t²)²,
    //   x″ = (12t² − 4)/(1+t²)³,     y″ = 4t(t² − 3)/(1+t²)³;
    // and the circle's curvature 1: (x′y″ − y′x″)² = |c′|⁶, x′y″ − y′x″ > 0 (counter-clockwise).
    void derivativesOfTheRationalCircle()
    {
        const std::vector<RPoint> P = pts({{1, 0}, {1, 1}, {0, 1}});
        const std::vector<Rational> w{1, 1, 2};
        for (const Rational& t : rationalParameters()) {
            const Rational d = 1 + t * t;
            const auto D = rationalBezierDerivatives(P, w, t);
            QCOMPARE(D.first.x, Rational(-4 * t / (d * d)));
            QCOMPARE(D.first.y, Rational(2 * (1 - t * t) / (d * d)));
            QCOMPARE(D.second.x, Rational((12 * t * t - 4) / (d * d * d)));
            QCOMPARE(D.second.y, Rational(4 * t * (t * t - 3) / (d * d * d)));
            const ExactCurvature k = exactRationalCurvatureAt(P, w, t);
            QVERIFY(k.numerator > 0);
            QCOMPARE(Rational(k.numerator * k.numerator), Rational(k.speedSquared * k.speedSquared * k.speedSquared));
            QCOMPARE(exactCurvatureText(k).value_or("?"), std::string("1"));
        }
    }

    // The left part's points and weights (the triangle's left edge) draw c on [0, t]:
    // c_left(s) = c(s t), exactly; the right part's, c on [t, 1].
    void subdivision()
    {
        std::mt19937 rng(7);
        std::uniform_int_distribution<int> weight(1, 9);
        for (int n = 1; n <= 5; ++n) {
            const std::vector<RPoint> P = randomRational(rng, n);
            std::vector<Rational> w;
            for (int i = 0; i <= n; ++i)
                w.push_back(frac(weight(rng), weight(rng)));
            const Rational t(2, 7);
            const auto table = rationalDeCasteljau(P, w, t);
            for (const Rational& s : rationalParameters()) {
                QVERIFY(rationalBezierPoint(table.leftPoints(), table.leftWeights(), s) ==
                        rationalBezierPoint(P, w, Rational(s * t)));
                QVERIFY(rationalBezierPoint(table.rightPoints(), table.rightWeights(), s) ==
                        rationalBezierPoint(P, w, Rational(t + s * (1 - t))));
            }
        }
    }

    // |c(t)| = 1 to 1e-15 (a few units in the last place) all along the standard-form quarter
    // circle, and κ = 1 where the derivatives are formed in doubles.
    void quarterCircleRadius()
    {
        const auto P = quarterPoints();
        const auto w = quarterWeights();
        for (int j = 0; j <= 1000; ++j) {
            const double t = j / 1000.0;
            const Point c = rationalBezierPoint(P, w, t);
            QVERIFY2(std::abs(norm(c) - 1) <= 1e-15, qPrintable(QString("t = %1: |c| − 1 = %2").arg(t).arg(norm(c) - 1)));
            const CurvatureAt k = rationalCurvatureAt(P, w, t);
            QVERIFY(k.curvature.has_value());
            QVERIFY2(std::abs(*k.curvature - 1) <= 1e-13, qPrintable(QString::number(*k.curvature - 1)));
            QVERIFY(k.center.has_value() && norm(*k.center) <= 1e-13);
        }
    }

    // The length of the quarter of the unit circle is π/2; of the arc from (1, 0) to c(t) it is
    // the angle atan2(y, x) of c(t) (an independent formula for the same number).
    void quarterCircleLength()
    {
        const auto P = quarterPoints();
        const auto w = quarterWeights();
        const double pi = std::acos(-1.0);
        const double L = rationalArcLength(P, w);
        QVERIFY2(std::abs(L - pi / 2) <= 1e-13, qPrintable(QString::number(L - pi / 2, 'g', 17)));
        for (double t : {0.1, 0.25, 0.5, 0.8, 1.0}) {
            const Point c = rationalBezierPoint(P, w, t);
            QVERIFY(std::abs(rationalArcLength(P, w, 0, t) - std::atan2(c.y, c.x)) <= 1e-13);
        }
        // Scaled by 1e100 and by 1e-100: the same length, scaled (no overflow in |c′|²).
        for (double s : {1e100, 1e-100}) {
            std::vector<Point> Q;
            for (const Point& p : P)
                Q.emplace_back(s * p.x, s * p.y);
            QVERIFY(std::abs(rationalArcLength(Q, w) / s - pi / 2) <= 1e-13);
        }
        // The weights (1, 1, 2) draw the same quarter, at another speed: the same length.
        QVERIFY(std::abs(rationalArcLength(P, {1, 1, 2}) - pi / 2) <= 1e-13);
        // Weights all 1: the polynomial curve, whose length arc_length.h computes another way
        // (the hodograph's Bernstein form): the two agree.
        const std::vector<Point> cubic{Point(0, 0), Point(1, 2), Point(3, -1), Point(4, 1)};
        QVERIFY(std::abs(rationalArcLength(cubic, {1, 1, 1, 1}) - arcLength(cubic)) <= 1e-13 * arcLength(cubic));
    }

    void faults()
    {
        QVERIFY(checkRationalBezier(3, std::vector<double>{1, 2, 3}).ok());
        QVERIFY(!checkRationalBezier(3, std::vector<double>{1, 2}).ok());
        QVERIFY(!checkRationalBezier(3, std::vector<double>{1, 0, 3}).ok());
        QVERIFY(!checkRationalBezier(3, std::vector<double>{1, -1, 3}).ok());
        QVERIFY(!checkRationalBezier(3, std::vector<double>{1, NAN, 3}).ok());
        QVERIFY(!checkRationalBezier(0, std::vector<double>{}).ok());
        QVERIFY(!checkRationalBezier(2, std::vector<Rational>{1, 0}).ok());
        const auto e = checkRationalBezier(3, std::vector<Rational>{1, Rational(-1, 2), 1});
        QVERIFY(!e.ok() && e.error().message.find("weight 2") != std::string::npos);
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestRationalBezier)
#include "test_rational_bezier.moc"
