#pragma once
/// \file cyclic_tridiagonal_system.h
/// A cyclic (periodic) tridiagonal system: row i reads
///     sub[i]·x[i−1] + diag[i]·x[i] + super[i]·x[i+1] = rhs[i],   indices mod n,
/// so that sub[0] is the corner coefficient of x[n−1] in row 0 and super[n−1] the corner
/// coefficient of x[0] in row n−1. The closed C² spline's system (parametric_spline.h) has
/// this shape.
///
/// Method: Sherman–Morrison on the tridiagonal solver (tridiagonal_system.h), as in Press
/// et al., "Numerical Recipes", §2.7 ("Cyclic tridiagonal systems"). With γ = −diag[0],
/// β = sub[0] (top right), α = super[n−1] (bottom left), the matrix is A = T + u vᵀ with
/// u = (γ, 0, …, 0, α), v = (1, 0, …, 0, β/γ), and T tridiagonal with
/// diag[0] − γ and diag[n−1] − αβ/γ. Then, with T y = rhs and T z = u,
///     x = y − z · (vᵀy)/(1 + vᵀz).
/// Banded solves only (z once, y per right side): O(n) work and memory, never a dense
/// matrix. Exact over Rational.

#include "core/curves/splines/tridiagonal_system.h"

#include <cassert>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace granota {

/// The solutions x of the cyclic system for each right side (one Sherman–Morrison vector z
/// serves them all: k right sides cost k + 1 banded solves), or nullopt when it is singular
/// or, in floating point, a result is not finite. The three diagonals and every right side
/// have size n ≥ 3.
template <class S>
std::optional<std::vector<std::vector<S>>> solveCyclicTridiagonal(std::vector<S> sub, std::vector<S> diag, std::vector<S> super,
                                                                  std::vector<std::vector<S>> rightSides)
{
    const std::size_t n = diag.size();
    assert(n >= 3 && sub.size() == n && super.size() == n);
    const S beta = sub[0];        // A[0][n−1]
    const S alpha = super[n - 1]; // A[n−1][0]
    // γ = −diag[0] keeps T's first pivot 2·diag[0] (no cancellation); any γ ≠ 0 is correct.
    const S gamma = diag[0] == S(0) ? S(1) : S(-diag[0]);
    diag[0] = S(diag[0] - gamma);
    diag[n - 1] = S(diag[n - 1] - S(S(alpha * beta) / gamma));
    std::vector<S> u(n, S(0));
    u[0] = gamma;
    u[n - 1] = alpha;
    const auto z = solveTridiagonal(sub, diag, super, std::move(u));
    if (!z)
        return std::nullopt;
    const S denominator = S(S(1) + (*z)[0] + S(S(beta * (*z)[n - 1]) / gamma));
    if (denominator == S(0))
        return std::nullopt;
    std::vector<std::vector<S>> solutions;
    solutions.reserve(rightSides.size());
    for (auto& rhs : rightSides) {
        assert(rhs.size() == n);
        auto y = solveTridiagonal(sub, diag, super, std::move(rhs));
        if (!y)
            return std::nullopt;
        const S factor = S(S((*y)[0] + S(S(beta * (*y)[n - 1]) / gamma)) / denominator);
        for (std::size_t i = 0; i < n; ++i) {
            (*y)[i] = S((*y)[i] - S(factor * (*z)[i]));
            if constexpr (std::is_floating_point_v<S>) {
                if (!std::isfinite((*y)[i]))
                    return std::nullopt;
            }
        }
        solutions.push_back(std::move(*y));
    }
    return solutions;
}

/// x solving the cyclic system for one right side (see above).
template <class S>
std::optional<std::vector<S>> solveCyclicTridiagonal(std::vector<S> sub, std::vector<S> diag, std::vector<S> super,
                                                     std::vector<S> rhs)
{
    std::vector<std::vector<S>> rightSides;
    rightSides.push_back(std::move(rhs));
    auto x = solveCyclicTridiagonal(std::move(sub), std::move(diag), std::move(super), std::move(rightSides));
    if (!x)
        return std::nullopt;
    return std::move(x->front());
}

} // namespace granota
