#pragma once
/// \file number_column.h
/// How a column of numbers is written: one notation for the whole column, never "-9/5" above
/// "1.0000000000000007" (docs/numbers-and-locales.md). Fractions when every entry is a small
/// fraction (denominator ≤ kColumnFractionDenominator) and one of them has no finite decimal
/// expansion (1/3): then 2, 5/4 and 1/3. Otherwise decimals for every entry, each the shortest
/// text that reads back as its double (formatDouble): a typed 0.05688 is "0.05688", 1.25 is
/// "1.25", and a 1/3 among dragged values is "0.3333333333333333".

#include "core/exact/exact_point.h"

#include <string>
#include <vector>

namespace granota {

/// The largest denominator a column writes as a fraction (1/999 yes, 1/1024 as 0.0009765625).
constexpr long kColumnFractionDenominator = 1000;

enum class ColumnNotation { Decimals, Fractions };

/// The notation of a column holding `values` (finite or not; a non-finite one means decimals).
ColumnNotation columnNotation(const std::vector<double>& values);
/// One entry of a column in `notation`, in the C form ("-9/5", "0.05688"; never the locale's).
std::string columnEntry(double v, ColumnNotation notation);

/// The same for values that keep their exact form (exact_point.h; nullopt: the double alone).
/// Fractions when every entry has an exact form of denominator ≤ kColumnFractionDenominator and
/// one of them repeats; else decimals.
ColumnNotation columnNotation(const std::vector<ExactCoordinate>& exact);
/// One entry: in fractions its exact form; in decimals its finite decimal expansion when it has
/// one (kExactDecimalDigits at most: 0.1 nudged by 0.01 is "0.11", as typed), a repeating exact
/// value to 16 significant digits ("0.3333333333333333": never the 17th digit that tells only
/// the binary rounding), and a value without an exact form as columnEntry(v, Decimals).
std::string columnEntry(const ExactCoordinate& exact, double v, ColumnNotation notation);

} // namespace granota
