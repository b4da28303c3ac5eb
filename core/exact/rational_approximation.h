#pragma once
/// \file rational_approximation.h
/// Recovering the fraction a user meant from a double: points typed as 1/3 or loaded from
/// Ex 2.7 are stored as doubles by the editors, but the exact panels (docs/tabs.md) want
/// 1/3, not the dyadic rational 6004799503160661/18014398509481984.

#include "core/exact/rational.h"

#include <optional>
#include <vector>

namespace granota {

/// The fraction p/q with q ≤ maxDenominator whose nearest double is exactly `d`
/// (continued fractions), or nullopt when there is none (d not finite, or |d| > 1e15).
std::optional<Rational> smallRational(double d, long maxDenominator = 100000);

/// The value a stored coordinate stands for: the small fraction it was typed or loaded as
/// (smallRational with the same bound), else the double's own exact value (exactRational).
/// Finite `d` only.
Rational meantRational(double d, long maxDenominator = 100000);

/// Every point as small fractions, or nullopt if one coordinate has none.
std::optional<std::vector<RPoint>> smallRationalPoints(const std::vector<Point>& points, long maxDenominator = 100000);

} // namespace granota
