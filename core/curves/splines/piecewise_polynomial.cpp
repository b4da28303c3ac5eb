#include "core/curves/splines/piecewise_polynomial.h"

namespace granota {

// Compiled once here for the two scalars Granota uses (and so checked for both).
template struct PiecewisePolynomial<double>;
template struct PiecewisePolynomial<Rational>;

} // namespace granota
