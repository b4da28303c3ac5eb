#pragma once
/// \file parametric_spline.h
/// The C² cubic spline through points P_0..P_n of the plane (Def 2.1 in full: a curve made
/// of cubic pieces joined with equal first and second derivatives). Each coordinate is a
/// function spline of Def 2.3 in a common parameter u with knots u_0 < u_1 < …; the end
/// conditions are those of cubic_spline.h, in u:
///  - natural: p″(u_0) = p″(u_n) = 0;
///  - clamped: p′(u_0) and p′(u_n) are given (tangents in the global parameter u, as
///    scipy's CubicSpline takes them; with uniform parameters that is the tangent in each
///    segment's local s too);
///  - not-a-knot: p‴ continuous at u_1 and u_{n−1};
///  - periodic (closed): one more segment P_n → P_0, and p, p′, p″ agree at the wrap, so
///    the curve is C² at every knot including u_0 ≡ u_{n+1}.
/// Parameters (the interval lengths h_i = u_{i+1} − u_i):
///  - uniform: h_i = 1 (u_i = i), exact over Rational;
///  - chord length: h_i = |P_{i+1} − P_i| (the knots are the cumulative distances);
///  - centripetal: h_i = |P_{i+1} − P_i|^{1/2} (Lee 1989; no cusps within a segment).
/// Over Rational chord and centripetal work when the lengths are rational (3-4-5 steps),
/// and are refused (NotRational) otherwise.
///
/// Method: the unknowns are the second derivatives M_i = p″(u_i) (vectors). C² at knot i:
///     h_{i−1} M_{i−1} + 2(h_{i−1} + h_i) M_i + h_i M_{i+1} = 6(Δ_i − Δ_{i−1}),
///     Δ_i = (P_{i+1} − P_i)/h_i.
/// Open ends: the system of cubic_spline.h for each coordinate (a banded solve with
/// pivoting, tridiagonal_system.h). Closed: the same rows with indices mod n + 1, a cyclic
/// tridiagonal system (cyclic_tridiagonal_system.h, Sherman–Morrison): O(n), never dense.
/// Segment i in its local s = (u − u_i)/h_i ∈ [0, 1]:
///     p(s) = P_i + [P_{i+1} − P_i − h_i²(2M_i + M_{i+1})/6] s + h_i² M_i/2 s² + h_i²(M_{i+1} − M_i)/6 s³.

#include "core/base/expected.h"
#include "core/base/vec2.h"
#include "core/curves/splines/cubic_spline.h"
#include "core/curves/splines/cyclic_tridiagonal_system.h"
#include "core/exact/polynomial.h"
#include "core/exact/rational.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace granota {

/// The end conditions of the parametric spline (see the file's comment).
enum class ParametricEnds { Natural, Clamped, NotAKnot, Periodic };
/// How the knots u_i are spaced (see the file's comment).
enum class SplineParameters { Uniform, Chord, Centripetal };

/// "natural", "clamped", "not-a-knot", "periodic": as the CLI's --ends writes them.
std::string_view parametricEndsName(ParametricEnds ends);
std::optional<ParametricEnds> parseParametricEnds(std::string_view name);
/// "uniform", "chord", "centripetal": as the CLI's --param writes them.
std::string_view splineParametersName(SplineParameters parameters);
std::optional<SplineParameters> parseSplineParameters(std::string_view name);

/// The fewest points each end condition takes: 2 for open ends (2 points give the line, or
/// the Hermite cubic when clamped; not-a-knot through 3 points is the parabola), 3 for the
/// closed spline.
constexpr std::size_t parametricSplineMinimumPoints(ParametricEnds ends) { return ends == ParametricEnds::Periodic ? 3 : 2; }

template <class S> struct ParametricSpline {
    std::vector<S> knots; ///< u_0 < u_1 < … < u_m, one more than the segments (closed: u_m closes at P_0)
    /// Segment i from P_i to P_{i+1} (closed: the last one to P_0): c_0..c_3 with
    /// p(s) = c_0 + c_1 s + c_2 s² + c_3 s³ in its local s = (u − u_i)/(u_{i+1} − u_i) ∈ [0, 1].
    std::vector<std::array<Vec2<S>, 4>> segments;
};

namespace detail {
/// C++20's std::type_identity: keeps the tangents out of template deduction, so that a
/// plain Vec2<S> converts to the optional.
template <class T> struct TypeIdentity {
    using type = T;
};
Error parametricNonFinitePoint(std::size_t index);
Error parametricNonFiniteTangent();
Error parametricMissingTangent();
Error parametricTooFewPoints(ParametricEnds ends, std::size_t count);
Error parametricRepeatedPoint(std::size_t index, std::size_t next, SplineParameters parameters);
Error parametricIrrationalLength(std::size_t index, std::size_t next, SplineParameters parameters);
Error parametricSingular();
Error parametricOverflow();
} // namespace detail

