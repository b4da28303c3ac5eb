#include "core/curves/fitting/tall_skinny_qr.h"

#include "core/curves/fitting/bernstein_block.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace granota {

namespace {

constexpr int kBlockRows = 256;               ///< rows per block: 13 columns of them fit in L1
constexpr std::size_t kParallelRows = 200000; ///< below this, one thread is faster than two
static_assert(kBlockRows % 4 == 0, "blocks are processed four rows at a time");

/// x ← x − k·a over n rows (n a multiple of 4), returning Σ p_i·x_i with the new x, in
/// four interleaved partial sums (a fixed order: the same bits on every machine).
double updateAndDot(double* __restrict x, const double* __restrict a, double k, const double* __restrict p, int n)
{
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    for (int i = 0; i < n; i += 4) {
        const double x0 = x[i] - k * a[i], x1 = x[i + 1] - k * a[i + 1];
        const double x2 = x[i + 2] - k * a[i + 2], x3 = x[i + 3] - k * a[i + 3];
        x[i] = x0, x[i + 1] = x1, x[i + 2] = x2, x[i + 3] = x3;
        s0 += p[i] * x0, s1 += p[i + 1] * x1, s2 += p[i + 2] * x2, s3 += p[i + 3] * x3;
    }
    return (s0 + s1) + (s2 + s3);
}

/// The same with p = x: x ← x − k·a, returning Σ x_i² of the new x.
double updateAndSquare(double* __restrict x, const double* __restrict a, double k, int n)
{
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    for (int i = 0; i < n; i += 4) {
        const double x0 = x[i] - k * a[i], x1 = x[i + 1] - k * a[i + 1];
        const double x2 = x[i + 2] - k * a[i + 2], x3 = x[i + 3] - k * a[i + 3];
        x[i] = x0, x[i + 1] = x1, x[i + 2] = x2, x[i + 3] = x3;
        s0 += x0 * x0, s1 += x1 * x1, s2 += x2 * x2, s3 += x3 * x3;
    }
    return (s0 + s1) + (s2 + s3);
}

/// Σ p_i·x_i, in the same order as updateAndDot.
double dotRows(const double* __restrict p, const double* __restrict x, int n)
{
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    for (int i = 0; i < n; i += 4)
        s0 += p[i] * x[i], s1 += p[i + 1] * x[i + 1], s2 += p[i + 2] * x[i + 2], s3 += p[i + 3] * x[i + 3];
    return (s0 + s1) + (s2 + s3);
}

/// The R of [M | Q] over a stream of blocks of rows: each block is stacked under the R
/// so far and reduced to a new R by Householder reflections (Golub & Van Loan, §5.2).
/// The R on top is upper triangular, so the reflector of column j touches row j of R and
/// the block's rows only; a column's norm and the products the next reflector needs are
/// summed while the block is updated, so each column costs one sweep over the block.
class StreamingQr {
public:
    explicit StreamingQr(int n)
        : m_n(n), m_w(n + 3), m_block(static_cast<std::size_t>(m_w) * kBlockRows), m_r(Eigen::MatrixXd::Zero(m_w, m_w)),
          m_gram(static_cast<std::size_t>(m_w)), m_k(static_cast<std::size_t>(m_w)), m_bernstein(n, kBlockRows)
    {
    }

