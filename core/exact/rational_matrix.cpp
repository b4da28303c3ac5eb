#include "core/exact/rational_matrix.h"

#include <algorithm>
#include <utility>

namespace granota {

RationalMatrix::RationalMatrix(int rows, int cols)
    : m_rows(std::max(rows, 0)), m_cols(std::max(cols, 0)),
      m_a(static_cast<std::size_t>(m_rows) * static_cast<std::size_t>(m_cols), Rational(0))
{
}

RationalMatrix::RationalMatrix(std::initializer_list<std::initializer_list<Rational>> rows)
{
    m_rows = static_cast<int>(rows.size());
    m_cols = m_rows > 0 ? static_cast<int>(rows.begin()->size()) : 0;
    m_a.reserve(static_cast<std::size_t>(m_rows) * static_cast<std::size_t>(m_cols));
    for (const auto& row : rows) {
        assert(static_cast<int>(row.size()) == m_cols);
        m_a.insert(m_a.end(), row.begin(), row.end());
    }
}

RationalMatrix RationalMatrix::identity(int n)
{
    RationalMatrix id(n, n);
    for (int i = 0; i < n; ++i)
        id(i, i) = 1;
    return id;
}

RationalMatrix RationalMatrix::transpose() const
{
    RationalMatrix t(m_cols, m_rows);
    for (int r = 0; r < m_rows; ++r)
        for (int c = 0; c < m_cols; ++c)
            t(c, r) = (*this)(r, c);
    return t;
}

RationalMatrix operator*(const RationalMatrix& a, const RationalMatrix& b)
{
    assert(a.cols() == b.rows());
    // Each row of a and each column of b is brought to a common denominator once, so that
    // every entry of the product is an integer dot product and a single canonicalisation
    // (instead of a gcd after every addition): several times faster for M⁺ = (MᵀM)⁻¹Mᵀ.
    const int rows = a.rows(), inner = a.cols(), cols = b.cols();
    const auto at = [](int r, int c, int stride) {
        return static_cast<std::size_t>(r) * static_cast<std::size_t>(stride) + static_cast<std::size_t>(c);
    };
    std::vector<mpz_class> aNum(static_cast<std::size_t>(rows) * static_cast<std::size_t>(inner));
    std::vector<mpz_class> aDen(static_cast<std::size_t>(rows), mpz_class(1));
    for (int r = 0; r < rows; ++r) {
        mpz_class& L = aDen[static_cast<std::size_t>(r)];
        for (int k = 0; k < inner; ++k)
            mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), a(r, k).get_den_mpz_t());
        for (int k = 0; k < inner; ++k) {
            mpz_class& x = aNum[at(r, k, inner)];
            mpz_divexact(x.get_mpz_t(), L.get_mpz_t(), a(r, k).get_den_mpz_t());
            x *= a(r, k).get_num();
        }
    }
    std::vector<mpz_class> bNum(static_cast<std::size_t>(inner) * static_cast<std::size_t>(cols));
    std::vector<mpz_class> bDen(static_cast<std::size_t>(cols), mpz_class(1));
    for (int c = 0; c < cols; ++c) {
        mpz_class& L = bDen[static_cast<std::size_t>(c)];
        for (int k = 0; k < inner; ++k)
            mpz_lcm(L.get_mpz_t(), L.get_mpz_t(), b(k, c).get_den_mpz_t());
        for (int k = 0; k < inner; ++k) {
            mpz_class& x = bNum[at(k, c, cols)];
            mpz_divexact(x.get_mpz_t(), L.get_mpz_t(), b(k, c).get_den_mpz_t());
            x *= b(k, c).get_num();
        }
    }
    RationalMatrix p(rows, cols);
    mpz_class sum;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            sum = 0;
            for (int k = 0; k < inner; ++k)
                mpz_addmul(sum.get_mpz_t(), aNum[at(r, k, inner)].get_mpz_t(), bNum[at(k, c, cols)].get_mpz_t());
            Rational& entry = p(r, c);
            mpz_swap(entry.get_num_mpz_t(), sum.get_mpz_t());
            mpz_mul(entry.get_den_mpz_t(), aDen[static_cast<std::size_t>(r)].get_mpz_t(),
                    bDen[static_cast<std::size_t>(c)].get_mpz_t());
            entry.canonicalize();
        }
    return p;
}

Expected<RationalMatrix> RationalMatrix::solve(const RationalMatrix& rhs) const
{
    if (m_rows != m_cols)
        return makeError(ErrorCode::InvalidInput, "only a square matrix can be inverted: this one is " + std::to_string(m_rows) +
                                                      "×" + std::to_string(m_cols));
    if (rhs.rows() != m_rows)
        return makeError(ErrorCode::InvalidInput,
                         "right-hand side has " + std::to_string(rhs.rows()) + " rows, the matrix " + std::to_string(m_rows));
    const int n = m_rows;
    const int p = rhs.cols();
    RationalMatrix a = *this;
    RationalMatrix x = rhs;
    Rational term;
    // Gauss–Jordan: reduce [A | B] to [I | A⁻¹B].
    for (int col = 0; col < n; ++col) {
        int pivot = col;
        while (pivot < n && sgn(a(pivot, col)) == 0)
            ++pivot;
        if (pivot == n)
            return makeError(ErrorCode::Singular,
                             "the matrix is singular (no nonzero pivot in column " + std::to_string(col + 1) + ")");
        if (pivot != col) {
            for (int c = 0; c < n; ++c)
                std::swap(a(pivot, c), a(col, c));
            for (int c = 0; c < p; ++c)
                std::swap(x(pivot, c), x(col, c));
        }
        const Rational inv = Rational(1 / a(col, col));
        for (int c = col; c < n; ++c)
            a(col, c) *= inv;
        for (int c = 0; c < p; ++c)
            x(col, c) *= inv;
        for (int r = 0; r < n; ++r) {
            if (r == col || sgn(a(r, col)) == 0)
                continue;
            const Rational f = a(r, col);
            for (int c = col; c < n; ++c) {
                mpq_mul(term.get_mpq_t(), f.get_mpq_t(), a(col, c).get_mpq_t());
                mpq_sub(a(r, c).get_mpq_t(), a(r, c).get_mpq_t(), term.get_mpq_t());
            }
            for (int c = 0; c < p; ++c) {
                mpq_mul(term.get_mpq_t(), f.get_mpq_t(), x(col, c).get_mpq_t());
                mpq_sub(x(r, c).get_mpq_t(), x(r, c).get_mpq_t(), term.get_mpq_t());
            }
        }
    }
    return x;
}

Expected<RationalMatrix> RationalMatrix::inverse() const { return solve(identity(m_rows)); }

Eigen::MatrixXd RationalMatrix::toDouble() const
{
    Eigen::MatrixXd d(m_rows, m_cols);
    for (int r = 0; r < m_rows; ++r)
        for (int c = 0; c < m_cols; ++c)
            d(r, c) = (*this)(r, c).get_d();
    return d;
}

std::string toText(const RationalMatrix& m)
{
    std::string s = "[";
    for (int r = 0; r < m.rows(); ++r) {
        if (r > 0)
            s += "; ";
        for (int c = 0; c < m.cols(); ++c) {
            if (c > 0)
                s += ", ";
            s += toString(m(r, c));
        }
    }
    return s + "]";
}

} // namespace granota
