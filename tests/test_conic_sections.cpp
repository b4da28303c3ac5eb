// Conic sections and circles as rational curves (conic_section.h, circle_arcs.h): an ellipse,
// a parabola and a hyperbola whose implicit equations are derived by hand in the comments,
// the kind by the middle weight against the discriminant, the circle's arcs and its NURBS,
// and the cubic Bézier quarter circle's radial error against its closed form.
#include "core/curves/bezier/rational_bezier.h"
#include "core/curves/bsplines/circle_arcs.h"
#include "core/curves/bsplines/conic_section.h"
#include "core/curves/bsplines/de_boor.h"
#include "rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <random>

using namespace granota;
using granota::testing::randomRational;

namespace {

RPoint rp(const Rational& x, const Rational& y) { return RPoint(x, y); }

/// t = j/m for j = 0..m, several m.
std::vector<Rational> rationalParameters()
{
    std::vector<Rational> out;
    for (int m : {1, 2, 3, 5, 8, 11})
        for (int j = 0; j <= m; ++j)
            out.push_back(frac(j, m));
    return out;
}

RPoint conicPoint(const ConicSection<Rational>& c, const Rational& t)
{
    return rationalBezierPoint(c.controlPoints(), c.weights(), t);
}

} // namespace

class TestConicSections : public QObject {
    Q_OBJECT
private slots:
    // P_0 = (1,0), P_1 = (1,1), P_2 = (0,1): a point τ_0 P_0 + τ_1 P_1 + τ_2 P_2 has x = τ_0 + τ_1,
    // y = τ_1 + τ_2, so τ_0 = 1 − y, τ_1 = x + y − 1, τ_2 = 1 − x, and τ_1² = 4w² τ_0 τ_2 reads
    // (x + y − 1)² = 4w² (1 − x)(1 − y). Expanded by hand:
    //   w = 1/2: x² + xy + y² − x − y = 0            (B² − 4AC = 1 − 4 = −3: an ellipse)
    //   w = 1:   x² − 2xy + y² + 2x + 2y − 3 = 0     (4 − 4 = 0: a parabola)
    //   w = 2:   x² − 14xy + y² + 14x + 14y − 15 = 0 (196 − 4 = 192: a hyperbola)
    void equationsOnTheUnitTriangle_data()
    {
        QTest::addColumn<QString>("weight");
        QTest::addColumn<QList<int>>("coefficients"); // A, B, C, D, E, F
        QTest::addColumn<int>("kind");
        QTest::newRow("ellipse") << "1/2" << QList<int>{1, 1, 1, -1, -1, 0} << int(ConicKind::Ellipse);
        QTest::newRow("parabola") << "1" << QList<int>{1, -2, 1, 2, 2, -3} << int(ConicKind::Parabola);
        QTest::newRow("hyperbola") << "2" << QList<int>{1, -14, 1, 14, 14, -15} << int(ConicKind::Hyperbola);
    }
    void equationsOnTheUnitTriangle()
    {
        QFETCH(QString, weight);
        QFETCH(QList<int>, coefficients);
        QFETCH(int, kind);
        ConicSection<Rational> c{{rp(1, 0), rp(1, 1), rp(0, 1)}, *parseRational(weight.toStdString())};
        QCOMPARE(int(c.kind()), kind);
        const ImplicitConic<Rational> hand{coefficients[0], coefficients[1], coefficients[2],
                                           coefficients[3], coefficients[4], coefficients[5]};
        for (const Rational& t : rationalParameters())
            QCOMPARE(hand(conicPoint(c, t)), Rational(0));
        // implicitEquation() is the same conic: a multiple of the hand-made coefficients.
        const ImplicitConic<Rational> q = c.implicitEquation();
        const Rational s = q.a / hand.a;
        QCOMPARE(q.b, Rational(s * hand.b));
        QCOMPARE(q.c, Rational(s * hand.c));
        QCOMPARE(q.d, Rational(s * hand.d));
        QCOMPARE(q.e, Rational(s * hand.e));
        QCOMPARE(q.f, Rational(s * hand.f));
    }

    // Random triangles and weights: every point of the arc is on implicitEquation() exactly,
    // and the kind by the weight agrees with the sign of the discriminant B² − 4AC.
    void randomConicsOnTheirEquation()
    {
        std::mt19937 rng(36);
        std::uniform_int_distribution<int> num(1, 12), den(1, 6);
        int kinds[3] = {0, 0, 0};
        for (int trial = 0; trial < 60; ++trial) {
            const std::vector<RPoint> P = randomRational(rng, 2);
            ConicSection<Rational> c{{P[0], P[1], P[2]}, frac(num(rng), den(rng))};
            if (c.kind() == ConicKind::Degenerate)
                continue;
            const ImplicitConic<Rational> q = c.implicitEquation();
            for (const Rational& t : rationalParameters())
                QCOMPARE(q(conicPoint(c, t)), Rational(0));
            const int sign = sgn(q.discriminant());
            const ConicKind expected = sign < 0 ? ConicKind::Ellipse : sign == 0 ? ConicKind::Parabola : ConicKind::Hyperbola;
            QCOMPARE(int(c.kind()), int(expected));
            ++kinds[int(expected)];
        }
        QVERIFY(kinds[0] > 0 && kinds[2] > 0); // both sides of w = 1 were tried
        ConicSection<Rational> flat{{rp(0, 0), rp(1, 1), rp(3, 3)}, Rational(1, 2)};
        QCOMPARE(int(flat.kind()), int(ConicKind::Degenerate));
    }

