#pragma once
/// \file cubic_spline.h
/// The C² cubic interpolating spline of Def 2.3 for function data (x_i, y_i), with the end
/// conditions that fix it. Def 2.3 fixes the pieces' degree (≤ 3), interpolation and
/// s ∈ C², which leaves two degrees of freedom; an end condition at each end picks one
/// spline:
///  - natural: s″(x_0) = s″(x_k) = 0;
///  - clamped: the end slopes s′(x_0) = A and s′(x_k) = B are given;
///  - not-a-knot: s‴ is continuous at x_1 and x_{k−1} (the first two pieces are one cubic,
///    and so are the last two; scipy's default);
///  - as Ex 2.1: s₁‴ = 0 (the first piece is a parabola) and the last piece has no x² term
///    in powers of x — the ends that give Ex 2.1's printed pieces, corrected (its s₂ lacks
///    +1/53: docs/thesis-errata.md). Ex 2.1 is not the natural spline: s₁″(0) = −264/53.
///
/// Method: the unknowns are the second derivatives M_i = s″(x_i). With h_i = x_{i+1} − x_i
/// and Δ_i = (y_{i+1} − y_i)/h_i, C² at the interior knots gives
///     h_{i−1} M_{i−1} + 2(h_{i−1} + h_i) M_i + h_i M_{i+1} = 6(Δ_i − Δ_{i−1}),  1 ≤ i ≤ k−1.
/// Each end condition writes the end value as M_0 = p₀ + p₁M_1 + p₂M_2 (and M_k likewise
/// from M_{k−1}, M_{k−2}), which is put into the first (last) interior row: the system stays
/// tridiagonal, and is solved with pivoting (tridiagonal_system.h), exactly over Rational.
/// Piece i in the local u = x − x_i:
///     s_i(u) = y_i + b_i u + M_i/2 u² + (M_{i+1} − M_i)/(6 h_i) u³,
///     b_i = Δ_i − h_i (2 M_i + M_{i+1})/6.

#include "core/base/expected.h"
#include "core/curves/splines/piecewise_polynomial.h"
#include "core/curves/splines/tridiagonal_system.h"
#include "core/exact/rational.h"
#include "core/base/vec2.h"

#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace granota {

/// The end conditions of a cubic spline (see the file's comment).
enum class SplineEnds { Natural, Clamped, NotAKnot, AsEx21 };
/// "natural", "clamped", "not-a-knot", "ex-2.1": as the CLI's --ends and documents write them.
std::string_view splineEndsName(SplineEnds ends);
std::optional<SplineEnds> parseSplineEnds(std::string_view name);

/// The end conditions with the end slopes that `Clamped` needs (ignored otherwise).
template <class S> struct SplineEndConditions {
    SplineEnds kind = SplineEnds::Natural;
    S startSlope = S(0); ///< s′(x_0), clamped only
    S endSlope = S(0);   ///< s′(x_k), clamped only
};

