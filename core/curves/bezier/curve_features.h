#pragma once
/// \file curve_features.h
/// The features of a Bézier curve c(t) = Σ B_i^n(t) P_i (Def 2.6) that are roots of
/// polynomials in Bernstein form (bernstein_roots.h), beyond the thesis (Pomax, "A Primer
/// on Bézier Curves", §§ "Extremities", "Bounding boxes", "Curve inflections"; Farin,
/// "Curves and Surfaces for CAGD", §5.3 for the hodograph):
///  - extrema of x and of y: the zeros of the coordinates of the hodograph c′ (hodograph.h);
///  - the tight axis-aligned bounding box: the ends and the extrema;
///  - inflections: the sign changes of x′y″ − y′x″, a polynomial of degree 2n − 4;
///  - cusps: the t where c′ = 0 (both coordinates at once).

#include "core/base/aabb.h"
#include "core/base/vec2.h"

#include <vector>

namespace granota {

struct CurveFeatures {
    /// t in (0, 1) where x′ = 0, resp. y′ = 0, ascending, once each (a double zero once).
    /// Empty when that coordinate is constant (x′ ≡ 0: every t would do).
    std::vector<double> extremaX, extremaY;
    /// The tight axis-aligned box of the curve over [0, 1].
    Aabb bbox;
    /// t in (0, 1) where x′y″ − y′x″ changes sign (a touching zero is not an inflection).
    std::vector<double> inflections;
    /// t in [0, 1] where c′ = 0 (coincident end control points give 0 or 1).
    std::vector<double> cusps;
    /// c′ ≡ 0: every control point is the same point, the curve is that point; every t is
    /// stationary, so cusps, extrema and inflections are left empty rather than listed.
    bool stationary = false;
    /// x′y″ − y′x″ ≡ 0: the curve lies on a line (all control points collinear, degree ≤ 1
    /// included), so it has no inflections; its curvature is 0 wherever it is defined.
    bool straight = false;
};

CurveFeatures curveFeatures(const std::vector<Point>& P);

/// The t in (0, 1) where the coordinate (0 = x, 1 = y) of c′ vanishes.
std::vector<double> extremaParameters(const std::vector<Point>& P, int coordinate);
/// The tight box from the ends and the extrema of x and y.
Aabb tightBoundingBox(const std::vector<Point>& P);
/// The t in [0, 1] where c′ = 0, within 10⁻⁹ of the size of the hodograph (max |n (P_{i+1} − P_i)|).
std::vector<double> cuspParameters(const std::vector<Point>& P);
/// The sign changes of x′y″ − y′x″ in (0, 1).
std::vector<double> inflectionParameters(const std::vector<Point>& P);

/// The Bernstein coefficients D_0 … D_{2m−2} (m = n − 1 ≥ 1) of x′y″ − y′x″ = A(t) × A′(t),
/// A = c′ with control points A_i: from B_i^m (B_j^m)′ − B_j^m (B_i^m)′ =
/// (j − i) C(m,i) C(m,j) t^{i+j−1} (1 − t)^{2m−1−i−j},
///   D_k = Σ_{i<j, i+j=k+1} (j − i) C(m,i) C(m,j) / C(2m−2,k) · (A_i × A_j),
/// the exact degree 2n − 4 (the t^{2n−3} term of the plain product cancels). Empty for n ≤ 1.
std::vector<double> curvatureNumerator(const std::vector<Point>& P);

} // namespace granota
