#include "core/curves/bsplines/bspline_curve.h"

#include "core/base/number_format.h"

namespace granota {

std::string bsplineNumberText(double v) { return formatDouble(v); }
std::string bsplineNumberText(const Rational& v) { return toString(v); }
MessageArg bsplineNumberArg(double v) { return numberArg(v); }
MessageArg bsplineNumberArg(const Rational& v)
{
    // An integer is a number the GUI writes as any other; a fraction keeps its exact text.
    if (v.get_den() == 1)
        return numberArg(toDouble(v));
    return textArg(toString(v));
}

} // namespace granota
