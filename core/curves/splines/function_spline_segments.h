#pragma once
/// \file function_spline_segments.h
/// The graph (x, s(x)) of a function spline (Def 2.2, Def 2.3) as a parametric curve made of
/// segments on local u ∈ [0, 1], so that it can be compared with Catmull-Rom curves on the
/// same canvas, converted to Bézier segments (bezier_segments.h) and checked knot by knot
/// (knot_continuity.h). Piece i becomes
///     x(u) = x_i + h_i u,   y(u) = s_i(x_i + h_i u),   h_i = x_{i+1} − x_i,
/// a polynomial of the piece's degree in u (the Taylor shift, then the scaling u ↦ h_i u),
/// exact for Rational. With the intervals h_i as the knot spacing, the graph of a C² spline
/// is C² in x.

#include "core/base/vec2.h"
#include "core/curves/splines/piecewise_polynomial.h"
#include "core/exact/polynomial.h"
#include "core/exact/rational.h"

#include <vector>

namespace granota {

template <class S> struct FunctionSplineSegments {
    std::vector<Vec2<Polynomial<S>>> segments; ///< one per piece, in order
    std::vector<S> intervals;                  ///< h_i, one per piece
};

/// `pp` must be valid (pp.isValid()); global or local storage alike.
template <class S> FunctionSplineSegments<S> functionSplineSegments(const PiecewisePolynomial<S>& pp);

extern template FunctionSplineSegments<double> functionSplineSegments(const PiecewisePolynomial<double>&);
extern template FunctionSplineSegments<Rational> functionSplineSegments(const PiecewisePolynomial<Rational>&);

} // namespace granota
