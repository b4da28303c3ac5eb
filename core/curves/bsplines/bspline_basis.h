#pragma once
/// \file bspline_basis.h
/// The B-spline basis functions N_{i,p}(u) on a knot vector u_0 ≤ … ≤ u_m, m = n + p + 1.
/// Cox–de Boor recursion (de Boor 1972; Cox 1972):
///   N_{i,0}(u) = 1 if u_i ≤ u < u_{i+1}, else 0,
///   N_{i,p}(u) = (u − u_i)/(u_{i+p} − u_i) N_{i,p−1}(u) + (u_{i+p+1} − u)/(u_{i+p+1} − u_{i+1}) N_{i+1,p−1}(u),
/// a quotient 0/0 read as 0. N_{i,p} is a polynomial of degree p on each span, ≥ 0, zero outside
/// [u_i, u_{i+p+1}), and the p + 1 functions non-zero on a span sum to 1 there. On the
/// clamped vector with no interior knot they are the Bernstein polynomials B_i^p of Def 2.5.
/// At the domain's end u_{n+1} the last non-empty span is taken closed, so that c(u_{n+1}) is
/// defined (P_n on a clamped vector).

#include "core/curves/bsplines/bspline_curve.h"
#include "core/curves/bsplines/knot_vector.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <vector>

