#pragma once
/// \file gauss_legendre.h
/// The k-point Gauss–Legendre rule on [−1, 1] (beyond the thesis): ∫ f ≈ Σ w_i f(x_i), exact
/// for polynomials of degree 2k − 1. Used by the arc length (arc_length.h) and by the
/// arc-length report's fixed rule and reference.

#include <vector>

namespace granota {

struct GaussLegendreRule {
    std::vector<long double> nodes;   ///< descending: the first ⌊k/2⌋ are the positive ones
    std::vector<long double> weights; ///< weights[i] belongs to nodes[i]
};

/// Newton's method on the Legendre polynomial P_k in long double, from the starting
/// guesses cos(π(i + 3/4)/(k + 1/2)) (Numerical Recipes, §4.6; Golub–Welsch would do as
/// well). k ≥ 1.
GaussLegendreRule gaussLegendreRule(int k);

} // namespace granota
