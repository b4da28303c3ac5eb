#include "core/curves/splines/cubic_spline.h"

namespace granota {

// Def 2.3 with natural ends, compiled once for doubles (drawing) and Rational (exact panels).
template Expected<PiecewisePolynomial<double>> naturalCubicSpline(const std::vector<Vec2<double>>&);
template Expected<PiecewisePolynomial<Rational>> naturalCubicSpline(const std::vector<Vec2<Rational>>&);

} // namespace granota
