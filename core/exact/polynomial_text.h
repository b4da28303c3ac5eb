#pragma once
/// \file polynomial_text.h
/// Polynomials written as the thesis writes them: ascending powers, "2 - 6t - t^2"
/// (Ex 2.2), exact fractions "7/2 t^3". Used by the CLI, the exact side panels and tests.

#include "core/exact/polynomial.h"
#include "core/exact/rational.h"
#include "core/base/number_format.h"

#include <optional>
#include <string>
#include <string_view>

namespace granota {

/// Ascending powers of `var`, e.g. "2 - 6t - t^2", "-1/2t + t^2 - 1/2t^3"; "0" for zero.
std::string toText(const Polynomial<Rational>& p, const std::string& var = "t");
/// The same for doubles (shortest round-trip formatting of each coefficient).
std::string toText(const Polynomial<double>& p, const std::string& var = "t");
/// "(x(t), y(t))".
std::string toText(const Vec2<Polynomial<Rational>>& p, const std::string& var = "t");
std::string toText(const Vec2<Polynomial<double>>& p, const std::string& var = "t");

/// Reads the text form back: a sum of terms "[±][coefficient][ ][var[^k]]", coefficients
/// integers, fractions or decimals ("2 - 6t - t^2", "-7/2 s^3 + 6s^2", "t^4"), in any order,
/// repeated powers added. nullopt for anything else.
std::optional<Polynomial<Rational>> parsePolynomial(std::string_view text, char var = 't');

} // namespace granota
