// The geometry of a polynomial B-spline through its Bézier pieces (issue 36,
// core/curves/bsplines/bspline_analysis.h): one piece gives the Bézier analysis itself; two
// pieces the sum of lengths; extrema and inflections that fall on a knot; curvature against
// the basis derivatives of A2.3; the closest point.
#include "core/curves/bezier/arc_length.h"
#include "core/curves/bezier/closest_point.h"
#include "core/curves/bezier/curvature.h"
#include "core/curves/bezier/curve_features.h"
#include "core/curves/bsplines/bspline_analysis.h"
#include "core/curves/bsplines/bspline_basis.h"
#include "core/curves/bsplines/knot_vector.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>

using namespace granota;

namespace {

BSplineCurve<double> curve(int degree, std::vector<Point> points, std::vector<double> knots)
{
    BSplineCurve<double> c;
    c.degree = degree;
    c.points = std::move(points);
    c.knots = std::move(knots);
    return c;
}

bool near(double a, double b, double tol = 1e-12) { return std::abs(a - b) <= tol * std::max(1.0, std::abs(b)); }

} // namespace

class TestBSplineAnalysis : public QObject {
    Q_OBJECT
private slots:
    // A B-spline on the Bézier knots [0, 1] is one piece, the control points themselves: every
    // answer is the Bézier analysis's, to the bit. On [2, 5] (u = 2 + 3t) the parameters map,
    // c′ is divided by 3, and the geometry stays.
    void oneBezierPiece()
    {
        const std::vector<Point> P = {Point(0, 0), Point(1, 3), Point(3, -2), Point(4, 2), Point(6, 1)};
        const auto c = curve(4, P, presetKnots<double>(KnotPreset::Bezier, 5, 4));
        const BSplineAnalysis a(c);
        QCOMPARE(a.segments().size(), std::size_t(1));
        QVERIFY(a.segments()[0].points == P);
        for (double t : {0.0, 0.25, 0.5, 0.8, 1.0}) {
            const auto k = a.curvatureAt(t), e = curvatureAt(P, t);
            QCOMPARE(k.curvature, e.curvature);
            QCOMPARE(k.point, e.point);
            QCOMPARE(k.tangent, e.tangent);
        }
        QCOMPARE(a.arcLength(), arcLength(P));
        QCOMPARE(a.extremaX(), extremaParameters(P, 0));
        QCOMPARE(a.extremaY(), extremaParameters(P, 1));
        QCOMPARE(a.inflections(), inflectionParameters(P));
        QCOMPARE(a.tightBox().minCorner(), tightBoundingBox(P).minCorner());
        QCOMPARE(a.tightBox().maxCorner(), tightBoundingBox(P).maxCorner());
        const auto cp = a.closestPoint(Point(3, 3)), ce = closestPoint(P, Point(3, 3));
        QCOMPARE(cp.t, ce.t);
        QCOMPARE(cp.distance, ce.distance);

        auto shifted = c;
        shifted.knots = {2, 2, 2, 2, 2, 5, 5, 5, 5, 5};
        const BSplineAnalysis b(shifted);
        const auto k = b.curvatureAt(2.75), e = curvatureAt(P, 0.25); // (2.75 − 2)/3 = 0.25 exactly
        QCOMPARE(k.curvature, e.curvature);
        QCOMPARE(k.t, 2.75);
        QCOMPARE(k.tangent, Point(e.tangent.x / 3, e.tangent.y / 3));
        QCOMPARE(b.arcLength(), arcLength(P));
        const auto ex = extremaParameters(P, 1);
        QCOMPARE(b.extremaY().size(), ex.size());
        for (std::size_t i = 0; i < ex.size(); ++i)
            QVERIFY(near(b.extremaY()[i], 2 + 3 * ex[i]));
    }

