#include "core/exact/rational_approximation.h"

#include <cmath>

namespace granota {

std::optional<Rational> smallRational(double d, long maxDenominator)
{
    if (!std::isfinite(d) || std::fabs(d) > 1e15)
        return std::nullopt;
    // Convergents h/k of the continued fraction of d; stop at the first whose double is d.
    const bool negative = d < 0;
    double x = std::fabs(d);
    mpz_class h0 = 0, h1 = 1, k0 = 1, k1 = 0;
    for (int iteration = 0; iteration < 64; ++iteration) {
        const double a = std::floor(x);
        const mpz_class ai(a);
        const mpz_class h2 = ai * h1 + h0, k2 = ai * k1 + k0;
        if (k2 > maxDenominator)
            return std::nullopt;
        Rational q(h2, k2);
        q.canonicalize();
        if (negative)
            q = -q;
        if (toDouble(q) == d)
            return q;
        h0 = h1;
        h1 = h2;
        k0 = k1;
        k1 = k2;
        const double frac = x - a;
        if (frac <= 0)
            return std::nullopt;
        x = 1.0 / frac;
        if (!std::isfinite(x))
            return std::nullopt; // d is subnormal (1e-320): 1/d overflows, no small fraction is d
    }
    return std::nullopt;
}

Rational meantRational(double d, long maxDenominator)
{
    if (auto q = smallRational(d, maxDenominator))
        return *q;
    return exactRational(d);
}

std::optional<std::vector<RPoint>> smallRationalPoints(const std::vector<Point>& points, long maxDenominator)
{
    std::vector<RPoint> out;
    out.reserve(points.size());
    for (const Point& p : points) {
        auto x = smallRational(p.x, maxDenominator), y = smallRational(p.y, maxDenominator);
        if (!x || !y)
            return std::nullopt;
        out.emplace_back(*x, *y);
    }
    return out;
}

} // namespace granota
