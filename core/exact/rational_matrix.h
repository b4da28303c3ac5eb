#pragma once
/// \file rational_matrix.h
/// A small dense matrix of exact rationals, for the thesis's matrices M, MᵀM, (MᵀM)⁻¹ and
/// M⁺ = (MᵀM)⁻¹Mᵀ of §2.1.3 (Lemma 2.2, Nota 2.2), shown as fractions in Ex 2.7 and Ex 2.8.
/// Sizes are small (tens of rows and columns): the algorithms are the textbook ones.

#include "core/base/expected.h"
#include "core/exact/rational.h"

#include <Eigen/Core>

#include <cassert>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

namespace granota {

class RationalMatrix {
public:
    /// The empty 0×0 matrix.
    RationalMatrix() = default;
    /// A rows×cols matrix of zeros (negative sizes are treated as 0).
    RationalMatrix(int rows, int cols);
    /// Row by row: RationalMatrix{{1, 0}, {Rational(9, 16), Rational(3, 8)}}. All rows must
    /// have the same length.
    RationalMatrix(std::initializer_list<std::initializer_list<Rational>> rows);
    static RationalMatrix identity(int n);

    int rows() const { return m_rows; }
    int cols() const { return m_cols; }
    Rational& operator()(int r, int c) { return m_a[index(r, c)]; }
    const Rational& operator()(int r, int c) const { return m_a[index(r, c)]; }

    RationalMatrix transpose() const;

    /// Exact inverse by Gauss–Jordan elimination, pivoting on the first nonzero entry of
    /// each column (exact arithmetic needs no other pivoting). Singular when there is no
    /// nonzero pivot, InvalidInput when the matrix is not square.
    Expected<RationalMatrix> inverse() const;
    /// X with (*this)·X = b, for a square nonsingular matrix and any number of right-hand
    /// sides (the columns of b). Same errors as inverse(), InvalidInput on a shape mismatch.
    Expected<RationalMatrix> solve(const RationalMatrix& b) const;

    /// Nearest doubles (mpq_get_d, i.e. truncated: at most one ulp off).
    Eigen::MatrixXd toDouble() const;

    /// Matrix product; precondition a.cols() == b.rows().
    friend RationalMatrix operator*(const RationalMatrix& a, const RationalMatrix& b);
    friend bool operator==(const RationalMatrix& a, const RationalMatrix& b)
    {
        return a.m_rows == b.m_rows && a.m_cols == b.m_cols && a.m_a == b.m_a;
    }
    friend bool operator!=(const RationalMatrix& a, const RationalMatrix& b) { return !(a == b); }

private:
    std::size_t index(int r, int c) const
    {
        assert(r >= 0 && r < m_rows && c >= 0 && c < m_cols);
        return static_cast<std::size_t>(r) * static_cast<std::size_t>(m_cols) + static_cast<std::size_t>(c);
    }

    int m_rows = 0;
    int m_cols = 0;
    std::vector<Rational> m_a; // row-major
};

/// Matlab-style text, rows separated by "; ": "[1, 0, 0; 9/16, 3/8, 1/16]". (Named toText,
/// like the polynomial texts, so that QCOMPARE on matrices does not pick it up by ADL.)
std::string toText(const RationalMatrix& m);

} // namespace granota
