#include "core/base/number_format.h"

#include <charconv>
#include <cmath>

namespace granota {

std::string formatDouble(double v)
{
    if (v == 0)
        return "0"; // also folds -0
    // Whole numbers as whole numbers: 100, not the equally short 1e+02.
    if (std::fabs(v) < 1e16 && v == std::trunc(v))
        return formatFixed(v, 0);
    // The fewest significant digits that read back as the same double ("%.*g" in the C
    // locale: to_chars and from_chars never look at LC_NUMERIC).
    std::string text;
    for (int precision = 1; precision <= 17; ++precision) {
        text = formatSignificant(v, precision);
        double back = 0;
        std::from_chars(text.data(), text.data() + text.size(), back);
        if (back == v)
            break;
    }
    return text;
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