    // The parabola y = x² from (−1, 1) to (1, 1): its tangents there, y = −2x − 1 and y = 2x − 1,
    // meet at (0, −1); with w = 1, x = 2t − 1 and y = (1−t)² − 2t(1−t) + t² = (2t − 1)².
    void parabola()
    {
        ConicSection<Rational> c{{rp(-1, 1), rp(0, -1), rp(1, 1)}, Rational(1)};
        QCOMPARE(int(c.kind()), int(ConicKind::Parabola));
        for (const Rational& t : rationalParameters()) {
            const RPoint p = conicPoint(c, t);
            QCOMPARE(p.y, Rational(p.x * p.x));
            QCOMPARE(p.x, Rational(2 * t - 1));
        }
    }

    // The hyperbola xy = 1 from (1/2, 2) to (2, 1/2): the tangents y = −4x + 4 and y = −x/4 + 1
    // (slope −1/a² at (a, 1/a)) meet at (4/5, 4/5). Its weight from a third point, (1, 1): by
    // the symmetry x ↔ y, τ_0 = τ_2, and (1, 1) = τ_0 (5/2, 5/2) + τ_1 (4/5, 4/5) with
    // 2τ_0 + τ_1 = 1 gives τ_0 = 2/9, τ_1 = 5/9, so w² = τ_1²/(4 τ_0 τ_2) = 25/16, w = 5/4 > 1.
    void hyperbola()
    {
        ConicSection<Rational> c{{rp(Rational(1, 2), 2), rp(Rational(4, 5), Rational(4, 5)), rp(2, Rational(1, 2))},
                                 Rational(5, 4)};
        QCOMPARE(int(c.kind()), int(ConicKind::Hyperbola));
        for (const Rational& t : rationalParameters()) {
            const RPoint p = conicPoint(c, t);
            QCOMPARE(Rational(p.x * p.y), Rational(1));
        }
        QVERIFY(conicPoint(c, Rational(1, 2)) == rp(1, 1)); // the shoulder, by the symmetry
    }

    // The ellipse x²/4 + y² = 1 is the unit circle stretched by 2 in x; rational Bézier curves
    // are affinely invariant (the weights do not change), so the quarter from (2, 0) to (0, 1)
    // has the corner (2, 1) and w = √2/2, like the circle's.
    void ellipse()
    {
        const std::vector<Point> P{Point(2, 0), Point(2, 1), Point(0, 1)};
        const std::vector<double> w{1, std::sqrt(2.0) / 2, 1};
        for (int j = 0; j <= 200; ++j) {
            const Point p = rationalBezierPoint(P, w, j / 200.0);
            QVERIFY(std::abs(p.x * p.x / 4 + p.y * p.y - 1) <= 2e-15); // a few units in the last place
        }
        ConicSection<double> c{{P[0], P[1], P[2]}, w[1]};
        QCOMPARE(int(c.kind()), int(ConicKind::Ellipse));
        QVERIFY(c.implicitEquation().discriminant() < 0);
    }

    // Arcs of the circle (centre (3, −2), radius 5): every point at distance 5 from the centre;
    // the ends at the angles asked; a sweep of 270° in three pieces.
    void circleArcsOnTheCircle()
    {
        const Point centre(3, -2);
        const double r = 5, pi = std::acos(-1.0);
        for (double sweep : {pi / 6, pi / 2, -pi / 3}) {
            const auto s = circleArc(centre, r, 0.4, sweep);
            QVERIFY(std::abs(s.weights[1] - std::cos(sweep / 2)) <= 1e-16);
            for (int j = 0; j <= 100; ++j)
                QVERIFY(std::abs(distance(rationalBezierPoint(s.points, s.weights, j / 100.0), centre) - r) <= 4e-15);
            const Point end = s.points.back();
            QVERIFY(distance(end, Point(centre.x + r * std::cos(0.4 + sweep), centre.y + r * std::sin(0.4 + sweep))) <= 1e-14);
            // The length of the arc is r·|θ| (rational_bezier.h's arc length).
            QVERIFY(std::abs(rationalArcLength(s.points, s.weights) - r * std::abs(sweep)) <= 1e-13 * r);
        }
        const auto pieces = circleArcs(centre, r, 0, 1.5 * pi);
        QCOMPARE(pieces.size(), std::size_t(3));
        for (std::size_t i = 0; i + 1 < pieces.size(); ++i)
            QVERIFY(distance(pieces[i].points.back(), pieces[i + 1].points.front()) <= 1e-14);
        QVERIFY(distance(pieces.back().points.back(), Point(3, -7)) <= 1e-14); // at 270°: (3, −2 − 5)
    }

