#pragma once
/// \file bspline_curve.h
/// A B-spline curve of degree p (beyond the thesis, issue 36; docs/bsplines.md):
///   c(u) = Σ_{i=0..n} N_{i,p}(u) P_i            (polynomial), or
///   c(u) = Σ w_i N_{i,p}(u) P_i / Σ w_i N_{i,p}(u)   (rational, NURBS),
/// on the knot vector u_0 ≤ … ≤ u_{n+p+1}, defined on the domain [u_p, u_{n+1}]. On each knot
/// span it is one polynomial (or rational) piece of degree p — the thesis's §2.3 dilemma
/// (one Bézier curve of high degree or many pieces joined by hand) answered by one object.
/// Templated on the scalar: double to draw, Rational (core/exact/rational.h) for exact values.
/// De Boor, "On calculating with B-splines", J. Approx. Theory 6 (1972); Piegl & Tiller,
/// "The NURBS Book", 2nd ed. (1997), ch. 2–4.

#include "core/base/expected.h"
#include "core/base/vec2.h"
#include "core/exact/rational.h"

#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace granota {

/// The highest degree p a B-spline may have: 1..10. Enough for any teaching example, and it
/// lets the hot path (bsplinePoint, de_boor.h) keep its p + 1 points on the stack.
constexpr int kMaxBSplineDegree = 10;

template <class S> struct BSplineCurve {
    int degree = 0;              ///< p, 1..kMaxBSplineDegree
    std::vector<Vec2<S>> points; ///< P_0..P_n, the control points (de Boor points)
    std::vector<S> weights;      ///< empty: polynomial; else n + 1 weights w_i > 0 (NURBS)
    std::vector<S> knots;        ///< u_0..u_{n+p+1}, non-decreasing

    bool rational() const { return !weights.empty(); }
    int pointCount() const { return static_cast<int>(points.size()); }
    /// u_p, where the domain starts (the first p knots only shape the first piece).
    const S& domainStart() const { return knots[static_cast<std::size_t>(degree)]; }
    /// u_{n+1}, where the domain ends.
    const S& domainEnd() const { return knots[points.size()]; }
};

/// How a scalar is written in a message: "0.25" for a double, "1/4" for a Rational.
std::string bsplineNumberText(double v);
std::string bsplineNumberText(const Rational& v);
/// The same value as an argument of a translated message (message_id.h): a number the GUI
/// writes with its decimal sign, or a fraction's text.
MessageArg bsplineNumberArg(double v);
MessageArg bsplineNumberArg(const Rational& v);

namespace detail {
template <class S> bool finiteScalar(const S& v)
{
    if constexpr (std::is_floating_point_v<S>)
        return std::isfinite(v);
    else
        return true; // exact numbers are always finite
}
} // namespace detail

