#pragma once
/// \file square_root.h
/// Square roots of rationals in simplest radical form, a√b with a rational and b a
/// square-free integer: the chord lengths of Ex 2.9 and Ex 2.10 are d_1 = √10, d_2 = √10,
/// d_3 = √32 = 4√2 and d_4 = √98 = 7√2 (the thesis writes √85, from its slip (1 − 7)).

#include "core/exact/rational.h"

#include <optional>
#include <string>
#include <vector>

namespace granota {

/// √q = coefficient · √radicand, with radicand ≥ 1 square-free (1 when √q is rational).
struct SimplifiedSquareRoot {
    Rational coefficient; ///< a ≥ 0
    mpz_class radicand;   ///< b ≥ 1, no square factor
};

/// √q in simplest form, or nullopt when q < 0 or its numerator or denominator is too
/// large to factor quickly (beyond 10^18: trial division up to 10^6).
std::optional<SimplifiedSquareRoot> simplifySquareRoot(const Rational& q);

/// "7√2", "√10", "3/2", "√6/2" (a rational coefficient p/q is written p√b/q), "0".
std::string toString(const SimplifiedSquareRoot& r);

/// The chord lengths d_j = |Q_j − Q_{j−1}|, j = 1..k, of §2.1.3 in simplest radical form
/// (Ex 2.9: √10, √10, 4√2, 7√2); an entry is nullopt when it cannot be simplified quickly.
std::vector<std::optional<SimplifiedSquareRoot>> exactChordLengths(const std::vector<RPoint>& q);

} // namespace granota
