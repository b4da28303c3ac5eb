#include "core/curves/bezier/bernstein.h"

namespace granota {

Polynomial<Rational> bernsteinPolynomial(int i, int n)
{
    if (i < 0 || i > n)
        return Polynomial<Rational>();
    std::vector<Rational> c(static_cast<std::size_t>(n + 1), Rational(0));
    const Rational cni = binomial(n, i);
    for (int k = i; k <= n; ++k) {
        Rational term = cni * binomial(n - i, k - i);
        c[static_cast<std::size_t>(k)] = (k - i) % 2 == 0 ? term : Rational(-term);
    }
    return Polynomial<Rational>(std::move(c));
}

} // namespace granota
