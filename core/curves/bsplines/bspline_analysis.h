#pragma once
/// \file bspline_analysis.h
/// The geometry of a polynomial B-spline through its Bézier pieces (bezier_extraction.h):
/// each piece is a Bézier curve, and the Bézier analysis of core/curves/bezier/ — curvature
/// (curvature.h), arc length (arc_length.h), extrema, tight box, inflections and cusps
/// (curve_features.h), the closest point (closest_point.h) — runs on it, its parameter
/// t ∈ [0, 1] mapped back to u = start + t (end − start). What happens at the joins (the
/// knots) is decided here: a coordinate's derivative that vanishes or changes sign across a
/// knot is an extremum there, x′y″ − y′x″ changing sign across it an inflection, and a point
/// found at the end of one piece and the start of the next is listed once. Beyond the thesis
/// (issue 36); the pieces answer §2.3's dilemma: many low-degree Bézier curves joined.
/// Doubles only, as the Bézier analysis; rational B-splines are not analysed here.

#include "core/base/aabb.h"
#include "core/curves/bezier/closest_point.h"
#include "core/curves/bezier/curvature.h"
#include "core/curves/bsplines/bezier_extraction.h"
#include "core/curves/bsplines/bspline_curve.h"

#include <vector>

namespace granota {

class BSplineAnalysis {
public:
    /// `c` must pass checkBSpline and be polynomial (no weights). Extracts the pieces once.
    explicit BSplineAnalysis(const BSplineCurve<double>& c);

    const std::vector<RationalBezierSegment<double>>& segments() const { return m_segments; }
    /// The piece holding u (the last one at the domain's end; u is clamped to the domain),
    /// and u's parameter t ∈ [0, 1] on it.
    int segmentAt(double u, double* t = nullptr) const;

    /// Curvature, normal and osculating circle at u (curvature.h on u's piece); `t` and
    /// `tangent` are in u: tangent = c′(u) = c′_piece(t) / (end − start). At a knot the piece
    /// on the right is used (the left one at the domain's end).
    CurvatureAt curvatureAt(double u) const;
    /// ∫ |c′| du over [u0, u1] (both clamped to the domain; negative when u1 < u0): the pieces'
    /// lengths by adaptive Gauss–Legendre (arc_length.h) summed.
    double arcLength(double u0, double u1) const;
    /// The whole length.
    double arcLength() const;
    /// u inside the domain where x′ = 0 (resp. y′ = 0), ascending, each once: the pieces'
    /// extrema and the knots across which x′ vanishes or changes sign.
    std::vector<double> extremaX() const { return extrema(0); }
    std::vector<double> extremaY() const { return extrema(1); }
    /// The tight box: the union of the pieces' tight boxes (curve_features.h).
    Aabb tightBox() const;
    /// u inside the domain where x′y″ − y′x″ changes sign: inside pieces and across knots.
    std::vector<double> inflections() const;
    /// u in the domain where c′ = 0 (curve_features.h's test on each piece), each once.
    std::vector<double> cusps() const;
    /// The point of the curve closest to p over the whole domain (closest_point.h on each
    /// piece); on a tie the smallest u. `t` of the result is u.
    ClosestPoint closestPoint(Point p) const;

private:
    std::vector<double> extrema(int coordinate) const;
    double toU(std::size_t piece, double t) const;

    std::vector<RationalBezierSegment<double>> m_segments;
};

} // namespace granota