/// The cubic spline through points (x_i, y_i), x strictly increasing, at least 2 points,
/// with the given ends. Two points give the line (natural, not-a-knot, as Ex 2.1) or the
/// cubic Hermite piece (clamped); three points with not-a-knot give the parabola.
/// Errors: TooFewPoints, NotIncreasing, InvalidInput (NaN/inf, doubles only), Singular
/// (as Ex 2.1 with x_{k−1} = 0, where the condition on the last piece does not fix M_k),
/// OutOfRange (the result overflows, doubles only).
/// For Rational the pieces are exact and in powers of the global x (as Ex 2.1 prints
/// them); for floating point they are kept in powers of (x − x_i) (`localOrigin`).
template <class S>
Expected<PiecewisePolynomial<S>> cubicSpline(const std::vector<Vec2<S>>& points, const SplineEndConditions<S>& ends)
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
        if (ends.kind == SplineEnds::Clamped && (!std::isfinite(ends.startSlope) || !std::isfinite(ends.endSlope)))
            return makeError(ErrorCode::InvalidInput, "An end slope is not a finite number (NaN or infinity).");
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
    const SplineEnds kind = ends.kind;
    std::vector<S> m(k + 1, S(0)); // M_0 … M_k
    if (kind == SplineEnds::AsEx21 && k >= 2 && points[k - 1].x == S(0))
        return makeError(ErrorCode::Singular, "The ends of Ex 2.1 need x_{k-1} ≠ 0: with x_{k-1} = 0 the last piece has no x² "
                                              "term for every M_k, and the spline is not unique.");
    if (k == 1) {
        // One piece: the line, or the cubic Hermite piece of the two end slopes.
        if (kind == SplineEnds::Clamped) {
            // 2h M_0 + h M_1 = 6(Δ − A), h M_0 + 2h M_1 = 6(B − Δ).
            const S a = S(S(6) * S(delta[0] - ends.startSlope) / h[0]), b = S(S(6) * S(ends.endSlope - delta[0]) / h[0]);
            m[0] = S(S(S(2) * a - b) / S(3));
            m[1] = S(S(S(2) * b - a) / S(3));
        }
    } else if (kind == SplineEnds::NotAKnot && k == 2) {
        // Both conditions make the two pieces one cubic whose s‴ = 0: the parabola.
        const S second = S(S(2) * S(delta[1] - delta[0]) / S(h[0] + h[1]));
        m.assign(k + 1, second);
    } else {
        // M_0 = p0 + p1 M_1 + p2 M_2 and M_k = q0 + q1 M_{k−1} + q2 M_{k−2}.
        S p0(0), p1(0), p2(0), q0(0), q1(0), q2(0);
        switch (kind) {
        case SplineEnds::Natural: break;
        case SplineEnds::Clamped: // 2h_0 M_0 + h_0 M_1 = 6(Δ_0 − A), h M_{k−1} + 2h M_k = 6(B − Δ_{k−1})
            p0 = S(S(3) * S(delta[0] - ends.startSlope) / h[0]);
            p1 = S(-1) / S(2);
            q0 = S(S(3) * S(ends.endSlope - delta[k - 1]) / h[k - 1]);
            q1 = S(-1) / S(2);
            break;
        case SplineEnds::NotAKnot: // (M_1 − M_0)/h_0 = (M_2 − M_1)/h_1, and at the other end
            p1 = S(S(h[0] + h[1]) / h[1]);
            p2 = S(-h[0] / h[1]);
            q1 = S(S(h[k - 2] + h[k - 1]) / h[k - 2]);
            q2 = S(-h[k - 1] / h[k - 2]);
            break;
        case SplineEnds::AsEx21: // M_0 = M_1; the last piece's x² coefficient M_{k−1}/2 − 3 d x_{k−1} = 0
            p1 = S(1);
            q1 = S(points[k].x / points[k - 1].x);
            break;
        }
        const std::size_t n = k - 1; // the interior unknowns M_1 … M_{k−1}
        std::vector<S> sub(n), diag(n), super(n), rhs(n);
        for (std::size_t j = 0; j < n; ++j) {
            const std::size_t i = j + 1;
            sub[j] = h[i - 1];
            diag[j] = S(S(2) * S(h[i - 1] + h[i]));
            super[j] = h[i];
            rhs[j] = S(S(6) * S(delta[i] - delta[i - 1]));
        }
        // Row 1 takes M_0 in; row k−1 takes M_k in (the same row when k = 2).
        diag[0] = S(diag[0] + S(h[0] * p1));
        rhs[0] = S(rhs[0] - S(h[0] * p0));
        if (n > 1)
            super[0] = S(super[0] + S(h[0] * p2));
        diag[n - 1] = S(diag[n - 1] + S(h[k - 1] * q1));
        rhs[n - 1] = S(rhs[n - 1] - S(h[k - 1] * q0));
        if (n > 1)
            sub[n - 1] = S(sub[n - 1] + S(h[k - 1] * q2));
        const auto interior = solveTridiagonal(std::move(sub), std::move(diag), std::move(super), std::move(rhs));
        if (!interior)
            return makeError(ErrorCode::Singular, std::string("No unique cubic spline with ") +
                                                      std::string(splineEndsName(kind)) + " ends through these points.");
        for (std::size_t j = 0; j < n; ++j)
            m[j + 1] = (*interior)[j];
        m[0] = S(p0 + S(p1 * m[1]) + S(p2 * (k >= 2 ? m[2] : S(0))));
        m[k] = S(q0 + S(q1 * m[k - 1]) + S(q2 * (k >= 2 ? m[k - 2] : S(0))));
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

/// The natural cubic spline (s″ = 0 at both ends): cubicSpline with natural ends.
template <class S> Expected<PiecewisePolynomial<S>> naturalCubicSpline(const std::vector<Vec2<S>>& points)
{
    return cubicSpline(points, SplineEndConditions<S>{});
}

extern template Expected<PiecewisePolynomial<double>> cubicSpline(const std::vector<Vec2<double>>&,
                                                                  const SplineEndConditions<double>&);
extern template Expected<PiecewisePolynomial<Rational>> cubicSpline(const std::vector<Vec2<Rational>>&,
                                                                    const SplineEndConditions<Rational>&);

} // namespace granota
