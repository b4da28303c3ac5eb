#pragma once
/// \file fit_error_by_degree.h
/// The least-squares error Σ‖Q_i − α(t_i)‖² (Prop 2.2) of the best Bézier curve of each
/// degree n = 1, 2, …, for fixed parameters t_i: the "error against degree" plot of the
/// fitting tab. With fixed t_i the curves of degree ≤ n are a subspace of those of degree
/// ≤ n + 1 (degree elevation), so the optimal error never increases with n — up to
/// rounding, and as long as the solver is stable (the normal equations break first).

#include "core/curves/fitting/least_squares_fit.h"

#include <cstddef>
#include <vector>

namespace granota {

struct DegreeError {
    int degree = 0;
    double sse = 0;  ///< Σ‖Q_i − α(t_i)‖²
    double cond = 1; ///< cond₂(M)
    bool ok = false; ///< false when that fit failed (e.g. the normal equations broke down)
};

/// Fits every degree 1..maxDegree (capped at k, the number of data points minus one) with
/// `options` (its degree is ignored). To keep the work bounded for huge data sets, stops
/// before the degree at which (k + 1)·(n + 1) would exceed `entryBudget` matrix entries;
/// `*truncated` (when given) tells whether that cut the list short.
std::vector<DegreeError> fitErrorByDegree(const std::vector<Point>& q, FitOptions options, int maxDegree,
                                          std::size_t entryBudget = 4000000, bool* truncated = nullptr);

} // namespace granota
