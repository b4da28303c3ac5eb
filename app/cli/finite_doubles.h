#pragma once
/// \file finite_doubles.h
/// Where granota-cli's exact input becomes doubles, and where its doubles are printed. A
/// value beyond the largest double (±1.8e308), or the NaN an overflow leaves behind
/// (∞ − ∞), is refused by name — exit 2 — never printed as inf, nan or null. The same
/// approach as the Catmull-Rom segments and the least-squares fit, which check every
/// number they return with std::isfinite; here in one place for every command.

#include "core/base/expected.h"
#include "core/io/json.h"
#include "core/exact/rational.h"

#include <optional>
#include <string>
#include <vector>

namespace granota::cli {

/// "WHAT is too large for a double (beyond ±1.8e308)", and when `exactAvailable`, that
/// --exact computes it with exact fractions, which do not overflow.
Error tooLargeForDouble(const std::string& what, bool exactAvailable);

/// "= 7/2", or "≈ 1e400" for a number too long to show: for messages about `q`.
std::string valueText(const Rational& q);

/// `q` as the nearest double, or tooLargeForDouble(what) when that is infinite.
Expected<double> finiteDouble(const Rational& q, const std::string& what, bool exactAvailable);

/// Every point as doubles, or an error naming the first coordinate too large ("point 1: x").
Expected<std::vector<Point>> finiteDoubles(const std::vector<RPoint>& points, bool exactAvailable);

/// Where `answer` holds a number that is not finite, as --json would name it
/// ("tangent[0]", "levels[2][0][1]"); nullopt when every number is finite.
std::optional<std::string> nonFiniteNumber(const Json& answer);

} // namespace granota::cli
