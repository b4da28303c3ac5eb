#include "core/exact/exact_point.h"

#include "core/base/number_format.h"
#include "core/exact/rational_approximation.h"

#include <cmath>

namespace granota {

bool operator==(const ExactPoint& a, const ExactPoint& b) { return a.x == b.x && a.y == b.y; }

ExactPoint writtenExact(const Point& p) { return {smallRational(p.x), smallRational(p.y)}; }

std::vector<ExactPoint> writtenExact(const std::vector<Point>& points)
{
    if (points.size() > kExactFormsUpTo)
        return {};
    std::vector<ExactPoint> out;
    out.reserve(points.size());
    for (const Point& p : points)
        out.push_back(writtenExact(p));
    return out;
}

std::vector<ExactPoint> exactForms(const std::vector<RPoint>& points)
{
    if (points.size() > kExactFormsUpTo)
        return {};
    std::vector<ExactPoint> out;
    out.reserve(points.size());
    for (const RPoint& p : points)
        out.push_back({p.x, p.y});
    return out;
}

std::optional<std::vector<RPoint>> allExact(const std::vector<ExactPoint>& points, std::size_t count)
{
    if (points.size() != count)
        return std::nullopt;
    std::vector<RPoint> out;
    out.reserve(points.size());
    for (const ExactPoint& p : points) {
        if (!p.x || !p.y)
            return std::nullopt;
        out.emplace_back(*p.x, *p.y);
    }
    return out;
}

Rational exactOr(const ExactCoordinate& q, double d) { return q ? *q : exactRational(d); }

bool terminates(const Rational& q)
{
    mpz_class d = q.get_den();
    for (unsigned long p : {2UL, 5UL})
        while (mpz_divisible_ui_p(d.get_mpz_t(), p))
            d /= p;
    return d == 1;
}

std::optional<std::string> terminatingDecimal(const Rational& q, int maxSignificant)
{
    if (!terminates(q))
        return std::nullopt;
    // q = n / (2^a 5^b) = n·2^(k−a)·5^(k−b) / 10^k with k = max(a, b): k decimals.
    const mpz_class den = q.get_den();
    int k = 0;
    mpz_class scale = 1;
    while (!mpz_divisible_p(scale.get_mpz_t(), den.get_mpz_t())) {
        scale *= 10;
        ++k;
        if (k > 4 * maxSignificant + 400)
            return std::nullopt; // more decimals than any text of maxSignificant digits we write
    }
    mpz_class digits = abs(q.get_num()) * (scale / den);
    std::string text = digits.get_str();
    if (k > 0) {
        if (static_cast<int>(text.size()) <= k)
            text.insert(0, static_cast<std::size_t>(k + 1) - text.size(), '0');
        text.insert(text.size() - static_cast<std::size_t>(k), 1, '.');
    }
    // Significant digits: all of them but the leading zeros (and the point).
    int significant = 0;
    bool leading = true;
    for (char c : text) {
        if (c == '.')
            continue;
        leading = leading && c == '0';
        significant += !leading;
    }
    if (significant > maxSignificant)
        return std::nullopt;
    if (q < 0)
        text.insert(0, 1, '-');
    return text;
}

std::string roundedDecimal(const Rational& q, int digits)
{
    if (q == 0)
        return "0";
    const Rational a = abs(q);
    // The decimal exponent e of a: 10^e ≤ a < 10^(e+1), guessed from the double and then made sure.
    const double guess = std::floor(std::log10(toDouble(a)));
    if (!std::isfinite(guess) || guess < -5 || guess > 16)
        return formatSignificant(toDouble(q), digits);
    int e = static_cast<int>(guess);
    const auto power = [](int k) {
        mpz_class p;
        mpz_ui_pow_ui(p.get_mpz_t(), 10, static_cast<unsigned long>(k < 0 ? -k : k));
        return k < 0 ? Rational(mpz_class(1), p) : Rational(p);
    };
    while (a < power(e))
        --e;
    while (a >= power(e + 1))
        ++e;
    // r = a · 10^(digits − 1 − e) rounded: `digits` digits (or one more when it rounds up to 10^digits).
    Rational scaled = a * power(digits - 1 - e) + Rational(1, 2);
    mpz_class r = scaled.get_num() / scaled.get_den();
    if (r == power(digits).get_num()) {
        r /= 10;
        ++e;
    }
    std::string text = r.get_str(); // `digits` digits: d.ddd… × 10^e
    const int point = e + 1;        // digits before the decimal point
    if (point <= 0)
        text.insert(0, std::string(static_cast<std::size_t>(1 - point), '0'));
    else if (point > static_cast<int>(text.size()))
        text.append(static_cast<std::size_t>(point) - text.size(), '0');
    const std::size_t at = point <= 0 ? 1 : static_cast<std::size_t>(point);
    if (at < text.size()) {
        text.insert(at, 1, '.');
        while (text.back() == '0')
            text.pop_back();
        if (text.back() == '.')
            text.pop_back();
    }
    return q < 0 ? "-" + text : text;
}

std::string readableExact(const ExactCoordinate& q, double d)
{
    if (q)
        if (auto text = terminatingDecimal(*q, kExactDecimalDigits))
            return *text;
    return formatReadable(d);
}

} // namespace granota
