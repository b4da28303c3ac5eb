#pragma once
/// \file knot_vector.h
/// Knot vectors u_0 ≤ … ≤ u_{n+p+1} of a B-spline of degree p with n + 1 control points:
/// the three presets, the span a parameter falls in (Piegl & Tiller A2.1) and the
/// multiplicity of a knot.

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <vector>

namespace granota {

enum class KnotPreset {
    Clamped, ///< p + 1 zeros, interior i/(n − p + 1), p + 1 ones: the curve starts at P_0, ends at P_n
    Uniform, ///< 0, 1, …, n + p + 1: every piece the same shape, the ends float
    Bezier,  ///< p + 1 zeros, p + 1 ones, only when n = p: exactly the Bézier curve (Def 2.4)
};

/// The knots of `preset` for `pointCount` = n + 1 points and degree p ≥ 1; empty when the
/// preset does not exist for these counts (fewer than p + 1 points; Bezier with n ≠ p), which
/// checkBSpline then refuses with its message.
template <class S> std::vector<S> presetKnots(KnotPreset preset, int pointCount, int degree)
{
    const int n = pointCount - 1, p = degree;
    if (p < 1 || n < p)
        return {};
    std::vector<S> knots;
    knots.reserve(static_cast<std::size_t>(n + p + 2));
    switch (preset) {
    case KnotPreset::Uniform:
        for (int i = 0; i <= n + p + 1; ++i)
            knots.push_back(S(i));
        break;
    case KnotPreset::Bezier:
        if (n != p)
            return {};
        [[fallthrough]]; // n = p: the clamped vector has no interior knot
    case KnotPreset::Clamped:
        for (int i = 0; i <= p; ++i)
            knots.push_back(S(0));
        for (int i = 1; i <= n - p; ++i)
            knots.push_back(S(S(i) / S(n - p + 1)));
        for (int i = 0; i <= p; ++i)
            knots.push_back(S(1));
        break;
    }
    return knots;
}

/// The span k with u_k ≤ u < u_{k+1}, p ≤ k ≤ n, for `pointCount` = n + 1 (Piegl & Tiller
/// A2.1, by bisection). u = u_{n+1} (the domain's end) gives the last non-empty span, so that
/// the curve is closed on the right; u below u_p the first, u above u_{n+1} the last (the end
/// pieces extended). The knots must pass checkBSpline (a non-empty domain).
template <class S> int findSpan(const std::vector<S>& knots, int degree, int pointCount, const S& u)
{
    const int p = degree, n = pointCount - 1;
    assert(p >= 0 && n >= p && knots.size() == static_cast<std::size_t>(n + p + 2));
    const auto first = knots.begin() + p;
    const auto last = knots.begin() + (n + 1); // u_{n+1}
    assert(*first < *last);
    if (!(u < *last)) { // the end of the domain or beyond: the last span that is not empty
        int k = n;
        while (k > p && !(knots[static_cast<std::size_t>(k)] < knots[static_cast<std::size_t>(k + 1)]))
            --k;
        return k;
    }
    const S& v = u < *first ? *first : u;
    // The first knot in [u_p, u_{n+1}] greater than v; the span starts just before it.
    const auto above = std::upper_bound(first, last + 1, v);
    return static_cast<int>(above - knots.begin()) - 1;
}

/// How many knots equal u (0 when u is no knot).
template <class S> int knotMultiplicity(const std::vector<S>& knots, const S& u)
{
    const auto range = std::equal_range(knots.begin(), knots.end(), u);
    return static_cast<int>(range.second - range.first);
}

} // namespace granota
