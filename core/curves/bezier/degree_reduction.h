#pragma once
/// \file degree_reduction.h
/// Degree reduction: the Bézier curve of degree n − 1 closest to c in L²([0, 1]), the inverse
/// of degree elevation (degree_elevation.h) where one exists (beyond the thesis; Eck, "Least
/// squares degree reduction of Bézier curves", CAD 27 (1995), and Farin, "Curves and
/// Surfaces for CAGD", §6.3). It is the least-squares problem of §2.1.3 with the integral in
/// place of the sum over data points: the normal equations G Q = H P with the exact Gram
/// matrices of the Bernstein polynomials (Def 2.5)
///   G_ij = ∫ B_i^{m} B_j^{m} = C(m,i) C(m,j) / ((2m+1) C(2m, i+j)),
///   H_ik = ∫ B_i^{m} B_k^{n} = C(m,i) C(n,k) / ((m+n+1) C(m+n, i+k)),   m = n − 1,
/// solved exactly in rationals (rational_matrix.h). The error is the L² distance
/// √∫|c − r|², r the reduced curve elevated back to degree n.

#include "core/base/expected.h"
#include "core/base/vec2.h"
#include "core/exact/rational.h"

#include <vector>

namespace granota {

template <class S> struct DegreeReduction {
    std::vector<Vec2<S>> points; ///< the n control points of the reduced curve
    double error = 0;            ///< √∫_0^1 |c(t) − r(t)|² dt
    bool exact = false;          ///< r = c: c was a degree elevation (error 0)
};

/// Exact for rationals. An Error (TooFewPoints) for a single point: degree 0 has nothing to
/// reduce.
Expected<DegreeReduction<Rational>> reduceDegree(const std::vector<RPoint>& P);
/// For doubles: each double is the rational it denotes, reduced exactly and rounded once (the
/// correctly rounded optimum; G's condition number grows too fast with n for a floating-point
/// solve). exact = true when P is exactly the elevation of a curve (its points then need not be
/// doubles and are rounded). Degrees above 40 are refused (OutOfRange), and non-finite points
/// (InvalidInput).
Expected<DegreeReduction<double>> reduceDegree(const std::vector<Point>& P);

} // namespace granota
