#pragma once
/// \file tall_skinny_qr.h
/// Least squares for many data points (k ≫ n): the Householder QR of [M | Q] computed a
/// block of rows at a time (TSQR, Demmel et al. 2012) without ever forming the k × (n+1)
/// matrix M of Lemma 2.2. Each block — the R found so far stacked on the next rows of M,
/// built from Def 2.5 (bernstein_block.h) — fits in the L1 cache, so the factorisation runs
/// at arithmetic speed instead of memory speed; the two halves of the data are factorised
/// on two threads and merged. The result is the R of a QR of [M | Q], as stable as the
/// Householder QR it replaces: no normal equations.

#include "core/base/vec2.h"

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

namespace granota {

/// The data of a fit as the solver reads them, Q_i = (q_i − centre)/scale, computed when
/// a block needs them: a million points are never copied.
struct ScaledPoints {
    const Point* q = nullptr;
    std::size_t count = 0;
    Point centre;
    double scale = 1;

    double x(std::size_t i) const { return (q[i].x - centre.x) / scale; }
    double y(std::size_t i) const { return (q[i].y - centre.y) / scale; }
};

/// R of [M | Q] ((n+3) × (n+3), upper triangular): its top-left (n+1)×(n+1) block is the R
/// of M (so cond₂(M) = cond₂(R)), its top-right (n+1)×2 block is c = (QᵀQ)_{0..n} with
/// R P = c the least-squares solution, and its bottom-right 2×2 block has squared norm
/// Σ‖Q_i − α(t_i)‖² (the error of Prop 2.2). The block partition and every sum's order are
/// fixed, so the result depends neither on the number of threads nor on the machine.
Eigen::MatrixXd tallSkinnyQr(const std::vector<double>& t, const ScaledPoints& q, int n);

/// From this many data points on, the fit uses tallSkinnyQr.
constexpr std::size_t kTallSkinnyRows = 20000;

} // namespace granota
