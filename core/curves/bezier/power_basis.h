#pragma once
/// \file power_basis.h
/// A Bézier curve rewritten in powers of t, c(t) = Σ a_k t^k — the form in which the
/// thesis states its results (Ex 2.2: c(t) = (2 − 12t − 6t² + 52t³ − 43t⁴, …)).
/// Exact for Rational. In floating point, Horner on this basis loses digits at high
/// degree where De Casteljau does not (the coefficients grow like C(n,k) and cancel).

#include "core/exact/polynomial.h"
#include "core/base/vec2.h"

#include <vector>

namespace granota {

/// C(n,k) computed in S by the multiplicative formula (exact for Rational and for double
/// while it fits in 53 bits).
template <class S> S binomialIn(int n, int k)
{
    if (k < 0 || k > n)
        return S(0);
    if (k > n - k)
        k = n - k;
    S c(1);
    for (int j = 1; j <= k; ++j)
        c = S(c * S(n - k + j) / S(j));
    return c;
}

/// a_k = C(n,k) Σ_{i=0}^{k} (−1)^{k−i} C(k,i) P_i: the k-th forward difference of the
/// control points times C(n,k) (expand Def 2.6 with Def 2.5).
template <class S> Vec2<Polynomial<S>> bezierToPowerBasis(const std::vector<Vec2<S>>& points)
{
    const int n = static_cast<int>(points.size()) - 1;
    std::vector<S> ax, ay;
    for (int k = 0; k <= n; ++k) {
        S sx(0), sy(0);
        for (int i = 0; i <= k; ++i) {
            S w = binomialIn<S>(k, i);
            if ((k - i) % 2 != 0)
                w = S(-w);
            sx += S(w * points[static_cast<std::size_t>(i)].x);
            sy += S(w * points[static_cast<std::size_t>(i)].y);
        }
        const S cnk = binomialIn<S>(n, k);
        ax.push_back(S(cnk * sx));
        ay.push_back(S(cnk * sy));
    }
    return Vec2<Polynomial<S>>(Polynomial<S>(std::move(ax)), Polynomial<S>(std::move(ay)));
}

/// Horner's rule on the power basis, both coordinates.
template <class S> Vec2<S> evaluateHorner(const Vec2<Polynomial<S>>& c, const S& t) { return Vec2<S>(c.x(t), c.y(t)); }

} // namespace granota
