#include "core/tall_skinny_qr.h"

#include "core/bernstein_block.h"

#include <algorithm>
#include <thread>

namespace granota {

namespace {

constexpr int kBlockRows = 1024;           ///< rows per block: the block stays in L2 cache
constexpr std::size_t kParallelRows = 200000; ///< below this, one thread is faster than two

/// R of [M | Q] over the rows [first, last).
Eigen::MatrixXd factorRows(const std::vector<double>& t, const Eigen::MatrixX2d& q, int n, std::size_t first,
                           std::size_t last)
{
    const int m = n + 1, w = m + 2;
    Eigen::MatrixXd block(w + kBlockRows, w);
    Eigen::MatrixXd r = Eigen::MatrixXd::Zero(w, w);
    BernsteinBlock bernstein(n, kBlockRows);
    for (std::size_t s = first; s < last; s += kBlockRows) {
        const int rows = static_cast<int>(std::min<std::size_t>(kBlockRows, last - s));
        block.topRows(w) = r;
        block.block(w, 0, rows, m) = bernstein.fill(t.data() + s, rows).topRows(rows);
        block.col(m).segment(w, rows) = q.col(0).segment(static_cast<Eigen::Index>(s), rows);
        block.col(m + 1).segment(w, rows) = q.col(1).segment(static_cast<Eigen::Index>(s), rows);
        auto active = block.topRows(w + rows);
        Eigen::HouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr(active);
        r = qr.matrixQR().topRows(w).triangularView<Eigen::Upper>();
    }
    return r;
}

} // namespace

Eigen::MatrixXd tallSkinnyQr(const std::vector<double>& t, const Eigen::MatrixX2d& q, int n)
{
    const std::size_t k = t.size();
    const int w = n + 3;
    if (k < kParallelRows)
        return factorRows(t, q, n, 0, k);
    // Two halves (a fixed split: the same answer on one core or two), then R of [R₁; R₂].
    const std::size_t half = (k / 2 / kBlockRows) * kBlockRows;
    Eigen::MatrixXd r1;
    std::thread first([&] { r1 = factorRows(t, q, n, 0, half); });
    const Eigen::MatrixXd r2 = factorRows(t, q, n, half, k);
    first.join();
    Eigen::MatrixXd stacked(2 * w, w);
    stacked << r1, r2;
    Eigen::HouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr(stacked);
    return qr.matrixQR().topRows(w).triangularView<Eigen::Upper>();
}

} // namespace granota
