#include "core/curves/bsplines/bspline_curve.h"

#include "core/base/number_format.h"

namespace granota {

std::string bsplineNumberText(double v) { return formatDouble(v); }
std::string bsplineNumberText(const Rational& v) { return toString(v); }

} // namespace granota
