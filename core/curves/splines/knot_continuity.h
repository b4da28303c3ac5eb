#pragma once
/// \file knot_continuity.h
/// How smoothly a piecewise curve passes each of its knots, parametrically (C⁰, C¹, C²) and
/// geometrically (G¹, G²), with the jumps — §2.3 knot by knot: Bézier curves are C^∞,
/// Catmull-Rom curves C¹ (Prop 2.3) but not C², the cubic spline of Def 2.3 C².
///
/// The segments p_1, p_2, … each live on a local s ∈ [0, 1]; segment i covers an interval of
/// length h_i of the curve's own (global) parameter u, s = (u − u_i)/h_i. h_i = 1 for uniform
/// Catmull-Rom curves, h_i = |q_{i+1} − q_i|^α for centripetal and chordal spacing, and
/// h_i = x_{i+1} − x_i for a function spline drawn as its graph (function_spline_segments.h).
/// C^k compares the derivatives in u, d^k p/du^k = h^{−k} d^k p/ds^k, on both sides of a knot.
///
/// Beyond the thesis (Farin, "Curves and Surfaces for CAGD", ch. 7; Barsky and DeRose,
/// "Geometric continuity of parametric curves", 1989): G^k does not depend on the
/// parametrization.
///  - G¹: C⁰ and both tangents non-zero and pointing the same way (cross product 0, dot
///    product > 0). A knot where a tangent vanishes is not G¹ (the direction is undefined).
///  - G²: G¹ and the same signed curvature κ = (x′y″ − y′x″)/|p′|³ on both sides.
///    Exactly for Rational: sign(c_L) = sign(c_R) and c_L²|p′_R|⁶ = c_R²|p′_L|⁶ (c the cross
///    term), so no square root is taken.
/// Every C^k (k ≥ 1) with non-zero tangent implies G^k; the converse fails, which is why a
/// centripetal Catmull-Rom curve is drawn with parallel but unequal local tangents.
///
/// Exact for Rational (tolerance 0). For doubles a tolerance > 0 accepts as in
/// continuity_check.h: |a − b| ≤ tolerance · max(1, |a|, |b|) per coordinate, and for the
/// direction and the curvature the same test on the quantities above relative to their size.

#include "core/base/vec2.h"
#include "core/exact/polynomial.h"
#include "core/exact/rational.h"

#include <optional>
#include <vector>

namespace granota {

/// One knot: the end of segment `fromSegment` meets the start of `toSegment`.
template <class S> struct KnotContinuity {
    int fromSegment = 0; ///< 0-based (the thesis's p_{fromSegment+1})
    int toSegment = 0;   ///< fromSegment + 1, or 0 at the closing knot of a closed loop
    /// Left (p_from at s = 1) and right (p_to at s = 0) values of the derivatives of order
    /// 0, 1, 2 in the global parameter u.
    Vec2<S> left[3];
    Vec2<S> right[3];
    bool equal[3] = {false, false, false}; ///< equal[k]: the k-th derivatives agree
    bool g1 = false;
    bool g2 = false;
    /// Signed curvature on each side (doubles, for display); nullopt where the tangent is 0.
    std::optional<double> curvatureLeft;
    std::optional<double> curvatureRight;
    /// The turn of the tangent across the knot in radians, in (−π, π] (0 when G¹);
    /// nullopt where a tangent is 0.
    std::optional<double> tangentTurn;

    /// Highest k ≤ 2 with C⁰..C^k at this knot; −1 when the curve breaks here.
    int parametricOrder() const { return !equal[0] ? -1 : !equal[1] ? 0 : !equal[2] ? 1 : 2; }
    /// Highest k ≤ 2 with G^k (G⁰ = C⁰); −1 when the curve breaks here.
    int geometricOrder() const { return !equal[0] ? -1 : !g1 ? 0 : !g2 ? 1 : 2; }
    /// right[k] − left[k]: the jump of the k-th derivative.
    Vec2<S> jump(int k) const { return right[k] - left[k]; }
};

/// Every knot of the curve in order (the joins of consecutive segments and, with
/// closedLoop, the last segment's end against the first one's start). `intervals` holds
/// h_i per segment; empty means all 1 (uniform). Segments are polynomials of any degree in
/// their local s. Returns no knots for fewer than two segments (one without closedLoop).
/// Requires intervals.size() == segments.size() when not empty, every h_i > 0.
template <class S>
std::vector<KnotContinuity<S>> knotContinuity(const std::vector<Vec2<Polynomial<S>>>& segments,
                                              const std::vector<S>& intervals = {}, bool closedLoop = false,
                                              double tolerance = 0);

extern template std::vector<KnotContinuity<double>> knotContinuity(const std::vector<Vec2<Polynomial<double>>>&,
                                                                   const std::vector<double>&, bool, double);
extern template std::vector<KnotContinuity<Rational>> knotContinuity(const std::vector<Vec2<Polynomial<Rational>>>&,
                                                                     const std::vector<Rational>&, bool, double);

} // namespace granota
