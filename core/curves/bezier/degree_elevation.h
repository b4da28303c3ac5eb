#pragma once
/// \file degree_elevation.h
/// Degree elevation: the same curve written with one control point more,
///   Q_0 = P_0,  Q_i = (i/(n+1)) P_{i−1} + (1 − i/(n+1)) P_i,  Q_{n+1} = P_n.
/// (Beyond the thesis, docs/tabs.md; Farin, "Curves and Surfaces for CAGD", §6.1.)

#include "core/base/vec2.h"

#include <cassert>
#include <vector>

namespace granota {

template <class S> std::vector<Vec2<S>> elevateDegree(const std::vector<Vec2<S>>& points)
{
    assert(!points.empty());
    const int n = static_cast<int>(points.size()) - 1;
    std::vector<Vec2<S>> q;
    q.reserve(points.size() + 1);
    q.push_back(points.front());
    for (int i = 1; i <= n; ++i) {
        const S a = S(S(i) / S(n + 1));
        const S b = S(S(1) - a);
        q.push_back(a * points[static_cast<std::size_t>(i - 1)] + b * points[static_cast<std::size_t>(i)]);
    }
    q.push_back(points.back());
    return q;
}

} // namespace granota
