#pragma once
/// \file interval_overshoot.h
/// How far a curve piece leaves the band of its two data values: on [x_i, x_{i+1}] an
/// interpolating piece p starts at y_i and ends at y_{i+1}, and it overshoots where it goes
/// above max(y_i, y_{i+1}) or below min(y_i, y_{i+1}) — what d3-shape #38 reports of the
/// natural spline (Def 2.3) and what the monotone schemes of monotone_spline.h never do.
///
/// The largest overshoot of a polynomial of degree ≤ 3 on u ∈ [0, 1] is found exactly where
/// it can be: at u = 0, u = 1 and at the roots of p′ inside (a quadratic, solved by the
/// stable formula q = −(b + sign(b)√(b² − 4ac))/2, roots q/a and c/q). No sampling.

#include "core/exact/polynomial.h"

namespace granota {

struct IntervalOvershoot {
    double amount = 0;  ///< the largest distance outside [lo, hi]; 0 when p stays inside
    double at = 0;      ///< the u ∈ [0, 1] where it is reached (0 when amount is 0)
    bool above = false; ///< beyond hi (true) or below lo (false)
};

/// The overshoot of p(u), u ∈ [0, 1], outside [lo, hi] (lo ≤ hi, p of degree ≤ 3, finite
/// coefficients).
IntervalOvershoot polynomialOvershoot(const Polynomial<double>& p, double lo, double hi);

} // namespace granota
