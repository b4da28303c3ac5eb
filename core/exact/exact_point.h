#pragma once
/// \file exact_point.h
/// A point's exact form kept beside its double: a point typed as 1/3 or 0.1, loaded from a
/// document, or moved by a round nudge step keeps the fraction it is (docs/numbers-and-locales.md),
/// so that the tables, the exact panels and the CSV exports print that value and never the
/// binary noise of its double. A coordinate without an exact form (a point dragged along the
/// curve to where the mouse happened to be) holds nullopt, and its double is all there is.

#include "core/exact/rational.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace granota {

/// A coordinate's exact value, or nullopt when it has none.
using ExactCoordinate = std::optional<Rational>;

struct ExactPoint {
    ExactCoordinate x, y;
};
bool operator==(const ExactPoint& a, const ExactPoint& b);
inline bool operator!=(const ExactPoint& a, const ExactPoint& b) { return !(a == b); }

/// A list of more points keeps no exact forms (an empty list of them): it is data (an imported set of up to
/// kMaxDataPoints), the exact panels list far fewer, and guessing fractions back costs about
/// 10 µs a coordinate.
constexpr std::size_t kExactFormsUpTo = 2000;

/// The exact form of a point given only as doubles (an example written in code, a test): each
/// coordinate the small fraction its double was written as (smallRational, the default bound),
/// else nullopt.
ExactPoint writtenExact(const Point& p);
/// The same for a list (empty beyond kExactFormsUpTo points: none has an exact form).
std::vector<ExactPoint> writtenExact(const std::vector<Point>& points);
/// Exact points with exact forms for every coordinate (an example's fractions, a file's values;
/// empty beyond kExactFormsUpTo points).
std::vector<ExactPoint> exactForms(const std::vector<RPoint>& points);

/// Every point exactly, or nullopt if a coordinate has no exact form (or `points` has other
/// than `count` entries: none has).
std::optional<std::vector<RPoint>> allExact(const std::vector<ExactPoint>& points, std::size_t count);
/// The value to compute with exactly: the exact form, else the double's own value (exactRational).
/// `d` finite.
Rational exactOr(const ExactCoordinate& q, double d);

/// Whether q has a finite decimal expansion (its denominator is 2^a 5^b).
bool terminates(const Rational& q);
/// q's finite decimal expansion ("0.1", "-2.072", "3") when it has one of at most
/// `maxSignificant` significant digits; nullopt otherwise.
std::optional<std::string> terminatingDecimal(const Rational& q, int maxSignificant);
/// q rounded to `digits` significant digits (a half away from zero), in the C form without
/// trailing zeros: 1/3 to 16 is "0.3333333333333333", 54/6125 is "0.008816326530612245" (its
/// double's own digits end in …244). Written as formatSignificant writes the double beyond
/// 10^-5 … 10^17.
std::string roundedDecimal(const Rational& q, int digits);
/// Significant digits in which every exact value is written when its decimal expansion is
/// finite (every double's shortest text fits: a typed "1.0000000000000007" comes back as typed).
constexpr int kExactDecimalDigits = 17;

/// How a file a person reads (the window's CSV exports) writes a coordinate: its exact value's
/// finite decimal expansion when it has one (kExactDecimalDigits at most), else formatReadable
/// of the double (at most 15 significant digits, no binary noise).
std::string readableExact(const ExactCoordinate& q, double d);

} // namespace granota
