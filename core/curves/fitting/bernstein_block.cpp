#include "core/curves/fitting/bernstein_block.h"

namespace granota {

BernsteinBlock::BernsteinBlock(int n, int maxRows)
    : m_n(n), m_binomial(static_cast<std::size_t>(n + 1), 1.0), m_power(static_cast<std::size_t>(maxRows))
{
    // C(n, j), exact in double for the degrees a fit allows (≤ 100: C(100, 50) < 2^97, but the
    // product C(n,j)·(n−j)/(j+1) is exact while it stays below 2^53 and within 1 ulp beyond).
    for (int j = 1; j <= n; ++j)
        m_binomial[static_cast<std::size_t>(j)] = m_binomial[static_cast<std::size_t>(j - 1)] * (n - j + 1) / j;
}

void BernsteinBlock::fillInto(const double* t, int rows, double* out, std::size_t stride)
{
    // Def 2.5 as (C(n,j)·t^j)·(1 − t)^(n−j): the first sweep writes C(n,j)·t^j with the
    // powers of t going up, the second multiplies in (1 − t)^(n−j) with j going down. Each
    // loop runs down a column (contiguous), with no sums: vectorised, and the same numbers
    // on any machine.
    double* const power = m_power.data();
    for (int i = 0; i < rows; ++i)
        power[i] = 1.0;
    for (int j = 0; j <= m_n; ++j) {
        double* const column = out + static_cast<std::size_t>(j) * stride;
        const double c = m_binomial[static_cast<std::size_t>(j)];
        for (int i = 0; i < rows; ++i) {
            column[i] = c * power[i];
            power[i] *= t[i];
        }
    }
    for (int i = 0; i < rows; ++i)
        power[i] = 1.0;
    for (int j = m_n; j >= 0; --j) {
        double* const column = out + static_cast<std::size_t>(j) * stride;
        for (int i = 0; i < rows; ++i) {
            column[i] *= power[i];
            power[i] *= 1.0 - t[i];
        }
    }
}

} // namespace granota
