#pragma once
/// \file bernstein.h
/// Bernstein polynomials (Def 2.5) B_i^n(t) = C(n,i) t^i (1−t)^{n−i}, zero outside
/// 0 ≤ i ≤ n, and the Bézier curve as Σ B_i^n(t) P_i (Def 2.6).

#include "core/exact/polynomial.h"
#include "core/exact/rational.h"
#include "core/base/vec2.h"

#include <cassert>
#include <vector>

namespace granota {

/// All of B_0^n(t) … B_n^n(t) at once through the recursion of Lemma 2.1,
/// B_i^n = (1−t) B_i^{n−1} + t B_{i−1}^{n−1}: only sums of products of numbers in [0,1]
/// for t ∈ [0,1], so no binomial coefficient ever overflows or cancels. Into b[0..n], with
/// no allocation (a row of the fit's matrix M, Lemma 2.2).
template <class S> void bernsteinAllInto(int n, const S& t, S* b)
{
    assert(n >= 0);
    for (int i = 1; i <= n; ++i)
        b[i] = S(0);
    b[0] = S(1);
    const S u = S(S(1) - t);
    for (int m = 1; m <= n; ++m) {
        // In place from the top so that b[i−1] is still of degree m−1 when b[i] is formed.
        for (int i = m; i >= 1; --i)
            b[i] = S(u * b[i] + t * b[i - 1]);
        b[0] = S(u * b[0]);
    }
}

/// The same as a vector.
template <class S> std::vector<S> bernsteinAll(int n, const S& t)
{
    assert(n >= 0);
    std::vector<S> b(static_cast<std::size_t>(n + 1), S(0));
    bernsteinAllInto(n, t, b.data());
    return b;
}

/// B_i^n(t) (Def 2.5); 0 when i < 0 or i > n.
template <class S> S bernstein(int i, int n, const S& t)
{
    if (i < 0 || i > n)
        return S(0);
    return bernsteinAll(n, t)[static_cast<std::size_t>(i)];
}

/// B_i^n expanded in powers of t, exactly (Ex 2.4):
/// B_i^n(t) = Σ_{k=i}^{n} (−1)^{k−i} C(n,i) C(n−i, k−i) t^k.
Polynomial<Rational> bernsteinPolynomial(int i, int n);

/// Def 2.6: α(t) = Σ_{k=0}^{n} B_k^n(t) P_k, the "Bernstein sum" way of evaluating a
/// Bézier curve (Prop 2.1 proves it equals De Casteljau's P_0^n(t)).
template <class S> Vec2<S> bezierBernstein(const std::vector<Vec2<S>>& points, const S& t)
{
    assert(!points.empty());
    const std::vector<S> b = bernsteinAll(static_cast<int>(points.size()) - 1, t);
    Vec2<S> sum(S(0), S(0));
    for (std::size_t k = 0; k < points.size(); ++k)
        sum += b[k] * points[k];
    return sum;
}

} // namespace granota
