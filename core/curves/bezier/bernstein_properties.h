#pragma once
/// \file bernstein_properties.h
/// The properties of the Bernstein polynomials that the Bernstein tab checks live, at a
/// degree n and a parameter t (docs/tabs.md): each one as a floating-point residual at t and
/// as an exact identity between polynomials with rational coefficients.
///  - partition of unity: Σ_i B_i^n(t) = 1;
///  - symmetry: B_i^n(t) = B_{n−i}^n(1 − t);
///  - the recursion of Lemma 2.1: B_i^n = (1 − t) B_i^{n−1} + t B_{i−1}^{n−1} (n ≥ 1).
/// The residuals compare two independent evaluations: the closed form of Def 2.5,
/// C(n,i) t^i (1−t)^{n−i}, against the sum, the mirror or the recursion.

#include "core/exact/polynomial.h"
#include "core/exact/rational.h"
#include "core/base/vec2.h"

#include <vector>

namespace granota {

/// One property at one (n, t): how far from exact the floating-point evaluation is, and
/// whether the identity holds exactly as polynomials.
struct BernsteinPropertyCheck {
    double residual = 0.0; ///< max over i of |left − right| at t (0 when there is nothing to check)
    bool exact = true;     ///< the identity holds for the polynomials with rational coefficients
    bool applies = true;   ///< false for the recursion at n = 0 (Lemma 2.1 needs n ≥ 1)
};

struct BernsteinChecks {
    BernsteinPropertyCheck partitionOfUnity; ///< Σ_i B_i^n(t) = 1
    BernsteinPropertyCheck symmetry;         ///< B_i^n(t) = B_{n−i}^n(1 − t)
    BernsteinPropertyCheck recursion;        ///< Lemma 2.1
};

/// B_i^n(t) by the closed form of Def 2.5 (binomial coefficient times powers), for
/// 0 ≤ i ≤ n ≤ 60; 0 outside 0 ≤ i ≤ n.
double bernsteinClosedForm(int i, int n, double t);

/// The three checks at degree n (0 ≤ n ≤ 60) and parameter t (finite).
BernsteinChecks checkBernsteinProperties(int n, double t);

/// How much the change from the Bernstein basis of degree n to the powers of t can amplify
/// relative errors: the condition number ‖M‖∞ ‖M⁻¹‖∞ of a_k = Σ_i C(n,k) C(k,i) (−1)^{k−i} P_i
/// (core/curves/bezier/power_basis.h), which is (n + 1) · max_k C(n,k) 2^k. It is 160 at n = 4 and about
/// 1e10 at n = 20: why the power-basis tables are hidden at high degree (docs/extreme-cases.md).
double powerBasisCondition(int n);

/// Def 2.6 written out as the thesis does in Ex 2.5 and Ex 2.6: the terms B_k^n(t) P_k
/// expanded in powers of t (one per control point; n = points.size() − 1).
std::vector<Vec2<Polynomial<Rational>>> bernsteinTerms(const std::vector<RPoint>& points);

/// Σ_k B_k^n(t) P_k in powers of t: the sum of bernsteinTerms(points).
Vec2<Polynomial<Rational>> bernsteinSum(const std::vector<RPoint>& points);

} // namespace granota
