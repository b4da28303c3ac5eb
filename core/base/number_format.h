#pragma once
/// \file number_format.h
/// How Granota writes every number it prints: in the CLI's CSV and JSON, in the exact
/// panels, in exports and in the polynomials of polynomial_text.h. Always a point for the
/// decimals, whatever the locale (docs/numbers-and-locales.md).

#include <string>

namespace granota {

/// Shortest text that reads back as the same double ("0.1", "1e-09", "-3").
/// Every number formatter here ignores the C locale (LC_NUMERIC): a point, always.
std::string formatDouble(double v);
/// For files a person reads (the window's CSV exports): the shortest text of at most 15
/// significant digits that reads back as `v`, else `v` rounded to 15 digits. A typed value
/// (never more than 15 digits) comes back as typed, and a computed one loses its binary noise
/// (0.1 + 0.2 → "0.3", not "0.30000000000000004"); never "-0".
std::string formatReadable(double v);
/// `digits` significant digits, as printf's "%.*g" writes them in the C locale ("1.5e-08").
std::string formatSignificant(double v, int digits);
/// `decimals` digits after the point, as printf's "%.*f" writes them in the C locale.
std::string formatFixed(double v, int decimals);

} // namespace granota