    // The quadratic (0,0), (1,2), (3,2), (4,0) on 0 0 0 ½ 1 1 1 is two Bézier pieces,
    // [P0, P1, M] and [M, P2, P3] with M = (P1 + P2)/2 = (2, 2) (Boehm with α = ½, by hand):
    // its length is the sum of theirs. It is symmetric about x = 2, highest at M (u = ½, the
    // knot, where y′ = 0 from both sides): extremaY = {½}, the box [0, 4] × [0, 2], and the
    // point closest to (2, 5) is M at distance 3 (every point has y ≤ 2).
    void twoPieces()
    {
        const std::vector<Point> P = {Point(0, 0), Point(1, 2), Point(3, 2), Point(4, 0)};
        const auto c = curve(2, P, {0, 0, 0, 0.5, 1, 1, 1});
        const BSplineAnalysis a(c);
        QCOMPARE(a.segments().size(), std::size_t(2));
        const Point M(2, 2);
        const std::vector<Point> left = {P[0], P[1], M}, right = {M, P[2], P[3]};
        QVERIFY(a.segments()[0].points == left);
        QVERIFY(a.segments()[1].points == right);
        QVERIFY(near(a.arcLength(), arcLength(left) + arcLength(right)));
        QVERIFY(near(a.arcLength(0.25, 1), arcLength(left, 0.5, 1) + arcLength(right)));
        QVERIFY(near(a.arcLength(1, 0.25), -a.arcLength(0.25, 1)));
        QCOMPARE(a.extremaY(), std::vector<double>{0.5});
        QVERIFY(a.extremaX().empty());
        const Aabb box = a.tightBox();
        QCOMPARE(box.minCorner(), Point(0, 0));
        QCOMPARE(box.maxCorner(), Point(4, 2));
        const auto cp = a.closestPoint(Point(2, 5));
        QCOMPARE(cp.t, 0.5);
        QCOMPARE(cp.point, M);
        QCOMPARE(cp.distance, 3.0);
        QVERIFY(a.inflections().empty());
        QVERIFY(a.cusps().empty());
    }

    // A straight B-spline (collinear, evenly spaced points) is as long as its chord.
    void straight()
    {
        const auto c = curve(3, {Point(0, 0), Point(1, 2), Point(2, 4), Point(3, 6), Point(4, 8), Point(5, 10)},
                             presetKnots<double>(KnotPreset::Clamped, 6, 3));
        const BSplineAnalysis a(c);
        QVERIFY(near(a.arcLength(), std::hypot(5.0, 10.0)));
        QVERIFY(a.inflections().empty());
    }

    // The S curve (0,0), (1,2), (2,0), (3,−2), (4,0), cubic on 0 0 0 0 ½ 1 1 1 1, is symmetric
    // about (2, 0) (the points and the knots are): it turns left, then right, the inflection
    // on the knot u = ½, where c = (2, 0) and κ = 0 (odd under the symmetry).
    void inflectionOnAKnot()
    {
        const auto c = curve(3, {Point(0, 0), Point(1, 2), Point(2, 0), Point(3, -2), Point(4, 0)},
                             {0, 0, 0, 0, 0.5, 1, 1, 1, 1});
        const BSplineAnalysis a(c);
        QCOMPARE(a.inflections(), std::vector<double>{0.5});
        const auto k = a.curvatureAt(0.5);
        QVERIFY(std::abs(k.point.x - 2) < 1e-15 && std::abs(k.point.y) < 1e-15);
        QVERIFY(k.curvature.has_value() && std::abs(*k.curvature) < 1e-12);
        QVERIFY(*a.curvatureAt(0.25).curvature < 0 && *a.curvatureAt(0.75).curvature > 0);
    }

    // Curvature from the pieces against κ = (x′y″ − y′x″)/|c′|³ with c′, c″ from the basis
    // derivatives of A2.3 (bspline_basis.h, checked in test_bspline_de_boor): another road.
    void curvatureAgainstBasisDerivatives()
    {
        const auto c = curve(3, {Point(0, 0), Point(1, 3), Point(3, 4), Point(5, 1), Point(6, 3), Point(8, 0)},
                             {0, 0, 0, 0, 0.3, 0.7, 1, 1, 1, 1});
        const BSplineAnalysis a(c);
        for (double u : {0.0, 0.1, 0.3, 0.45, 0.7, 0.9, 1.0}) {
            const int k = findSpan(c.knots, 3, 6, u);
            const auto d = basisDerivatives(c.knots, 3, k, u, 2);
            Point d1(0, 0), d2(0, 0);
            for (int j = 0; j <= 3; ++j) {
                const Point& P = c.points[static_cast<std::size_t>(k - 3 + j)];
                d1 += d[1][static_cast<std::size_t>(j)] * P;
                d2 += d[2][static_cast<std::size_t>(j)] * P;
            }
            const double kappa = cross(d1, d2) / std::pow(norm(d1), 3);
            const auto got = a.curvatureAt(u);
            QVERIFY(got.curvature.has_value());
            QVERIFY2(near(*got.curvature, kappa, 1e-11), qPrintable(QString::number(u)));
            QVERIFY(near(got.tangent.x, d1.x, 1e-12) && near(got.tangent.y, d1.y, 1e-12));
        }
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestBSplineAnalysis)
#include "test_bspline_analysis.moc"
