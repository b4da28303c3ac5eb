#pragma once
/// \file de_casteljau.h
/// De Casteljau's algorithm (Def 2.4) with every level kept:
///   P_i^0(t) = P_i,   P_i^r(t) = (1 − t) P_i^{r−1}(t) + t P_{i+1}^{r−1}(t),
/// and c(t) = P_0^n(t). Each level is computed once from the previous one — O(n²) work,
/// never the exponential recursion. Templated on the scalar S:
///  - double / long double: the point c(t) and the construction drawn in the tab;
///  - Rational: exact values at rational t;
///  - Polynomial<Rational> with t = Polynomial::identity(): the symbolic tables of
///    Ex 2.2 and Ex 2.3, every P_i^r(t) as a polynomial in t.

#include "core/base/vec2.h"

#include <cassert>
#include <vector>

namespace granota {

template <class S> struct DeCasteljauTable {
    /// levels[r][i] = P_i^r(t), for r = 0..n and i = 0..n−r (Def 2.4).
    std::vector<std::vector<Vec2<S>>> levels;

    int degree() const { return static_cast<int>(levels.size()) - 1; }
    /// c(t) = P_0^n(t).
    const Vec2<S>& point() const { return levels.back().front(); }
    /// The tangent c′(t) = n (P_1^{n−1}(t) − P_0^{n−1}(t)), read off the last level but one.
    Vec2<S> tangent() const
    {
        const int n = degree();
        if (n < 1)
            return Vec2<S>(S(0), S(0));
        const auto& last = levels[static_cast<std::size_t>(n - 1)];
        return S(n) * (last[1] - last[0]);
    }
    /// Control points of c restricted to [0, t]: the triangle's left edge P_0^0 … P_0^n.
    std::vector<Vec2<S>> leftHalf() const
    {
        std::vector<Vec2<S>> out;
        for (const auto& level : levels)
            out.push_back(level.front());
        return out;
    }
    /// Control points of c restricted to [t, 1]: the right edge P_0^n, P_1^{n−1}, …, P_n^0.
    std::vector<Vec2<S>> rightHalf() const
    {
        std::vector<Vec2<S>> out;
        for (auto it = levels.rbegin(); it != levels.rend(); ++it)
            out.push_back(it->back());
        return out;
    }
};

/// Def 2.4. `points` must not be empty.
template <class S> DeCasteljauTable<S> deCasteljau(const std::vector<Vec2<S>>& points, const S& t)
{
    assert(!points.empty());
    DeCasteljauTable<S> table;
    table.levels.reserve(points.size());
    table.levels.push_back(points);
    const S u = S(S(1) - t);
    for (std::size_t r = 1; r < points.size(); ++r) {
        const auto& prev = table.levels.back();
        std::vector<Vec2<S>> level;
        level.reserve(prev.size() - 1);
        for (std::size_t i = 0; i + 1 < prev.size(); ++i)
            level.push_back(u * prev[i] + t * prev[i + 1]);
        table.levels.push_back(std::move(level));
    }
    return table;
}

/// c(t) alone, overwriting `work` (the control points on entry): the hot path for
/// sampling, with no allocation.
template <class S> Vec2<S> deCasteljauInPlace(std::vector<Vec2<S>>& work, const S& t)
{
    assert(!work.empty());
    const S u = S(S(1) - t);
    for (std::size_t m = work.size(); m > 1; --m)
        for (std::size_t i = 0; i + 1 < m; ++i)
            work[i] = u * work[i] + t * work[i + 1];
    return work.front();
}

/// c(t) alone.
template <class S> Vec2<S> deCasteljauPoint(std::vector<Vec2<S>> controlPoints, const S& t)
{
    return deCasteljauInPlace(controlPoints, t);
}

/// `samples` points c(j/(samples−1)), j = 0..samples−1 (samples ≥ 2): the Matlab
/// De_Casteljau(P, part) with part = samples − 1.
std::vector<Point> sampleBezier(const std::vector<Point>& controlPoints, int samples);

} // namespace granota
