#include "core/curves/splines/continuity_check.h"

#include "core/base/number_format.h"

namespace granota {

namespace detail {

std::string scalarText(const Rational& v) { return toString(v); }
std::string scalarText(double v) { return formatDouble(v); }

std::string derivativeName(const std::string& name, int order)
{
    if (order <= 3)
        return name + std::string(static_cast<std::size_t>(order), '\'');
    return name + "^(" + std::to_string(order) + ")";
}

} // namespace detail

template ContinuityReport<double> checkContinuity(const PiecewisePolynomial<double>&, int, const std::vector<Vec2<double>>&,
                                                  double);
template ContinuityReport<Rational> checkContinuity(const PiecewisePolynomial<Rational>&, int, const std::vector<Vec2<Rational>>&,
                                                    double);
template JoinReport<double> checkSegmentJoins(const std::vector<Vec2<Polynomial<double>>>&, int, bool, double);
template JoinReport<Rational> checkSegmentJoins(const std::vector<Vec2<Polynomial<Rational>>>&, int, bool, double);

} // namespace granota
