#pragma once
/// \file bernstein_block.h
/// Rows of the matrix M of Lemma 2.2 (M(i, j) = B_j^n(t_i)) for a block of parameters at a
/// time, a column at a time: B_j^n(t) = C(n,j) t^j (1−t)^(n−j) (Def 2.5). Every factor is
/// positive, so each entry is accurate to n + 1 roundings like the recursion of Lemma 2.1,
/// and the loops run over contiguous rows, which the compiler vectorises. Used where a fit
/// meets a million points (tall_skinny_qr, the residuals of least_squares_fit).

#include <cstddef>
#include <vector>

namespace granota {

class BernsteinBlock {
public:
    /// Degree n, blocks of at most `maxRows` parameters.
    BernsteinBlock(int n, int maxRows);
    /// B_j^n(t_i) for i < rows, j ≤ n, written column by column: at out[j·stride + i]
    /// (rows ≤ maxRows ≤ stride).
    void fillInto(const double* t, int rows, double* out, std::size_t stride);
    int degree() const { return m_n; }

private:
    int m_n;
    std::vector<double> m_binomial;
    std::vector<double> m_power; ///< maxRows: t^j, then (1 − t)^(n−j), row by row
};

} // namespace granota
