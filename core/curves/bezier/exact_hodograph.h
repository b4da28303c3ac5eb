#pragma once
/// \file exact_hodograph.h
/// Whether c′ = 0, decided exactly when doubles cannot tell. A double has 53 bits, so with
/// control points near ±1e308 the rounding of c′(t) = Σ B_i^{n−1}(t) n (P_{i+1} − P_i)
/// (hodograph.h) is about 1e292, and a true c′(1/2) = (21/4, 0) is lost in it: the
/// floating-point test |c′| ≤ tolerance · size would call it a cusp. Every double is a
/// dyadic rational (exactRational), so the same control points, taken exactly, answer it.
/// Used by curvatureAt (curvature.h) and the cusps of curveFeatures (curve_features.h) only
/// when the floating-point test says c′ = 0, and only within kMaxExactWork
/// (core/exact/exact_cost.h); beyond it they keep the floating-point answer.

#include "core/base/vec2.h"
#include "core/exact/rational.h"

#include <optional>
#include <vector>

namespace granota {

/// c′(t) and c″(t) of the curve with control points P, exactly.
struct ExactDerivatives {
    RPoint first;  ///< c′(t)
    RPoint second; ///< c″(t)
};

/// nullopt when P has fewer than 2 points, a coordinate or t is not finite, or the work
/// (two De Casteljau triangles, deCasteljauExactWork) is beyond kMaxExactWork.
std::optional<ExactDerivatives> exactDerivativesAt(const std::vector<Point>& P, double t);

/// Whether x′ and y′ vanish together somewhere in [0, 1], exactly: at t = 1 when both
/// last hodograph points are 0, and in [0, 1) when the polynomials
/// Σ C(m, i) a_i s^i and Σ C(m, i) b_i s^i (the Bernstein coefficients a_i, b_i of x′ and
/// y′ of degree m, with s = t/(1 − t)) have a common factor (Euclid's algorithm over the
/// rationals). A common factor whose roots are all outside [0, 1) still answers true: the
/// callers only ask about t where the floating-point c′ is already 0. nullopt when P has
/// fewer than 2 points, a coordinate is not finite, or the work is beyond kMaxExactWork.
std::optional<bool> hodographVanishesSomewhere(const std::vector<Point>& P);

} // namespace granota