    // The full circle as a NURBS: a valid B-spline, on the circle everywhere (de Boor), through
    // (r, 0), (0, r), (−r, 0), (0, −r) (shifted by the centre) at u = 0, 1/4, 1/2, 3/4, and of
    // length 2πr (its four Bézier pieces, each a quarter).
    void fullCircleNurbs()
    {
        const Point centre(1, 1);
        const double r = 2, pi = std::acos(-1.0);
        const BSplineCurve<double> c = fullCircle(centre, r);
        QVERIFY(checkBSpline(c).ok());
        QCOMPARE(c.points.size(), std::size_t(9));
        for (int j = 0; j <= 400; ++j)
            QVERIFY(std::abs(distance(bsplinePoint(c, j / 400.0), centre) - r) <= 4e-15 * r);
        const Point expected[] = {Point(3, 1), Point(1, 3), Point(-1, 1), Point(1, -1), Point(3, 1)};
        for (int q = 0; q <= 4; ++q)
            QVERIFY(distance(bsplinePoint(c, q / 4.0), expected[q]) <= 1e-15);
        double length = 0;
        for (const auto& s : toBezierSegments(c))
            length += rationalArcLength(s.points, s.weights);
        QVERIFY(std::abs(length - 2 * pi * r) <= 1e-13 * r);
    }

    // The cubic (1,0), (1,k), (k,1), (0,1). f(t) = |c(t)|² − 1 is a polynomial of degree 6 with
    // double roots at t = 0 (c(0) = (1,0) on the circle, c′(0) = (0, 3k) tangent to it), at 1
    // (by symmetry) and, for k = 4(√2−1)/3, at 1/2 (c(1/2) = ((4 + 3k)/8)(1, 1) is on the circle
    // exactly for that k, and f′(1/2) = 0 by the symmetry t ↔ 1 − t). So f = C t²(1−t)²(2t−1)²,
    // with C from the t⁶ coefficients: x's t³ coefficient is 2 − 3k, y's 3k − 2, so
    // 2(2 − 3k)² = 4C, C = (2 − 3k)²/2. |t(1−t)(1−2t)| is largest on [0, 1/2] where its
    // derivative 6t² − 6t + 1 vanishes, t = (3 − √3)/6, where t(1−t) = 1/6 and (1 − 2t)² = 1/3:
    // f_max = C · (1/36) · (1/3) = C/108 = (2 − 3k)²/216. The
    // largest radial error is √(1 + (2 − 3k)²/216) − 1 ≈ 2.7253e-4 (Mortensen, "Approximate a
    // circle with cubic Bézier curves", 2012: 0.027253 %; Goldapp, CAGD 8 (1991)).
    void cubicQuarterCircleError()
    {
        const double k = cubicCircleHandle();
        QVERIFY(std::abs(k - 0.5522847498307936) <= 1e-16);
        const CubicCircleError e = cubicCircleRadialError(k);
        const double closedForm = std::sqrt(1 + (2 - 3 * k) * (2 - 3 * k) / 216) - 1;
        QVERIFY2(std::abs(e.maxError - closedForm) <= 1e-12 * closedForm,
                 qPrintable(QString("%1 against %2").arg(e.maxError, 0, 'g', 17).arg(closedForm, 0, 'g', 17)));
        QVERIFY(std::abs(e.maxError - 2.7253e-4) <= 1e-8);
        QVERIFY(std::abs(e.maxT - (3 - std::sqrt(3.0)) / 6) <= 1e-7);
        QVERIFY(e.minError >= -1e-15); // the cubic never goes inside the circle
        // No sample of a dense search beats the roots' answer.
        const auto P = cubicQuarterCircle(k);
        for (int j = 0; j <= 10000; ++j) {
            const double t = j / 10000.0, u = 1 - t;
            const Point c(u * u * u * P[0].x + 3 * u * u * t * P[1].x + 3 * u * t * t * P[2].x + t * t * t * P[3].x,
                          u * u * u * P[0].y + 3 * u * u * t * P[1].y + 3 * u * t * t * P[2].y + t * t * t * P[3].y);
            QVERIFY(norm(c) - 1 <= e.maxError + 1e-15);
        }
        // Another handle, k = 0.55: the curve dips inside the circle near t = 1/2 (c(1/2) =
        // ((4 + 1.65)/8)(1, 1), |c(1/2)| = 5.65√2/8 < 1).
        const CubicCircleError inside = cubicCircleRadialError(0.55);
        QVERIFY(inside.minError <= 5.65 * std::sqrt(2.0) / 8 - 1 + 1e-15);
        QVERIFY(inside.minError < 0);
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestConicSections)
#include "test_conic_sections.moc"
