#include "core/bernstein_block.h"

namespace granota {

BernsteinBlock::BernsteinBlock(int n, int maxRows)
    : m_n(n), m_binomial(static_cast<std::size_t>(n + 1), 1.0), m_values(maxRows, n + 1), m_uPowers(maxRows, n + 1),
      m_t(maxRows), m_tPower(maxRows)
{
    // C(n, j), exact in double for the degrees a fit allows (≤ 100: C(100, 50) < 2^97, but the
    // product C(n,j)·(n−j)/(j+1) is exact while it stays below 2^53 and within 1 ulp beyond).
    for (int j = 1; j <= n; ++j)
        m_binomial[static_cast<std::size_t>(j)] = m_binomial[static_cast<std::size_t>(j - 1)] * (n - j + 1) / j;
}

const Eigen::MatrixXd& BernsteinBlock::fill(const double* t, int rows)
{
    auto T = m_t.head(rows);
    for (int i = 0; i < rows; ++i)
        T(i) = t[i];
    m_uPowers.col(0).head(rows).setOnes();
    for (int e = 1; e <= m_n; ++e)
        m_uPowers.col(e).head(rows).array() = m_uPowers.col(e - 1).head(rows).array() * (1.0 - T);
    auto tPower = m_tPower.head(rows);
    tPower.setOnes();
    for (int j = 0; j <= m_n; ++j) {
        m_values.col(j).head(rows).array() =
            m_binomial[static_cast<std::size_t>(j)] * tPower * m_uPowers.col(m_n - j).head(rows).array();
        tPower *= T;
    }
    return m_values;
}

} // namespace granota
