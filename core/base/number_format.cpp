#include "core/base/number_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace granota {

namespace {

/// The shortest text of at most `maxDigits` significant digits that reads back as `v`; else
/// `v` rounded to `maxDigits` digits.
std::string shortestUpTo(double v, int maxDigits)
{
    if (v == 0)
        return "0"; // also folds -0
    // Whole numbers as whole numbers: 100, not the equally short 1e+02.
    if (std::fabs(v) < 1e16 && v == std::trunc(v))
        return formatFixed(v, 0);
    // The fewest significant digits that read back as the same double, written as "%.*g" in
    // the C locale (to_chars never looks at LC_NUMERIC). std::to_chars's shortest scientific
    // form finds that count at once: the closest decimal of that many digits is the one
    // "%.*g" writes, and it reads back.
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
    int digits = 0;
    for (const char* c = buf; c != r.ptr && *c != 'e'; ++c)
        digits += (*c >= '0' && *c <= '9') ? 1 : 0;
    return formatSignificant(v, std::min(digits, maxDigits));
}

} // namespace

std::string formatDouble(double v) { return shortestUpTo(v, 17); }

std::string formatReadable(double v)
{
    const std::string text = shortestUpTo(v, 15);
    return text == "-0" ? std::string("0") : text;
}

std::string formatSignificant(double v, int digits)
{
    char buf[64];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits);
    return std::string(buf, r.ptr);
}

std::string formatFixed(double v, int decimals)
{
    char buf[400]; // 1e308 written out in full, with its decimals
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
    if (r.ec != std::errc())
        return formatSignificant(v, 17);
    return std::string(buf, r.ptr);
}

} // namespace granota