/// Whether `c` is a B-spline every algorithm of this folder accepts; the error names the
/// first fault found, in this order: a degree outside 1..10, fewer than p + 1 points, a knot
/// count other than n + p + 2, a weight count other than 0 or n + 1, a value that is not
/// finite, knots that decrease, a knot repeated more than p times inside (p + 1 at the two
/// ends), an empty domain [u_p, u_{n+1}], a weight ≤ 0.
template <class S> Expected<void> checkBSpline(const BSplineCurve<S>& c)
{
    const auto num = [](std::size_t v) { return numberArg(static_cast<double>(v)); };
    const auto idx = [](std::size_t i) { return std::to_string(i); };
    const int p = c.degree;
    if (p < 1 || p > kMaxBSplineDegree)
        return makeError(ErrorCode::OutOfRange,
                         "the degree of a B-spline must be from 1 to " + std::to_string(kMaxBSplineDegree) + ", not " +
                             std::to_string(p),
                         MessageId::BSplineDegreeOutOfRange, {numberArg(p), numberArg(kMaxBSplineDegree)});
    const auto P = static_cast<std::size_t>(p);
    const std::size_t count = c.points.size();
    if (count < P + 1)
        return makeError(ErrorCode::TooFewPoints,
                         "a B-spline of degree " + idx(P) + " needs at least " + idx(P + 1) + " control points, not " +
                             idx(count),
                         MessageId::BSplineTooFewPoints, {num(P), num(P + 1), num(count)});
    const std::size_t knotCount = count + P + 1; // n + p + 2
    if (c.knots.size() != knotCount)
        return makeError(ErrorCode::InvalidInput,
                         "a B-spline of degree " + idx(P) + " with " + idx(count) +
                             " control points needs n + p + 2 = " + idx(knotCount) + " knots, not " + idx(c.knots.size()),
                         MessageId::BSplineKnotCount, {num(P), num(count), num(knotCount), num(c.knots.size())});
    if (!c.weights.empty() && c.weights.size() != count)
        return makeError(ErrorCode::InvalidInput,
                         "a rational B-spline needs one weight per control point: " + idx(count) + " weights, not " +
                             idx(c.weights.size()),
                         MessageId::BSplineWeightCount, {num(count), num(c.weights.size())});
    const auto notFinite = [](const std::string& what, const std::string& symbol) {
        return makeError(ErrorCode::InvalidInput, what + " " + symbol + " is not finite", MessageId::BSplineNotFinite,
                         {textArg(symbol)});
    };
    for (std::size_t i = 0; i < count; ++i)
        if (!detail::finiteScalar(c.points[i].x) || !detail::finiteScalar(c.points[i].y))
            return notFinite("control point", "P_" + idx(i));
    for (std::size_t i = 0; i < c.weights.size(); ++i)
        if (!detail::finiteScalar(c.weights[i]))
            return notFinite("weight", "w_" + idx(i));
    for (std::size_t i = 0; i < knotCount; ++i)
        if (!detail::finiteScalar(c.knots[i]))
            return notFinite("knot", "u_" + idx(i));
    for (std::size_t i = 0; i + 1 < knotCount; ++i)
        if (c.knots[i + 1] < c.knots[i])
            return makeError(ErrorCode::NotIncreasing,
                             "the knots must not decrease: u_" + idx(i) + " = " + bsplineNumberText(c.knots[i]) + " > u_" +
                                 idx(i + 1) + " = " + bsplineNumberText(c.knots[i + 1]),
                             MessageId::BSplineKnotsDecrease,
                             {num(i), bsplineNumberArg(c.knots[i]), num(i + 1), bsplineNumberArg(c.knots[i + 1])});
    // Multiplicity: p inside keeps the curve continuous (C^{p−m} at a knot of multiplicity m);
    // p + 1 at an end clamps the curve to its end point.
    for (std::size_t i = 0; i < knotCount;) {
        std::size_t j = i;
        while (j < knotCount && c.knots[j] == c.knots[i])
            ++j;
        const std::size_t m = j - i;
        const bool end = i == 0 || j == knotCount;
        const std::size_t allowed = end ? P + 1 : P;
        if (m > allowed)
            return makeError(ErrorCode::InvalidInput,
                             "the knot " + bsplineNumberText(c.knots[i]) + " is repeated " + idx(m) +
                                 " times; a B-spline of degree " + idx(P) + " allows at most " + idx(allowed) +
                                 (end ? " at an end" : " inside"),
                             end ? MessageId::BSplineEndMultiplicity : MessageId::BSplineInteriorMultiplicity,
                             {bsplineNumberArg(c.knots[i]), num(m), num(P), num(allowed)});
        i = j;
    }
    if (!(c.domainStart() < c.domainEnd()))
        return makeError(ErrorCode::InvalidInput,
                         "the domain [u_p, u_{n+1}] = [" + bsplineNumberText(c.domainStart()) + ", " +
                             bsplineNumberText(c.domainEnd()) + "] is empty",
                         MessageId::BSplineEmptyDomain, {bsplineNumberArg(c.domainStart()), bsplineNumberArg(c.domainEnd())});
    for (std::size_t i = 0; i < c.weights.size(); ++i)
        if (!(c.weights[i] > S(0)))
            return makeError(ErrorCode::OutOfRange,
                             "weight w_" + idx(i) + " = " + bsplineNumberText(c.weights[i]) + " must be positive",
                             MessageId::BSplineWeightNotPositive, {num(i), bsplineNumberArg(c.weights[i])});
    return {};
}

} // namespace granota
