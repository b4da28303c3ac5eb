#pragma once
/// \file rational_points.h
/// Control points with rational coordinates for the exact tests: small integers written out,
/// and random small fractions from a seeded generator.
#include "core/exact/rational.h"

#include <initializer_list>
#include <random>
#include <utility>
#include <vector>

namespace granota::testing {

/// {{0, 0}, {1, 2}} → the points (0, 0), (1, 2) as rationals.
inline std::vector<RPoint> pts(std::initializer_list<std::pair<int, int>> list)
{
    std::vector<RPoint> out;
    for (auto [x, y] : list)
        out.emplace_back(Rational(x), Rational(y));
    return out;
}

/// n + 1 points with coordinates a/b, a ∈ [−30, 30], b ∈ [1, 7].
inline std::vector<RPoint> randomRational(std::mt19937& rng, int n)
{
    std::uniform_int_distribution<int> num(-30, 30), den(1, 7);
    std::vector<RPoint> p;
    for (int i = 0; i <= n; ++i)
        p.emplace_back(frac(num(rng), den(rng)), frac(num(rng), den(rng)));
    return p;
}

} // namespace granota::testing
