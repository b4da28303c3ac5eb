#include "core/exact/polynomial_text.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

namespace granota {

namespace {

template <class S, class IsNeg, class Abs, class IsOne, class Fmt>
std::string polyText(const Polynomial<S>& p, const std::string& var, IsNeg isNeg, Abs abs, IsOne isOne, Fmt fmt)
{
    if (p.isZero())
        return "0";
    std::ostringstream out;
    bool first = true;
    for (int k = 0; k <= p.degree(); ++k) {
        const S c = p.coefficient(k);
        if (c == S(0))
            continue;
        const bool negative = isNeg(c);
        if (first)
            out << (negative ? "-" : "");
        else
            out << (negative ? " - " : " + ");
        first = false;
        const S a = abs(c);
        if (k == 0 || !isOne(a)) {
            const std::string text = fmt(a);
            out << text;
            if (k >= 1 && text.find_first_of("/e") != std::string::npos)
                out << ' '; // "7/2 t^3", not "7/2t^3"
        }
        if (k >= 1)
            out << var;
        if (k >= 2)
            out << '^' << k;
    }
    return out.str();
}

} // namespace

std::string toText(const Polynomial<Rational>& p, const std::string& var)
{
    return polyText(
        p, var, [](const Rational& c) { return c < 0; }, [](const Rational& c) { return Rational(abs(c)); },
        [](const Rational& c) { return c == 1; }, [](const Rational& c) { return toString(c); });
}

std::string toText(const Polynomial<double>& p, const std::string& var)
{
    return polyText(
        p, var, [](double c) { return c < 0; }, [](double c) { return std::fabs(c); }, [](double c) { return c == 1.0; },
        [](double c) { return formatDouble(c); });
}

std::optional<Polynomial<Rational>> parsePolynomial(std::string_view text, char var)
{
    std::string s;
    for (char c : text)
        if (!std::isspace(static_cast<unsigned char>(c)))
            s += c;
    if (s.empty())
        return std::nullopt;
    std::vector<Rational> coefficients;
    std::size_t pos = 0;
    while (pos < s.size()) {
        bool negative = false;
        if (s[pos] == '+' || s[pos] == '-') {
            negative = s[pos] == '-';
            ++pos;
        } else if (pos != 0) {
            return std::nullopt; // terms after the first need a sign
        }
        std::size_t end = pos;
        while (end < s.size() && (std::isdigit(static_cast<unsigned char>(s[end])) || s[end] == '/' || s[end] == '.'))
            ++end;
        Rational c(1);
        const bool hasNumber = end > pos;
        if (hasNumber) {
            auto parsed = parseRational(std::string_view(s).substr(pos, end - pos));
            if (!parsed)
                return std::nullopt;
            c = *parsed;
        }
        pos = end;
        int power = 0;
        if (pos < s.size() && s[pos] == var) {
            ++pos;
            power = 1;
            if (pos < s.size() && s[pos] == '^') {
                ++pos;
                std::size_t e = pos;
                while (e < s.size() && std::isdigit(static_cast<unsigned char>(s[e])))
                    ++e;
                if (e == pos || e - pos > 4)
                    return std::nullopt;
                std::from_chars(s.data() + pos, s.data() + e, power); // at most 4 digits
                pos = e;
            }
        } else if (!hasNumber) {
            return std::nullopt; // a sign followed by neither a number nor the variable
        }
        if (pos < s.size() && s[pos] != '+' && s[pos] != '-')
            return std::nullopt;
        if (coefficients.size() <= static_cast<std::size_t>(power))
            coefficients.resize(static_cast<std::size_t>(power) + 1, Rational(0));
        coefficients[static_cast<std::size_t>(power)] += negative ? Rational(-c) : c;
    }
    return Polynomial<Rational>(std::move(coefficients));
}

std::string toText(const Vec2<Polynomial<Rational>>& p, const std::string& var)
{
    return "(" + toText(p.x, var) + ", " + toText(p.y, var) + ")";
}

std::string toText(const Vec2<Polynomial<double>>& p, const std::string& var)
{
    return "(" + toText(p.x, var) + ", " + toText(p.y, var) + ")";
}

} // namespace granota
