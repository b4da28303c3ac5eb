#pragma once
/// \file cubic_spline.h
/// The C² cubic interpolating spline of Def 2.3 for function data (x_i, y_i), with
/// natural ends s″(x_0) = s″(x_k) = 0 — beyond the thesis, to compare continuity with
/// Catmull-Rom (§2.3: Bézier C^∞, Catmull-Rom C¹, cubic spline C²).
///
/// Def 2.3 fixes the pieces' degree (≤ 3), interpolation and s ∈ C², which leaves two
/// degrees of freedom; the natural ends pick one spline. (Ex 2.1 is *another* cubic spline
/// through its points: its ends are not natural, s₁″(0) = −264/53.)
///
/// Method: the unknowns are the second derivatives M_i = s″(x_i). With h_i = x_{i+1} − x_i
/// and Δ_i = (y_{i+1} − y_i)/h_i, C² at the interior knots gives the tridiagonal system
///     h_{i−1} M_{i−1} + 2(h_{i−1} + h_i) M_i + h_i M_{i+1} = 6(Δ_i − Δ_{i−1}),  1 ≤ i ≤ k−1,
/// with M_0 = M_k = 0. It is strictly diagonally dominant, so the Thomas algorithm (Gaussian
/// elimination without pivoting) is stable in floating point and exact over Rational.
/// Piece i in the local u = x − x_i:
///     s_i(u) = y_i + b_i u + M_i/2 u² + (M_{i+1} − M_i)/(6 h_i) u³,
///     b_i = Δ_i − h_i (2 M_i + M_{i+1})/6.

#include "core/base/expected.h"
#include "core/curves/splines/piecewise_polynomial.h"
#include "core/exact/rational.h"
#include "core/base/vec2.h"

#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace granota {

/// Natural cubic spline through points (x_i, y_i), x strictly increasing, at least 2
/// points (2 points give the line). Errors: TooFewPoints, NotIncreasing, InvalidInput
/// (NaN/inf, doubles only), OutOfRange (the result overflows, doubles only).
/// For Rational the pieces are exact and in powers of the global x (as Ex 2.1 prints
/// them); for floating point they are kept in powers of (x − x_i) (`localOrigin`).
template <class S> Expected<PiecewisePolynomial<S>> naturalCubicSpline(const std::vector<Vec2<S>>& points)
{
    constexpr bool floating = std::is_floating_point_v<S>;
    const std::size_t count = points.size();
    if (count < 2)
        return makeError(ErrorCode::TooFewPoints, "A cubic spline needs at least 2 points (got " + std::to_string(count) + ").");
    if constexpr (floating) {
        for (std::size_t i = 0; i < count; ++i)
            if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
                return makeError(ErrorCode::InvalidInput,
                                 "Point " + std::to_string(i) + " is not a finite number (NaN or infinity).");
    }
    for (std::size_t i = 0; i + 1 < count; ++i)
        if (!(points[i].x < points[i + 1].x))
            return makeError(ErrorCode::NotIncreasing, "The abscissae must increase strictly: x_" + std::to_string(i + 1) +
                                                           " is not greater than x_" + std::to_string(i) + ".");

    const std::size_t k = count - 1; // number of pieces
    std::vector<S> h(k), delta(k);
    for (std::size_t i = 0; i < k; ++i) {
        h[i] = S(points[i + 1].x - points[i].x);
        delta[i] = S(S(points[i + 1].y - points[i].y) / h[i]);
    }

    // Second derivatives M_0..M_k; M_0 = M_k = 0 (natural ends). Thomas algorithm on the
    // interior unknowns M_1..M_{k−1}.
    std::vector<S> m(k + 1, S(0));
    if (k >= 2) {
        const std::size_t n = k - 1;
        std::vector<S> cPrime(n), rPrime(n);
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t i = j + 1; // knot index
            const S sub = h[i - 1];
            const S diag = S(S(2) * S(h[i - 1] + h[i]));
            const S super = h[i];
            const S rhs = S(S(6) * S(delta[i] - delta[i - 1]));
            if (j == 0) {
                cPrime[j] = S(super / diag);
                rPrime[j] = S(rhs / diag);
            } else {
                const S denom = S(diag - S(sub * cPrime[j - 1]));
                cPrime[j] = S(super / denom);
                rPrime[j] = S(S(rhs - S(sub * rPrime[j - 1])) / denom);
            }
        }
        m[n] = rPrime[n - 1];
        for (std::size_t j = n - 1; j-- > 0;)
            m[j + 1] = S(rPrime[j] - S(cPrime[j] * m[j + 2]));
    }

    PiecewisePolynomial<S> spline;
    spline.localOrigin = true;
    spline.knots.reserve(count);
    for (const auto& p : points)
        spline.knots.push_back(p.x);
    for (std::size_t i = 0; i < k; ++i) {
        const S b = S(delta[i] - S(S(h[i] * S(S(2) * m[i] + m[i + 1])) / S(6)));
        const S c = S(m[i] / S(2));
        const S d = S(S(m[i + 1] - m[i]) / S(S(6) * h[i]));
        spline.pieces.push_back(Polynomial<S>(std::vector<S>{points[i].y, b, c, d}));
    }

    if constexpr (floating) {
        for (const auto& p : spline.pieces)
            for (const S& c : p.coefficients())
                if (!std::isfinite(c))
                    return makeError(ErrorCode::OutOfRange,
                                     "The spline overflows: the coordinates are too large or too close together.");
        return spline;
    } else {
        return spline.toGlobal(); // Ex 2.1's form: powers of x
    }
}

extern template Expected<PiecewisePolynomial<double>> naturalCubicSpline(const std::vector<Vec2<double>>&);
extern template Expected<PiecewisePolynomial<Rational>> naturalCubicSpline(const std::vector<Vec2<Rational>>&);

} // namespace granota
