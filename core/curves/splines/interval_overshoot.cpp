#include "core/curves/splines/interval_overshoot.h"

#include <cassert>
#include <cmath>
#include <vector>

namespace granota {

namespace {

/// The roots of a u² + b u + c inside (0, 1) (a linear or constant derivative included).
std::vector<double> overshootCriticalPoints(double a, double b, double c)
{
    std::vector<double> roots;
    if (a == 0) {
        if (b != 0)
            roots.push_back(-c / b);
    } else {
        const double disc = b * b - 4 * a * c;
        if (disc >= 0) {
            const double q = -(b + std::copysign(std::sqrt(disc), b)) / 2;
            roots.push_back(q / a);
            if (q != 0)
                roots.push_back(c / q);
        }
    }
    std::vector<double> inside;
    for (double u : roots)
        if (u > 0 && u < 1)
            inside.push_back(u);
    return inside;
}

} // namespace

IntervalOvershoot polynomialOvershoot(const Polynomial<double>& p, double lo, double hi)
{
    assert(p.degree() <= 3 && lo <= hi);
    const Polynomial<double> d = p.derivative();
    std::vector<double> candidates{0.0, 1.0};
    for (double u : overshootCriticalPoints(d.coefficient(2), d.coefficient(1), d.coefficient(0)))
        candidates.push_back(u);
    IntervalOvershoot out;
    for (double u : candidates) {
        const double y = p(u);
        if (y - hi > out.amount)
            out = {y - hi, u, true};
        if (lo - y > out.amount)
            out = {lo - y, u, false};
    }
    return out;
}

} // namespace granota