/// The interval lengths h_i of the parameters through `points` (closed: one more, P_n → P_0).
/// Errors: a repeated consecutive point with chord or centripetal parameters
/// (InvalidInput); over Rational, a length that is not rational (NotRational).
template <class S>
Expected<std::vector<S>> splineIntervals(const std::vector<Vec2<S>>& points, SplineParameters parameters, bool closed)
{
    const std::size_t n = points.size();
    const std::size_t count = n < 2 ? 0 : (closed ? n : n - 1);
    std::vector<S> h(count, S(1));
    if (parameters == SplineParameters::Uniform)
        return h;
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t next = (i + 1) % n;
        const Vec2<S> d = points[next] - points[i];
        if (d.x == S(0) && d.y == S(0))
            return detail::parametricRepeatedPoint(i, next, parameters);
        if constexpr (std::is_floating_point_v<S>) {
            const S length = std::hypot(d.x, d.y);
            h[i] = parameters == SplineParameters::Chord ? length : std::sqrt(length);
        } else {
            std::optional<S> length = exactSqrt(S(S(d.x * d.x) + S(d.y * d.y)));
            if (length && parameters == SplineParameters::Centripetal)
                length = exactSqrt(*length);
            if (!length)
                return detail::parametricIrrationalLength(i, next, parameters);
            h[i] = *length;
        }
    }
    return h;
}

/// The knots u_0 = 0, u_{i+1} = u_i + h_i (the cumulative chord lengths for Chord).
template <class S>
Expected<std::vector<S>> splineKnots(const std::vector<Vec2<S>>& points, SplineParameters parameters, bool closed)
{
    auto h = splineIntervals(points, parameters, closed);
    if (!h)
        return h.error();
    std::vector<S> knots;
    knots.reserve(h->size() + 1);
    knots.push_back(S(0));
    for (const S& length : *h)
        knots.push_back(S(knots.back() + length));
    return knots;
}

