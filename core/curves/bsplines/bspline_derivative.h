#pragma once
/// \file bspline_derivative.h
/// The derivative of a polynomial B-spline is a B-spline of degree p − 1 on the same knots
/// with the first and the last dropped (Piegl & Tiller eq. (3.4)–(3.5), A3.3):
///   c′(u) = Σ_{i=0..n−1} N_{i+1,p−1}(u) Q_i,   Q_i = p (P_{i+1} − P_i) / (u_{i+p+1} − u_{i+1}),
/// knots u_1..u_{n+p}. The hodograph of a Bézier curve (core/curves/bezier/hodograph.h) is the
/// case with no interior knot. Exact in Rational.

#include "core/curves/bsplines/bspline_curve.h"

#include <cassert>
#include <cstddef>
#include <vector>

namespace granota {

/// c′ for a polynomial curve `c` (not rational) of degree p ≥ 1 that passes checkBSpline; the
/// same domain. A curve of degree 1 gives one of degree 0, piecewise constant: de Boor
/// evaluates it (its span's point), though checkBSpline accepts degrees from 1 only.
template <class S> BSplineCurve<S> derivativeCurve(const BSplineCurve<S>& c)
{
    assert(!c.rational() && c.degree >= 1);
    const int p = c.degree, n = c.pointCount() - 1;
    const auto z = [](int i) { return static_cast<std::size_t>(i); };
    BSplineCurve<S> d;
    d.degree = p - 1;
    d.knots.assign(c.knots.begin() + 1, c.knots.end() - 1);
    d.points.reserve(z(n));
    for (int i = 0; i < n; ++i) {
        // u_{i+p+1} > u_{i+1}: otherwise a knot would be repeated p + 1 times inside.
        const S f = S(S(p) / S(c.knots[z(i + p + 1)] - c.knots[z(i + 1)]));
        d.points.push_back(f * (c.points[z(i + 1)] - c.points[z(i)]));
    }
    return d;
}

} // namespace granota
