#include "core/curves/bezier/exact_hodograph.h"

#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bezier/hodograph.h"
#include "core/exact/exact_cost.h"

#include <cmath>
#include <utility>

namespace granota {

namespace {

bool allFinite(const std::vector<Point>& P)
{
    for (const Point& p : P)
        if (!isFinite(p))
            return false;
    return true;
}

/// Drops the zero coefficients of the highest powers (the zero polynomial is empty).
void trim(std::vector<Rational>& f)
{
    while (!f.empty() && f.back() == 0)
        f.pop_back();
}

/// f mod g (g not zero), coefficients of t^0 first.
std::vector<Rational> remainder(std::vector<Rational> f, const std::vector<Rational>& g)
{
    trim(f);
    while (f.size() >= g.size()) {
        const Rational c = f.back() / g.back();
        const std::size_t shift = f.size() - g.size();
        for (std::size_t i = 0; i < g.size(); ++i)
            f[shift + i] -= c * g[i];
        f.pop_back(); // the leading coefficient is 0 now, exactly
        trim(f);
    }
    return f;
}

/// Divides by the leading coefficient, so that the coefficients grow slowly in Euclid's algorithm.
void makeMonic(std::vector<Rational>& f)
{
    if (f.empty())
        return;
    const Rational lead = f.back();
    for (Rational& c : f)
        c /= lead;
}

} // namespace

std::optional<ExactDerivatives> exactDerivativesAt(const std::vector<Point>& P, double t)
{
    if (P.size() < 2 || !allFinite(P) || !std::isfinite(t))
        return std::nullopt;
    const std::vector<RPoint> exact = toRational(P);
    const Rational s = exactRational(t);
    // The hodograph's points have at most a few bits more than P's; c″'s triangle is smaller.
    const long bits = maxBitLength(exact) + 8;
    const int n = static_cast<int>(P.size()) - 1;
    if (!exactWorkAllowed(2 * deCasteljauExactWork(n - 1, bits, bitLength(s))))
        return std::nullopt;
    const std::vector<RPoint> d1 = hodograph(exact);
    ExactDerivatives out;
    out.first = deCasteljauPoint(d1, s);
    out.second = n >= 2 ? deCasteljauPoint(hodograph(d1), s) : RPoint(Rational(0), Rational(0));
    return out;
}

std::optional<bool> hodographVanishesSomewhere(const std::vector<Point>& P)
{
    if (P.size() < 2 || !allFinite(P))
        return std::nullopt;
    const std::vector<RPoint> exact = toRational(P);
    const int m = static_cast<int>(P.size()) - 2; // the degree of c′
    // Euclid on two polynomials of degree m: about m² operations on numbers that grow to
    // about m times the points' bits, as a De Casteljau triangle of degree m does.
    if (!exactWorkAllowed(deCasteljauExactWork(m, maxBitLength(exact) + 8, maxBitLength(exact) + 8)))
        return std::nullopt;
    const std::vector<RPoint> A = hodograph(exact);
    if (A.back().x == 0 && A.back().y == 0)
        return true; // c′(1) = 0
    // In [0, 1): c′(t) = (1 − t)^m Σ C(m, i) A_i s^i with s = t / (1 − t) ≥ 0.
    std::vector<Rational> f, g;
    for (int i = 0; i <= m; ++i) {
        const Rational c = binomial(m, i);
        f.push_back(c * A[static_cast<std::size_t>(i)].x);
        g.push_back(c * A[static_cast<std::size_t>(i)].y);
    }
    trim(f);
    trim(g);
    if (f.empty() || g.empty())
        return true; // one coordinate of c′ is 0 everywhere: c′ = 0 where the other is
    makeMonic(f);
    makeMonic(g);
    while (!g.empty()) {
        std::vector<Rational> r = remainder(std::move(f), g);
        makeMonic(r);
        f = std::move(g);
        g = std::move(r);
    }
    return f.size() >= 2; // gcd(x′, y′) has degree ≥ 1
}

} // namespace granota
