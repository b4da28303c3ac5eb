#pragma once
/// \file rational.h
/// Exact rational numbers (GMP's mpq_class), so that rational input reproduces the
/// thesis's fractions exactly: the tables of Ex 2.2–2.6, the matrices of Ex 2.7–2.8 and
/// the segment polynomials of Ex 2.11–2.13.

#include "core/base/expected.h"
#include "core/base/vec2.h"

#include <gmpxx.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace granota {

using Rational = mpq_class;
using RPoint = Vec2<Rational>;

/// Parses an exact rational from text: an integer ("-3"), a fraction ("7/2", "-1/53"),
/// or a decimal with optional exponent ("0.25", "1.5e-3", "-2E4") — a decimal is the
/// rational it denotes (0.1 = 1/10, not the nearest double). nullopt for anything else,
/// including "nan", "inf", a zero denominator or an exponent beyond ±10000.
std::optional<Rational> parseRational(std::string_view text);

/// When parseRational refuses `text` only because its exponent is beyond ±10000 — a number
/// written right that no computation could hold — what a message says after the number:
/// "is too large (the largest double is about 1.8e308)" (1e1000000) or "is too close to
/// zero to read (exponents go down to -10000)" (1e-1000000); nullopt otherwise.
std::optional<std::string> numberBeyondReach(std::string_view text);

/// "p" for integers, "p/q" otherwise, always in lowest terms.
std::string toString(const Rational& q);

/// The exact rational value of a finite double (every double is a dyadic rational).
Rational exactRational(double d);

/// sqrt(q) when it is rational (numerator and denominator perfect squares), else nullopt.
std::optional<Rational> exactSqrt(const Rational& q);

/// p/q in lowest terms. Use this rather than Rational(p, q): GMP's two-argument
/// constructor does not canonicalize, and comparisons of non-canonical values are wrong.
inline Rational frac(long p, long q)
{
    Rational r(p, q);
    r.canonicalize();
    return r;
}

/// The double nearest to q (ties to even), as strtod reads the same decimal: "0.1" gives
/// 0.1, and a double written shortest reads back as itself; ±infinity beyond the largest
/// double. (GMP's get_d() truncates towards zero instead: 1/10 would become
/// 0.09999999999999999, and each retyping of that one step smaller.)
double toDouble(const Rational& q);
inline double toDouble(double d) { return d; }
inline double toDouble(long double d) { return static_cast<double>(d); }

/// Converts a point list of any scalar to doubles / to exact rationals.
std::vector<Point> toDouble(const std::vector<RPoint>& points);
std::vector<RPoint> toRational(const std::vector<Point>& points);

/// Binomial coefficient C(n, k) exactly (0 outside 0 <= k <= n).
Rational binomial(int n, int k);

} // namespace granota
