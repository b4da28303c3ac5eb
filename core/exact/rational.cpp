#include "core/exact/rational.h"

#include "core/base/text.h"

#include <cctype>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

namespace granota {

namespace {

bool allDigits(std::string_view s)
{
    if (s.empty())
        return false;
    for (char c : s)
        if (!std::isdigit(static_cast<unsigned char>(c)))
            return false;
    return true;
}

// Largest |exponent| accepted in "1e…": keeps a typo like 1e999999999 from eating memory.
constexpr long kMaxExponent = 10000;

std::optional<Rational> parseDecimal(std::string_view s)
{
    bool negative = false;
    if (!s.empty() && (s.front() == '+' || s.front() == '-')) {
        negative = s.front() == '-';
        s.remove_prefix(1);
    }
    long exponent = 0;
    if (auto e = s.find_first_of("eE"); e != std::string_view::npos) {
        std::string_view exp = s.substr(e + 1);
        s = s.substr(0, e);
        bool expNegative = false;
        if (!exp.empty() && (exp.front() == '+' || exp.front() == '-')) {
            expNegative = exp.front() == '-';
            exp.remove_prefix(1);
        }
        if (!allDigits(exp) || exp.size() > 6)
            return std::nullopt;
        std::from_chars(exp.data(), exp.data() + exp.size(), exponent); // at most 6 digits
        if (exponent > kMaxExponent)
            return std::nullopt;
        if (expNegative)
            exponent = -exponent;
    }
    std::string_view intPart = s, fracPart;
    if (auto dot = s.find('.'); dot != std::string_view::npos) {
        intPart = s.substr(0, dot);
        fracPart = s.substr(dot + 1);
    }
    if (intPart.empty() && fracPart.empty())
        return std::nullopt;
    if ((!intPart.empty() && !allDigits(intPart)) || (!fracPart.empty() && !allDigits(fracPart)))
        return std::nullopt;
    std::string digits = std::string(intPart) + std::string(fracPart);
    mpz_class numerator(digits, 10);
    exponent -= static_cast<long>(fracPart.size());
    mpz_class scale;
    mpz_ui_pow_ui(scale.get_mpz_t(), 10, static_cast<unsigned long>(std::labs(exponent)));
    Rational q = exponent >= 0 ? Rational(numerator * scale) : Rational(numerator, scale);
    q.canonicalize();
    if (negative)
        q = -q;
    return q;
}

} // namespace

std::optional<Rational> parseRational(std::string_view text)
{
    std::string_view s = trim(text);
    if (s.empty())
        return std::nullopt;
    if (auto slash = s.find('/'); slash != std::string_view::npos) {
        std::string_view num = trim(s.substr(0, slash));
        std::string_view den = trim(s.substr(slash + 1));
        bool negative = false;
        if (!num.empty() && (num.front() == '+' || num.front() == '-')) {
            negative = num.front() == '-';
            num.remove_prefix(1);
        }
        if (!allDigits(num) || !allDigits(den))
            return std::nullopt;
        mpz_class n(std::string(num), 10), d(std::string(den), 10);
        if (d == 0)
            return std::nullopt;
        Rational q(n, d);
        q.canonicalize();
        return negative ? Rational(-q) : q;
    }
    return parseDecimal(s);
}

std::optional<std::string> numberBeyondReach(std::string_view text)
{
    std::string_view s = trim(text);
    if (!s.empty() && (s.front() == '+' || s.front() == '-'))
        s.remove_prefix(1);
    const std::size_t e = s.find_first_of("eE");
    if (e == std::string_view::npos)
        return std::nullopt;
    std::string_view mantissa = s.substr(0, e), exponent = s.substr(e + 1);
    const bool negativeExponent = !exponent.empty() && exponent.front() == '-';
    if (!exponent.empty() && (exponent.front() == '+' || exponent.front() == '-'))
        exponent.remove_prefix(1);
    const std::size_t dot = mantissa.find('.');
    const std::string_view intPart = mantissa.substr(0, dot);
    const std::string_view fracPart = dot == std::string_view::npos ? std::string_view() : mantissa.substr(dot + 1);
    if ((intPart.empty() && fracPart.empty()) || (!intPart.empty() && !allDigits(intPart)) ||
        (!fracPart.empty() && !allDigits(fracPart)) || !allDigits(exponent) || parseRational(text))
        return std::nullopt; // not the form of a decimal, or read after all
    if (mantissa.find_first_not_of("0.") == std::string_view::npos)
        return std::nullopt; // zero: "too large" would be wrong
    if (negativeExponent)
        return std::string("is too close to zero to read (exponents go down to -") + std::to_string(kMaxExponent) + ")";
    return std::string("is too large (the largest double is about 1.8e308)");
}

std::string toString(const Rational& q)
{
    if (q.get_den() == 1)
        return q.get_num().get_str();
    return q.get_num().get_str() + "/" + q.get_den().get_str();
}

Rational exactRational(double d)
{
    assert(std::isfinite(d));
    Rational q(d); // GMP converts a double exactly
    q.canonicalize();
    return q;
}

std::optional<Rational> exactSqrt(const Rational& q)
{
    if (q < 0)
        return std::nullopt;
    mpz_class n = q.get_num(), d = q.get_den();
    if (!mpz_perfect_square_p(n.get_mpz_t()) || !mpz_perfect_square_p(d.get_mpz_t()))
        return std::nullopt;
    mpz_class rn, rd;
    mpz_sqrt(rn.get_mpz_t(), n.get_mpz_t());
    mpz_sqrt(rd.get_mpz_t(), d.get_mpz_t());
    Rational r(rn, rd);
    r.canonicalize();
    return r;
}

double toDouble(const Rational& q)
{
    const double truncated = q.get_d(); // towards zero; ±infinity from 2^1024 on
    if (!std::isfinite(truncated) || exactRational(truncated) == q)
        return truncated;
    const double away = std::nextafter(truncated, q > 0 ? HUGE_VAL : -HUGE_VAL);
    if (!std::isfinite(away)) {
        // Beyond the largest double: infinity from halfway to the next power of two on.
        static const Rational halfway = exactRational(DBL_MAX) + exactRational(std::ldexp(1.0, 970));
        return abs(q) >= halfway ? away : truncated;
    }
    const Rational below = abs(q - exactRational(truncated)), above = abs(exactRational(away) - q);
    double nearest = below < above ? truncated : away;
    if (below == above) {
        // A tie: the one whose last bit of mantissa is 0.
        std::uint64_t bits = 0;
        std::memcpy(&bits, &truncated, sizeof bits);
        nearest = (bits & 1) == 0 ? truncated : away;
    }
    return nearest == 0 ? std::copysign(0.0, q < 0 ? -1.0 : 1.0) : nearest; // -1e-400 is -0, as strtod reads it
}

std::vector<Point> toDouble(const std::vector<RPoint>& points)
{
    std::vector<Point> out;
    out.reserve(points.size());
    for (const RPoint& p : points)
        out.emplace_back(toDouble(p.x), toDouble(p.y));
    return out;
}

std::vector<RPoint> toRational(const std::vector<Point>& points)
{
    std::vector<RPoint> out;
    out.reserve(points.size());
    for (const Point& p : points)
        out.emplace_back(exactRational(p.x), exactRational(p.y));
    return out;
}

Rational binomial(int n, int k)
{
    if (k < 0 || k > n || n < 0)
        return Rational(0);
    mpz_class c;
    mpz_bin_uiui(c.get_mpz_t(), static_cast<unsigned long>(n), static_cast<unsigned long>(k));
    return Rational(c);
}

} // namespace granota
