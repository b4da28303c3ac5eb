#include "core/exact/rounding_residue.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granota {

Polynomial<double> withoutResidue(const Polynomial<double>& p, double relative)
{
    std::vector<double> c = p.coefficients();
    double largest = 0;
    for (double a : c)
        largest = std::max(largest, std::fabs(a));
    for (double& a : c)
        if (std::fabs(a) <= relative * largest)
            a = 0;
    return Polynomial<double>(std::move(c));
}

double fitResidueRelative(int degree, double cond)
{
    constexpr double kMostRelative = 1e-3;
    if (!std::isfinite(cond))
        return kMostRelative;
    double binomial = 1; // C(n, ⌊n/2⌋), built up as a double: at most C(100, 50) ≈ 1e29
    const int half = std::max(0, degree) / 2;
    for (int i = 1; i <= half; ++i)
        binomial = binomial * (degree - half + i) / i;
    const double tau = std::numeric_limits<double>::epsilon() * std::max(1.0, cond) * binomial;
    return std::clamp(tau, kResidueRelative, kMostRelative);
}

} // namespace granota
