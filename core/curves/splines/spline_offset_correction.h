#pragma once
/// \file spline_offset_correction.h
/// Diagnosing a printed spline: a piece s_i that misses *both* data points at the ends of its
/// interval by the same amount c is the right piece shifted by a constant, and s_i + c is what
/// was meant. That is Ex 2.1's slip: its s₂ as printed lacks +1/53 (s₂(1) = 158/53 instead of
/// 3, s₂(2) = 52/53 instead of 1), while s′ and s″ match at the knots. The correction is only
/// proposed, never assumed: checkContinuity (continuity_check.h) then confirms that the
/// corrected spline interpolates and is C² (Def 2.3).

#include "core/curves/splines/piecewise_polynomial.h"
#include "core/exact/rational.h"
#include "core/base/vec2.h"

#include <vector>

namespace granota {

/// One piece shifted by a constant.
struct OffsetCorrection {
    int piece = 0;   ///< 0-based (the thesis's s_{piece+1})
    Rational offset; ///< add this to the piece: y_i − s_i(x_i) = y_{i+1} − s_i(x_{i+1}) ≠ 0
};

struct OffsetCorrectionResult {
    PiecewisePolynomial<Rational> corrected; ///< the spline with every correction applied
    std::vector<OffsetCorrection> corrections;
};

/// `data` are the interpolated points, one per knot (data[i].x = knots[i]); pieces whose end
/// points are missed by different amounts (or data that do not sit on the knots) are left
/// alone: no constant repairs them. Exact arithmetic only.
OffsetCorrectionResult correctConstantOffsets(const PiecewisePolynomial<Rational>& spline, const std::vector<RPoint>& data);

} // namespace granota
