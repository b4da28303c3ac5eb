#include "app/cli/finite_doubles.h"

#include "core/base/number_format.h"

#include <cmath>

namespace granota::cli {

namespace {

/// "≈ -1e400": the order of magnitude of a rational too large for a double, short
/// where its digits would fill the screen (a 10 000-digit integer).
std::string magnitudeText(const Rational& q)
{
    long numExp = 0, denExp = 0;
    const double numMantissa = mpz_get_d_2exp(&numExp, q.get_num_mpz_t());
    const double denMantissa = mpz_get_d_2exp(&denExp, q.get_den_mpz_t());
    const double log10 = std::log10(std::fabs(numMantissa / denMantissa)) +
                         static_cast<double>(numExp - denExp) * std::log10(2.0);
    long exponent = static_cast<long>(std::floor(log10));
    double mantissa = std::round(std::pow(10.0, log10 - static_cast<double>(exponent)) * 10) / 10; // 1.8
    if (mantissa >= 10) {
        mantissa /= 10;
        ++exponent;
    }
    return std::string("≈ ") + (q < 0 ? "-" : "") + formatDouble(mantissa) + "e" + std::to_string(exponent);
}

} // namespace

std::string valueText(const Rational& q)
{
    const std::string exact = toString(q);
    return exact.size() <= 24 ? "= " + exact : magnitudeText(q);
}

Error tooLargeForDouble(const std::string& what, bool exactAvailable)
{
    return makeError(ErrorCode::OutOfRange,
                     what + " is too large for a double (beyond ±1.8e308)" +
                         (exactAvailable ? "; --exact computes it with exact fractions, which do not overflow" : ""));
}

Expected<double> finiteDouble(const Rational& q, const std::string& what, bool exactAvailable)
{
    const double d = toDouble(q);
    if (!std::isfinite(d))
        return tooLargeForDouble(what, exactAvailable);
    return d;
}

Expected<std::vector<Point>> finiteDoubles(const std::vector<RPoint>& points, bool exactAvailable)
{
    std::vector<Point> out;
    out.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const std::string name = "point " + std::to_string(i) + ": ";
        auto x = finiteDouble(points[i].x, name + "x " + valueText(points[i].x), exactAvailable);
        if (!x)
            return x.error();
        auto y = finiteDouble(points[i].y, name + "y " + valueText(points[i].y), exactAvailable);
        if (!y)
            return y.error();
        out.emplace_back(*x, *y);
    }
    return out;
}

std::optional<std::string> nonFiniteNumber(const Json& answer)
{
    if (const auto d = answer.asNumber())
        return std::isfinite(*d) ? std::nullopt : std::optional<std::string>("");
    if (const Json::Array* a = answer.asArray()) {
        for (std::size_t i = 0; i < a->size(); ++i)
            if (auto where = nonFiniteNumber((*a)[i]))
                return "[" + std::to_string(i) + "]" + *where;
    } else if (const Json::Object* o = answer.asObject()) {
        for (const auto& [key, value] : *o)
            if (auto where = nonFiniteNumber(value))
                return (where->empty() || where->front() == '[' ? key : key + ".") + *where;
    }
    return std::nullopt;
}

} // namespace granota::cli
