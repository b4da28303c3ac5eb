#pragma once
/// \file rounding_residue.h
/// Coefficients that are rounding residue, not mathematics: a least-squares fit of points on
/// the line y = 10t in double precision gives α(t) = 5.22388e-07 + 10t + 7.10543e-15 t², whose
/// first and last terms are the solver's and the power form's rounding, not the data's. A
/// shown polynomial drops every coefficient c_k with |c_k| ≤ τ · max_j |c_j|, where τ is at
/// least kResidueRelative and grows with what the numbers went through (fitResidueRelative).

#include "core/exact/polynomial.h"

namespace granota {

/// The least relative size of a shown coefficient: 10⁴ units in the last place of the largest.
inline constexpr double kResidueRelative = 1e-12;

/// `p` with every coefficient of magnitude ≤ relative · max|c| set to 0 (relative ≥ 0).
Polynomial<double> withoutResidue(const Polynomial<double>& p, double relative = kResidueRelative);

/// τ for the power form of a least-squares Bézier fit of degree n (§2.1.3) whose matrix has
/// condition number cond₂(M): the control points carry a relative error of about ε·cond₂(M),
/// and the change to powers of t multiplies it by up to C(n, ⌊n/2⌋) (Ex 2.4's binomials);
/// never below kResidueRelative, never above 1e-3 (a coefficient a thousandth of the largest
/// is always shown).
double fitResidueRelative(int degree, double cond);

} // namespace granota
