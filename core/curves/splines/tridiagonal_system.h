#pragma once
/// \file tridiagonal_system.h
/// A tridiagonal linear system  sub[i]·x[i−1] + diag[i]·x[i] + super[i]·x[i+1] = rhs[i],
/// solved by Gaussian elimination with partial pivoting (as LAPACK's ?gtsv): a row swap
/// fills one more diagonal above. The cubic splines' systems (cubic_spline.h) are
/// diagonally dominant for natural and clamped ends, but not always for not-a-knot and
/// Ex 2.1's ends, where elimination without pivoting can meet a zero pivot. Exact over
/// Rational (where "largest" is only used to avoid zero), stable in floating point.

#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace granota {

/// x solving the system, or nullopt when it is singular (a zero pivot remains after
/// pivoting) or, in floating point, the result is not finite. sub[0] and super[n−1] are
/// ignored. All four vectors have size n ≥ 1.
template <class S>
std::optional<std::vector<S>> solveTridiagonal(std::vector<S> sub, std::vector<S> diag, std::vector<S> super, std::vector<S> rhs)
{
    using std::abs;
    const std::size_t n = diag.size();
    std::vector<S> super2(n, S(0)); // the fill of a row swap: x[i+2]'s coefficient in row i
    for (std::size_t i = 0; i + 1 < n; ++i) {
        // Rows i and i+1 hold x[i] with coefficients diag[i] and sub[i+1]: the larger leads.
        if (abs(S(sub[i + 1])) > abs(S(diag[i]))) {
            std::swap(diag[i], sub[i + 1]);
            std::swap(super[i], diag[i + 1]);
            std::swap(rhs[i], rhs[i + 1]);
            // Row i+1 (now row i) may reach x[i+2]; the old row i did not.
            super2[i] = i + 2 < n ? super[i + 1] : S(0);
            if (i + 2 < n)
                super[i + 1] = S(0);
        }
        if (diag[i] == S(0))
            return std::nullopt;
        const S factor = S(sub[i + 1] / diag[i]);
        diag[i + 1] = S(diag[i + 1] - S(factor * super[i]));
        if (i + 2 < n)
            super[i + 1] = S(super[i + 1] - S(factor * super2[i]));
        rhs[i + 1] = S(rhs[i + 1] - S(factor * rhs[i]));
    }
    if (diag[n - 1] == S(0))
        return std::nullopt;
    std::vector<S> x(n);
    for (std::size_t i = n; i-- > 0;) {
        S value = rhs[i];
        if (i + 1 < n)
            value = S(value - S(super[i] * x[i + 1]));
        if (i + 2 < n)
            value = S(value - S(super2[i] * x[i + 2]));
        x[i] = S(value / diag[i]);
        if constexpr (std::is_floating_point_v<S>) {
            if (!std::isfinite(x[i]))
                return std::nullopt;
        }
    }
    return x;
}

} // namespace granota
