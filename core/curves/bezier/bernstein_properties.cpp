#include "core/curves/bezier/bernstein_properties.h"

#include "core/curves/bezier/bernstein.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace granota {

namespace {

using RPoly = Polynomial<Rational>;

/// 1 − t as a polynomial.
RPoly oneMinusT() { return RPoly{Rational(1), Rational(-1)}; }

} // namespace

double bernsteinClosedForm(int i, int n, double t)
{
    if (i < 0 || i > n)
        return 0.0;
    return binomial(n, i).get_d() * std::pow(t, i) * std::pow(1.0 - t, n - i);
}

BernsteinChecks checkBernsteinProperties(int n, double t)
{
    assert(n >= 0 && n <= 60);
    BernsteinChecks checks;
    const auto ni = static_cast<std::size_t>(n);

    // Floating point: closed forms (Def 2.5) against the sum, the mirror and the recursion.
    std::vector<double> closed(ni + 1), mirrored(ni + 1);
    for (int i = 0; i <= n; ++i) {
        closed[static_cast<std::size_t>(i)] = bernsteinClosedForm(i, n, t);
        mirrored[static_cast<std::size_t>(i)] = bernsteinClosedForm(n - i, n, 1.0 - t);
    }
    double sum = 0.0;
    for (double b : closed)
        sum += b;
    checks.partitionOfUnity.residual = std::fabs(sum - 1.0);
    for (std::size_t i = 0; i <= ni; ++i)
        checks.symmetry.residual = std::max(checks.symmetry.residual, std::fabs(closed[i] - mirrored[i]));
    if (n >= 1) {
        for (int i = 0; i <= n; ++i) {
            const double right = (1.0 - t) * bernsteinClosedForm(i, n - 1, t) + t * bernsteinClosedForm(i - 1, n - 1, t);
            checks.recursion.residual = std::max(checks.recursion.residual,
                                                 std::fabs(closed[static_cast<std::size_t>(i)] - right));
        }
    } else {
        checks.recursion.applies = false;
    }

    // Exactly, as polynomials with rational coefficients.
    RPoly total;
    const RPoly u = oneMinusT();
    for (int i = 0; i <= n; ++i) {
        const RPoly b = bernsteinPolynomial(i, n);
        total += b;
        // B_{n−i}^n(1 − t): Horner with the polynomial 1 − t as the argument.
        if (bernsteinPolynomial(n - i, n)(u) != b)
            checks.symmetry.exact = false;
        if (n >= 1 && u * bernsteinPolynomial(i, n - 1) + RPoly::identity() * bernsteinPolynomial(i - 1, n - 1) != b)
            checks.recursion.exact = false;
    }
    checks.partitionOfUnity.exact = total == RPoly(Rational(1));
    return checks;
}

double powerBasisCondition(int n)
{
    assert(n >= 0);
    // ‖M‖∞: row k sums C(n,k) C(k,i) over i, that is C(n,k) 2^k. ‖M⁻¹‖∞: row i of the
    // inverse (b_i = Σ_{k≤i} C(i,k)/C(n,k) a_k) sums to at most n + 1, reached at i = n.
    double norm = 0.0;
    for (int k = 0; k <= n; ++k)
        norm = std::max(norm, std::ldexp(binomial(n, k).get_d(), k));
    return (n + 1) * norm;
}

std::vector<Vec2<Polynomial<Rational>>> bernsteinTerms(const std::vector<RPoint>& points)
{
    assert(!points.empty());
    const int n = static_cast<int>(points.size()) - 1;
    std::vector<Vec2<RPoly>> terms;
    terms.reserve(points.size());
    for (int k = 0; k <= n; ++k) {
        const RPoly b = bernsteinPolynomial(k, n);
        const RPoint& p = points[static_cast<std::size_t>(k)];
        terms.emplace_back(b * RPoly(p.x), b * RPoly(p.y));
    }
    return terms;
}

Vec2<Polynomial<Rational>> bernsteinSum(const std::vector<RPoint>& points)
{
    Vec2<RPoly> sum;
    for (const auto& term : bernsteinTerms(points))
        sum += term;
    return sum;
}

} // namespace granota
