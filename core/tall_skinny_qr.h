#pragma once
/// \file tall_skinny_qr.h
/// Least squares for many data points (k ≫ n): the Householder QR of [M | Q] computed a
/// block of rows at a time (TSQR, Demmel et al. 2012) without ever forming the k × (n+1)
/// matrix M of Lemma 2.2. Each block — the R found so far stacked on the next rows of M,
/// built from the Bernstein recursion (Lemma 2.1) — fits in cache, so the factorisation runs
/// at arithmetic speed instead of memory speed; the two halves of the data are factorised
/// on two threads and merged. The result is the R of a QR of [M | Q], as stable as the
/// Householder QR it replaces: no normal equations.

#include <Eigen/Dense>

#include <vector>

namespace granota {

/// R of [M | Q] ((n+3) × (n+3), upper triangular): its top-left (n+1)×(n+1) block is the R
/// of M (so cond₂(M) = cond₂(R)), its top-right (n+1)×2 block is c = (QᵀQ)_{0..n} with
/// R P = c the least-squares solution, and its bottom-right 2×2 block has squared norm
/// Σ‖Q_i − α(t_i)‖² (the error of Prop 2.2). The block partition is fixed, so the result
/// does not depend on the number of threads.
Eigen::MatrixXd tallSkinnyQr(const std::vector<double>& t, const Eigen::MatrixX2d& q, int n);

/// From this many data points on, the fit uses tallSkinnyQr.
constexpr std::size_t kTallSkinnyRows = 20000;

} // namespace granota
