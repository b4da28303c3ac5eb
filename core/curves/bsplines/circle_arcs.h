#pragma once
/// \file circle_arcs.h
/// The circle drawn exactly by rational curves, and the usual cubic approximation beside it
/// (beyond the thesis, issue 36):
///  - an arc of angle θ ≤ 90° as one rational quadratic in standard form: ends on the circle,
///    the middle point where the end tangents meet, at distance r / cos(θ/2) from the centre,
///    middle weight cos(θ/2) (Piegl & Tiller, "The NURBS Book", §7.3; Farin,
///    "Curves and Surfaces for CAGD", §13.5); longer arcs as several such pieces;
///  - the quarter circle (1,0), (1,1), (0,1) with the rational weights (1, 1, 2): the same arc
///    in another parametrisation (w_0 w_2 / w_1² = 2 as for (1, √2/2, 1)), whose points at
///    rational t are rational, x = (1 − t²)/(1 + t²), y = 2t/(1 + t²) — exact in Rational;
///  - the full circle as a NURBS of degree 2 with 9 control points (the square's corners and
///    edge midpoints), knots 0,0,0,¼,¼,½,½,¾,¾,1,1,1 and weights 1, √2/2, 1, … (Piegl &
///    Tiller, §7.5);
///  - the cubic Bézier quarter circle (1,0), (1,k), (k,1), (0,1) with k = 4(√2 − 1)/3, which
///    passes through the circle at t = 0, 1/2, 1, and its largest radial error, found from the
///    roots of the derivative of |c(t)|² (bernstein_roots.h), ≈ 2.7e-4 (Goldapp, "Approximation
///    of circular arcs by cubic polynomials", CAGD 8 (1991); in closed form
///    √(1 + (2 − 3k)²/216) − 1 at t = (3 ∓ √3)/6, derived in test_conic_sections).

#include "core/base/vec2.h"
#include "core/curves/bsplines/bezier_extraction.h"
#include "core/curves/bsplines/bspline_curve.h"
#include "core/exact/rational.h"

#include <vector>

namespace granota {

/// The arc of the circle (centre, radius) from angle `start` through `sweep` radians,
/// 0 < |sweep| ≤ π/2, as one rational quadratic in standard form (weights 1, cos(sweep/2), 1).
/// The segment's start and end are 0 and 1.
RationalBezierSegment<double> circleArc(const Point& centre, double radius, double start, double sweep);

/// The same for any 0 < |sweep| ≤ 2π: ⌈|sweep|/(π/2)⌉ equal pieces, each ≤ 90°, joined with
/// the same tangent; piece j covers [j/m, (j + 1)/m].
std::vector<RationalBezierSegment<double>> circleArcs(const Point& centre, double radius, double start, double sweep);

/// The quarter of the unit circle from (1, 0) to (0, 1) with weights (1, 1, 2): exact in S.
template <class S> RationalBezierSegment<S> rationalQuarterCircle()
{
    RationalBezierSegment<S> q;
    q.points = {Vec2<S>(S(1), S(0)), Vec2<S>(S(1), S(1)), Vec2<S>(S(0), S(1))};
    q.weights = {S(1), S(1), S(2)};
    q.start = S(0);
    q.end = S(1);
    return q;
}

/// The full circle (centre, radius) as a NURBS: degree 2, 9 points from (centre.x + r, centre.y)
/// counter-clockwise, the knots and weights of the header.
BSplineCurve<double> fullCircle(const Point& centre, double radius);

/// k = 4(√2 − 1)/3 ≈ 0.5523: the cubic's handle length for a quarter of the unit circle that
/// meets the circle at its middle.
double cubicCircleHandle();

/// (1,0), (1,k), (k,1), (0,1): the cubic Bézier approximation of the unit quarter circle.
std::vector<Point> cubicQuarterCircle(double k);

/// The radial error of the cubic quarter circle with handle k: |c(t)| − 1 at its extremes.
struct CubicCircleError {
    double maxError = 0; ///< the largest |c(t)| − 1 over [0, 1] (≥ 0)
    double maxT = 0;     ///< the first t where it is reached
    double minError = 0; ///< the smallest |c(t)| − 1 (≤ 0; 0 when the curve never goes inside)
};

/// The extremes of |c(t)| − 1 over [0, 1]: |c(t)|² is a polynomial of degree 6, its derivative
/// one of degree 5 in Bernstein form (bernsteinProduct), whose roots in [0, 1]
/// (bernsteinRoots), with t = 0 and 1, are the candidates.
CubicCircleError cubicCircleRadialError(double k);

} // namespace granota
