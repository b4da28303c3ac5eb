#include "core/softbody/xpbd/xpbd_broad_phase.h"

#include <algorithm>
#include <cmath>

namespace granota {

namespace {

bool usable(const Aabb& b)
{
    return std::isfinite(b.minX) && std::isfinite(b.minY) && std::isfinite(b.maxX) && std::isfinite(b.maxY) && b.minX <= b.maxX &&
           b.minY <= b.maxY;
}

/// A box covering more cells than this is kept out of the grid (a body of target area 1e9
/// among small ones would otherwise fill every cell) and tested against every box.
constexpr int kMaxCellsPerBox = 16;

} // namespace

void bruteForcePairs(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs)
{
    pairs.clear();
    const int n = static_cast<int>(boxes.size());
    for (int i = 0; i < n; ++i) {
        if (!usable(boxes[i]))
            continue;
        for (int j = i + 1; j < n; ++j)
            if (usable(boxes[j]) && boxes[i].overlaps(boxes[j]))
                pairs.push_back({i, j});
    }
}

void UniformGridBroadPhase::reserve(int boxes)
{
    const std::size_t n = static_cast<std::size_t>(std::max(boxes, 0));
    m_range.reserve(4 * n);
    m_cellStart.reserve(4 * n + 64 + 2);    // the cap on the number of cells, + 1
    m_entries.reserve(kMaxCellsPerBox * n); // a box in the grid covers at most that many cells
    m_large.reserve(n);
}

void UniformGridBroadPhase::findPairs(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs)
{
    pairs.clear();
    const int n = static_cast<int>(boxes.size());
    Aabb all;
    double extentSum = 0;
    int valid = 0;
    for (const Aabb& b : boxes) {
        if (!usable(b))
            continue;
        if (valid == 0) {
            all = b;
        } else {
            all.minX = std::min(all.minX, b.minX);
            all.minY = std::min(all.minY, b.minY);
            all.maxX = std::max(all.maxX, b.maxX);
            all.maxY = std::max(all.maxY, b.maxY);
        }
        extentSum += std::max(b.maxX - b.minX, b.maxY - b.minY);
        ++valid;
    }
    if (valid < 2)
        return;

    // Cells as large as an average box: a typical box then covers at most four cells and a
    // cell holds a handful of boxes. The number of cells is capped at a few per box.
    double cell = extentSum / valid;
    if (!(cell > 0))
        cell = std::max({all.maxX - all.minX, all.maxY - all.minY, 1.0});
    const double maxCells = 4.0 * valid + 64;
    double nx = std::floor((all.maxX - all.minX) / cell) + 1;
    double ny = std::floor((all.maxY - all.minY) / cell) + 1;
    while (nx * ny > maxCells) {
        cell *= 2;
        nx = std::floor((all.maxX - all.minX) / cell) + 1;
        ny = std::floor((all.maxY - all.minY) / cell) + 1;
    }
    m_cell = cell;
    m_originX = all.minX;
    m_originY = all.minY;
    m_nx = static_cast<int>(nx);
    m_ny = static_cast<int>(ny);
    const int cells = m_nx * m_ny;

    const auto cellX = [&](double x) { return std::clamp(static_cast<int>((x - m_originX) / m_cell), 0, m_nx - 1); };
    const auto cellY = [&](double y) { return std::clamp(static_cast<int>((y - m_originY) / m_cell), 0, m_ny - 1); };

    // Counting sort of the (box, cell) entries into a compressed row layout.
    m_range.assign(static_cast<std::size_t>(4 * n), -1);
    m_cellStart.assign(static_cast<std::size_t>(cells + 1), 0);
    m_large.clear();
    int total = 0;
    for (int i = 0; i < n; ++i) {
        const Aabb& b = boxes[static_cast<std::size_t>(i)];
        if (!usable(b))
            continue;
        const int x0 = cellX(b.minX), x1 = cellX(b.maxX), y0 = cellY(b.minY), y1 = cellY(b.maxY);
        if ((x1 - x0 + 1) * (y1 - y0 + 1) > kMaxCellsPerBox) {
            m_large.push_back(i);
            continue;
        }
        int* r = &m_range[static_cast<std::size_t>(4 * i)];
        r[0] = x0, r[1] = y0, r[2] = x1, r[3] = y1;
        for (int cy = y0; cy <= y1; ++cy)
            for (int cx = x0; cx <= x1; ++cx)
                ++m_cellStart[static_cast<std::size_t>(cy * m_nx + cx)];
        total += (x1 - x0 + 1) * (y1 - y0 + 1);
    }
    for (int c = 1; c <= cells; ++c) // inclusive prefix sums: start[c] = end of cell c
        m_cellStart[static_cast<std::size_t>(c)] += m_cellStart[static_cast<std::size_t>(c - 1)];
    m_entries.resize(static_cast<std::size_t>(total));
    for (int i = n - 1; i >= 0; --i) { // backwards, so that each cell lists its boxes in increasing order
        const int* r = &m_range[static_cast<std::size_t>(4 * i)];
        if (r[0] < 0)
            continue;
        for (int cy = r[1]; cy <= r[3]; ++cy)
            for (int cx = r[0]; cx <= r[2]; ++cx)
                m_entries[static_cast<std::size_t>(--m_cellStart[static_cast<std::size_t>(cy * m_nx + cx)])] = i;
    }
    m_cellStart[static_cast<std::size_t>(cells)] = total;

    for (int c = 0; c < cells; ++c) {
        const int begin = m_cellStart[static_cast<std::size_t>(c)];
        const int end = m_cellStart[static_cast<std::size_t>(c + 1)];
        for (int a = begin; a < end; ++a) {
            const int i = m_entries[static_cast<std::size_t>(a)];
            const Aabb& bi = boxes[static_cast<std::size_t>(i)];
            for (int b = a + 1; b < end; ++b) {
                const int j = m_entries[static_cast<std::size_t>(b)];
                const Aabb& bj = boxes[static_cast<std::size_t>(j)];
                if (!bi.overlaps(bj))
                    continue;
                // Report the pair only from the cell holding the top-left corner of the
                // overlap: that point lies in both boxes, so both are listed in that cell.
                const int home = cellY(std::max(bi.minY, bj.minY)) * m_nx + cellX(std::max(bi.minX, bj.minX));
                if (home == c)
                    pairs.push_back({i, j});
            }
        }
    }
    for (std::size_t a = 0; a < m_large.size(); ++a) {
        const int i = m_large[a];
        for (int j = 0; j < n; ++j) {
            if (j == i || !usable(boxes[static_cast<std::size_t>(j)]))
                continue;
            const bool jLarge = m_range[static_cast<std::size_t>(4 * j)] < 0;
            if (jLarge && j < i) // a pair of two large boxes is reported by the smaller index
                continue;
            if (boxes[static_cast<std::size_t>(i)].overlaps(boxes[static_cast<std::size_t>(j)]))
                pairs.push_back({std::min(i, j), std::max(i, j)});
        }
    }
}

} // namespace granota