    /// Rows [first, first + rows) of [M | Q].
    void absorb(const double* t, const ScaledPoints& q, std::size_t first, int rows)
    {
        const int m = m_n + 1, padded = (rows + 3) / 4 * 4;
        double* const a = m_block.data();
        const auto column = [a](int c) { return a + static_cast<std::size_t>(c) * kBlockRows; };
        m_bernstein.fillInto(t + first, rows, a, kBlockRows);
        double* const x = column(m);
        double* const y = column(m + 1);
        for (int i = 0; i < rows; ++i) {
            x[i] = q.x(first + static_cast<std::size_t>(i));
            y[i] = q.y(first + static_cast<std::size_t>(i));
        }
        // Rows of zeros up to a multiple of four: a zero row changes no reflector.
        for (int c = 0; c < m_w; ++c)
            std::fill(column(c) + rows, column(c) + padded, 0.0);
        for (int c = 0; c < m_w; ++c)
            m_gram[static_cast<std::size_t>(c)] = dotRows(column(0), column(c), padded);
        for (int j = 0; j < m_w; ++j) {
            // Column j is (R(j, j); a) with a the block's column: its reflector
            // H = I − τ v vᵀ, v = (1; a/(α − β)), sends it to (β; 0) (LAPACK's dlarfg).
            const double sigma = m_gram[static_cast<std::size_t>(j)]; // ‖a‖²
            for (int c = j + 1; c < m_w; ++c)
                m_k[static_cast<std::size_t>(c)] = 0;
            if (sigma > 0) {
                const double alpha = m_r(j, j);
                const double norm = std::sqrt(alpha * alpha + sigma);
                const double beta = alpha >= 0 ? -norm : norm;
                const double tau = (beta - alpha) / beta, inverse = 1 / (alpha - beta);
                for (int c = j + 1; c < m_w; ++c) {
                    // vᵀ(R(j, c); column c) = R(j, c) + (aᵀ column c)/(α − β)
                    const double s = m_r(j, c) + m_gram[static_cast<std::size_t>(c)] * inverse;
                    m_r(j, c) -= tau * s;
                    m_k[static_cast<std::size_t>(c)] = tau * s * inverse;
                }
                m_r(j, j) = beta;
            }
            if (j + 1 == m_w)
                break;
            // Column c ← column c − τ·s_c·v, and the products with the next pivot column.
            const double* const aj = column(j);
            double* const next = column(j + 1);
            m_gram[static_cast<std::size_t>(j + 1)] = updateAndSquare(next, aj, m_k[static_cast<std::size_t>(j + 1)], padded);
            for (int c = j + 2; c < m_w; ++c)
                m_gram[static_cast<std::size_t>(c)] = updateAndDot(column(c), aj, m_k[static_cast<std::size_t>(c)], next, padded);
        }
    }

    const Eigen::MatrixXd& r() const { return m_r; }

private:
    int m_n, m_w;
    std::vector<double> m_block; ///< kBlockRows × w, column by column
    Eigen::MatrixXd m_r;
    std::vector<double> m_gram, m_k;
    BernsteinBlock m_bernstein;
};

/// R of [M | Q] over the rows [first, last).
Eigen::MatrixXd factorRows(const std::vector<double>& t, const ScaledPoints& q, int n, std::size_t first, std::size_t last)
{
    StreamingQr qr(n);
    for (std::size_t s = first; s < last; s += kBlockRows)
        qr.absorb(t.data(), q, s, static_cast<int>(std::min<std::size_t>(kBlockRows, last - s)));
    return qr.r();
}

} // namespace

Eigen::MatrixXd tallSkinnyQr(const std::vector<double>& t, const ScaledPoints& q, int n)
{
    const std::size_t k = t.size();
    const int w = n + 3;
    if (k < kParallelRows)
        return factorRows(t, q, n, 0, k);
    // Two halves (a fixed split: the same answer on one core or two), then R of [R₁; R₂].
    const std::size_t half = (k / 2 / kBlockRows) * kBlockRows;
    Eigen::MatrixXd r1;
    std::thread worker([&] { r1 = factorRows(t, q, n, 0, half); });
    const Eigen::MatrixXd r2 = factorRows(t, q, n, half, k);
    worker.join();
    Eigen::MatrixXd stacked(2 * w, w);
    stacked << r1, r2;
    Eigen::HouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr(stacked);
    return qr.matrixQR().topRows(w).triangularView<Eigen::Upper>();
}

} // namespace granota
