#pragma once
/// \file moore_penrose.h
/// What §2.1.3 states about the least-squares fit, checked on the matrices themselves:
///  - the four conditions that define the Moore–Penrose inverse A⁺ of A, in the order the
///    thesis lists them: (1) AA⁺A = A, (2) A⁺AA⁺ = A⁺, (3) (AA⁺)ᵀ = AA⁺, (4) (A⁺A)ᵀ = A⁺A
///    (real matrices: the conjugate transpose is the transpose) — checked exactly, so
///    Nota 2.2's M⁺ = (MᵀM)⁻¹Mᵀ is seen to be M's;
///  - the Hessian 2MᵀM of the error Σ‖Q_i − α(t_i)‖² (Prop 2.2), whose eigenvalues are
///    2σ_i², σ_i the singular values of M: all positive when M has full rank (Lemma 2.2),
///    so the critical point is the minimum.

#include "core/exact/rational_matrix.h"

#include <array>
#include <vector>

namespace granota {

/// Each of the four Penrose conditions for `aPlus` as the inverse of `a`, exactly, in the
/// thesis's order. A shape that cannot be A⁺ (not cols × rows of A) fails all four.
std::array<bool, 4> penroseConditions(const RationalMatrix& a, const RationalMatrix& aPlus);

/// 2MᵀM, exactly (Prop 2.2).
RationalMatrix leastSquaresHessian(const RationalMatrix& m);

/// The eigenvalues of a symmetric rational matrix, in decimals, ascending (Eigen's
/// self-adjoint solver on the nearest doubles).
std::vector<double> symmetricEigenvalues(const RationalMatrix& s);

} // namespace granota