/// The C² spline through `points` (see the file's comment). `startTangent`/`endTangent`
/// are p′(u_0) and p′(u_n), required by Clamped and ignored by the other ends.
/// Errors: TooFewPoints (fewer than parametricSplineMinimumPoints), InvalidInput (a missing
/// tangent for clamped ends; a repeated consecutive point with chord or centripetal
/// parameters; a point or tangent not finite), NotRational (an irrational length over
/// Rational), Singular, OutOfRange (overflow, doubles only).
template <class S>
Expected<ParametricSpline<S>> parametricSpline(
    const std::vector<Vec2<S>>& points, ParametricEnds ends, SplineParameters parameters,
    std::optional<Vec2<typename detail::TypeIdentity<S>::type>> startTangent = std::nullopt,
    std::optional<Vec2<typename detail::TypeIdentity<S>::type>> endTangent = std::nullopt)
{
    constexpr bool floating = std::is_floating_point_v<S>;
    const std::size_t count = points.size();
    if (count < parametricSplineMinimumPoints(ends))
        return detail::parametricTooFewPoints(ends, count);
    if (ends == ParametricEnds::Clamped && (!startTangent || !endTangent))
        return detail::parametricMissingTangent();
    if constexpr (floating) {
        for (std::size_t i = 0; i < count; ++i)
            if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
                return detail::parametricNonFinitePoint(i);
        if (ends == ParametricEnds::Clamped)
            for (const auto* t : {&*startTangent, &*endTangent})
                if (!std::isfinite(t->x) || !std::isfinite(t->y))
                    return detail::parametricNonFiniteTangent();
    }
    const bool closed = ends == ParametricEnds::Periodic;
    auto knots = splineKnots(points, parameters, closed);
    if (!knots)
        return knots.error();
    const std::size_t segmentCount = knots->size() - 1;
    std::vector<S> h(segmentCount);
    for (std::size_t i = 0; i < segmentCount; ++i)
        h[i] = S((*knots)[i + 1] - (*knots)[i]);

    ParametricSpline<S> spline;
    spline.segments.reserve(segmentCount);
    if (!closed) {
        // Def 2.3 for x(u) and for y(u) on the same knots: cubic_spline.h's banded solve.
        SplineEndConditions<S> xEnds, yEnds;
        xEnds.kind = yEnds.kind = ends == ParametricEnds::Natural   ? SplineEnds::Natural
                                  : ends == ParametricEnds::Clamped ? SplineEnds::Clamped
                                                                    : SplineEnds::NotAKnot;
        if (ends == ParametricEnds::Clamped) {
            xEnds.startSlope = startTangent->x;
            xEnds.endSlope = endTangent->x;
            yEnds.startSlope = startTangent->y;
            yEnds.endSlope = endTangent->y;
        }
        std::vector<Vec2<S>> xData(count), yData(count);
        for (std::size_t i = 0; i < count; ++i) {
            xData[i] = Vec2<S>((*knots)[i], points[i].x);
            yData[i] = Vec2<S>((*knots)[i], points[i].y);
        }
        const auto x = cubicSpline(xData, xEnds);
        if (!x)
            return x.error();
        const auto y = cubicSpline(yData, yEnds);
        if (!y)
            return y.error();
        for (std::size_t i = 0; i < segmentCount; ++i) {
            // Piece i in powers of t = u − u_i; s = t/h_i, so c_k(s) = c_k(t)·h_i^k.
            const Polynomial<S> px = x->localPiece(static_cast<int>(i)), py = y->localPiece(static_cast<int>(i));
            std::array<Vec2<S>, 4> c;
            S scale(1);
            for (int k = 0; k < 4; ++k) {
                c[static_cast<std::size_t>(k)] = Vec2<S>(S(px.coefficient(k) * scale), S(py.coefficient(k) * scale));
                scale = S(scale * h[i]);
            }
            spline.segments.push_back(c);
        }
    } else {
        // Row i: h_{i−1} M_{i−1} + 2(h_{i−1} + h_i) M_i + h_i M_{i+1} = 6(Δ_i − Δ_{i−1}), mod n.
        const std::size_t n = count;
        std::vector<S> sub(n), diag(n), super(n), rhsX(n), rhsY(n);
        std::vector<Vec2<S>> delta(n);
        for (std::size_t i = 0; i < n; ++i) {
            const Vec2<S> d = points[(i + 1) % n] - points[i];
            delta[i] = Vec2<S>(S(d.x / h[i]), S(d.y / h[i]));
        }
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t before = (i + n - 1) % n;
            sub[i] = h[before];
            diag[i] = S(S(2) * S(h[before] + h[i]));
            super[i] = h[i];
            rhsX[i] = S(S(6) * S(delta[i].x - delta[before].x));
            rhsY[i] = S(S(6) * S(delta[i].y - delta[before].y));
        }
        std::vector<std::vector<S>> rightSides;
        rightSides.push_back(std::move(rhsX));
        rightSides.push_back(std::move(rhsY));
        const auto solved = solveCyclicTridiagonal(std::move(sub), std::move(diag), std::move(super), std::move(rightSides));
        // The rows are strictly diagonally dominant (2(h_{i−1} + h_i) > h_{i−1} + h_i): in
        // floating point only an overflow fails the solve.
        if (!solved)
            return floating ? detail::parametricOverflow() : detail::parametricSingular();
        const std::vector<S>& mx = (*solved)[0];
        const std::vector<S>& my = (*solved)[1];
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t next = (i + 1) % n;
            const S h2 = S(h[i] * h[i]);
            const Vec2<S> m0(mx[i], my[i]), m1(mx[next], my[next]);
            const Vec2<S> chord = points[next] - points[i];
            std::array<Vec2<S>, 4> c;
            c[0] = points[i];
            c[1] = chord - S(h2 / S(6)) * (S(2) * m0 + m1);
            c[2] = S(h2 / S(2)) * m0;
            c[3] = S(h2 / S(6)) * (m1 - m0);
            spline.segments.push_back(c);
        }
    }
    spline.knots = std::move(*knots);

    if constexpr (floating) {
        for (const auto& c : spline.segments)
            for (const auto& v : c)
                if (!std::isfinite(v.x) || !std::isfinite(v.y))
                    return detail::parametricOverflow();
    }
    return spline;
}

/// The segments as polynomials in their local s (for bezierSegments(), sampling, drawing).
template <class S> std::vector<Vec2<Polynomial<S>>> parametricSplinePolynomials(const ParametricSpline<S>& spline)
{
    std::vector<Vec2<Polynomial<S>>> out;
    out.reserve(spline.segments.size());
    for (const auto& c : spline.segments)
        out.emplace_back(Polynomial<S>(std::vector<S>{c[0].x, c[1].x, c[2].x, c[3].x}),
                         Polynomial<S>(std::vector<S>{c[0].y, c[1].y, c[2].y, c[3].y}));
    return out;
}

extern template Expected<ParametricSpline<double>> parametricSpline(const std::vector<Vec2<double>>&, ParametricEnds,
                                                                    SplineParameters, std::optional<Vec2<double>>,
                                                                    std::optional<Vec2<double>>);
extern template Expected<ParametricSpline<Rational>> parametricSpline(const std::vector<Vec2<Rational>>&, ParametricEnds,
                                                                      SplineParameters, std::optional<Vec2<Rational>>,
                                                                      std::optional<Vec2<Rational>>);

} // namespace granota