namespace granota {

/// Room for the p + 1 basis values of any degree a B-spline may have (p ≤ kMaxBSplineDegree).
template <class S> using BasisValues = std::array<S, kMaxBSplineDegree + 1>;

/// The p + 1 values N_{span−p,p}(u), …, N_{span,p}(u) — every basis function that can be
/// non-zero on the span (Piegl & Tiller A2.2, the triangle of de Boor's "inverted" recursion,
/// with no 0/0) — written to N[0..p], the rest of N untouched. `span` is findSpan(knots,
/// degree, n + 1, u). No allocation: the knot differences live on the stack (p ≤ 10), so a
/// drag or a sampling loop may call it per point.
template <class S> void basisFunctionsInto(const std::vector<S>& knots, int degree, int span, const S& u, BasisValues<S>& N)
{
    const int p = degree;
    assert(p >= 0 && p <= kMaxBSplineDegree && span >= p && static_cast<std::size_t>(span + 1) < knots.size());
    const auto K = [&](int i) -> const S& { return knots[static_cast<std::size_t>(i)]; };
    BasisValues<S> left, right; // left[j] = u − u_{span+1−j}, right[j] = u_{span+j} − u (j ≥ 1)
    N[0] = S(1);
    for (int j = 1; j <= p; ++j) {
        left[static_cast<std::size_t>(j)] = S(u - K(span + 1 - j));
        right[static_cast<std::size_t>(j)] = S(K(span + j) - u);
        S saved(0);
        for (int r = 0; r < j; ++r) {
            const auto rr = static_cast<std::size_t>(r);
            // u_{span+r+1} − u_{span+1−j+r} > 0 on a non-empty span.
            const S temp = S(N[rr] / S(right[rr + 1] + left[static_cast<std::size_t>(j - r)]));
            N[rr] = S(saved + right[rr + 1] * temp);
            saved = S(left[static_cast<std::size_t>(j - r)] * temp);
        }
        N[static_cast<std::size_t>(j)] = saved;
    }
}

/// basisFunctionsInto as a vector of exactly p + 1 values (one allocation, the result's).
template <class S> std::vector<S> basisFunctions(const std::vector<S>& knots, int degree, int span, const S& u)
{
    BasisValues<S> N;
    basisFunctionsInto(knots, degree, span, u, N);
    return std::vector<S>(N.begin(), N.begin() + (degree + 1));
}

/// One basis function N_{i,p}(u) straight from the Cox–de Boor recursion above (the triangle
/// of N_{i..i+p, 0} up to N_{i,p}, Piegl & Tiller A2.4), for any u; i from 0 to n, where
/// n + 1 = knots.size() − p − 1. Independent of basisFunctions, which the tests compare it to.
template <class S> S basisFunction(const std::vector<S>& knots, int i, int degree, const S& u)
{
    const int p = degree;
    const int n = static_cast<int>(knots.size()) - p - 2;
    assert(p >= 0 && i >= 0 && i <= n);
    const auto K = [&](int k) -> const S& { return knots[static_cast<std::size_t>(k)]; };
    // At the domain's end only the last non-empty span counts, closed on the right (see the
    // file comment); elsewhere the spans are half-open.
    const bool atEnd = u == K(n + 1);
    const int endSpan = atEnd ? findSpan(knots, p, n + 1, u) : -1;
    std::vector<S> N(static_cast<std::size_t>(p + 1));
    for (int j = 0; j <= p; ++j) {
        const bool inside = atEnd ? i + j == endSpan : K(i + j) <= u && u < K(i + j + 1);
        N[static_cast<std::size_t>(j)] = inside ? S(1) : S(0);
    }
    for (int k = 1; k <= p; ++k)
        for (int j = 0; j + k <= p; ++j) {
            const auto jj = static_cast<std::size_t>(j);
            const int a = i + j; // this entry is N_{a,k}
            S value(0);
            if (N[jj] != S(0)) // then u_{a+k} > u_a
                value = S(S(u - K(a)) / S(K(a + k) - K(a)) * N[jj]);
            if (N[jj + 1] != S(0)) // then u_{a+k+1} > u_{a+1}
                value = S(value + S(K(a + k + 1) - u) / S(K(a + k + 1) - K(a + 1)) * N[jj + 1]);
            N[jj] = value;
        }
    return N[0];
}

/// The basis functions of the span and their derivatives up to `order`:
/// ders[k][j] = N^{(k)}_{span−p+j, p}(u), k = 0..order, j = 0..p; derivatives above p are 0
/// (Piegl & Tiller A2.3).
template <class S>
std::vector<std::vector<S>> basisDerivatives(const std::vector<S>& knots, int degree, int span, const S& u, int order)
{
    const int p = degree;
    assert(p >= 0 && span >= p && order >= 0 && static_cast<std::size_t>(span + 1) < knots.size());
    const auto K = [&](int i) -> const S& { return knots[static_cast<std::size_t>(i)]; };
    const auto P1 = static_cast<std::size_t>(p + 1);
    const auto at = [](std::vector<std::vector<S>>& m, int r, int c) -> S& {
        return m[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
    };
    // ndu: the basis functions (upper triangle) and the knot differences (lower triangle).
    std::vector<std::vector<S>> ndu(P1, std::vector<S>(P1, S(0)));
    std::vector<S> left(P1), right(P1);
    at(ndu, 0, 0) = S(1);
    for (int j = 1; j <= p; ++j) {
        left[static_cast<std::size_t>(j)] = S(u - K(span + 1 - j));
        right[static_cast<std::size_t>(j)] = S(K(span + j) - u);
        S saved(0);
        for (int r = 0; r < j; ++r) {
            at(ndu, j, r) = S(right[static_cast<std::size_t>(r + 1)] + left[static_cast<std::size_t>(j - r)]);
            const S temp = S(at(ndu, r, j - 1) / at(ndu, j, r));
            at(ndu, r, j) = S(saved + right[static_cast<std::size_t>(r + 1)] * temp);
            saved = S(left[static_cast<std::size_t>(j - r)] * temp);
        }
        at(ndu, j, j) = saved;
    }
    std::vector<std::vector<S>> ders(static_cast<std::size_t>(order + 1), std::vector<S>(P1, S(0)));
    for (int j = 0; j <= p; ++j)
        at(ders, 0, j) = at(ndu, j, p);
    const int top = std::min(order, p);
    std::vector<std::vector<S>> a(2, std::vector<S>(P1, S(0)));
    for (int r = 0; r <= p; ++r) {
        int s1 = 0, s2 = 1;
        at(a, 0, 0) = S(1);
        for (int k = 1; k <= top; ++k) {
            S d(0);
            const int rk = r - k, pk = p - k;
            if (r >= k) {
                at(a, s2, 0) = S(at(a, s1, 0) / at(ndu, pk + 1, rk));
                d = S(at(a, s2, 0) * at(ndu, rk, pk));
            }
            const int j1 = rk >= -1 ? 1 : -rk;
            const int j2 = r - 1 <= pk ? k - 1 : p - r;
            for (int j = j1; j <= j2; ++j) {
                at(a, s2, j) = S(S(at(a, s1, j) - at(a, s1, j - 1)) / at(ndu, pk + 1, rk + j));
                d = S(d + at(a, s2, j) * at(ndu, rk + j, pk));
            }
            if (r <= pk) {
                at(a, s2, k) = S(-at(a, s1, k - 1) / at(ndu, pk + 1, r));
                d = S(d + at(a, s2, k) * at(ndu, r, pk));
            }
            at(ders, k, r) = d;
            std::swap(s1, s2);
        }
    }
    // Multiply by p!/(p−k)!.
    S factor(p);
    for (int k = 1; k <= top; ++k) {
        for (int j = 0; j <= p; ++j)
            at(ders, k, j) = S(at(ders, k, j) * factor);
        factor = S(factor * S(p - k));
    }
    return ders;
}

} // namespace granota
