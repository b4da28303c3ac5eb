#pragma once
/// \file xpbd_broad_phase.h
/// The broad phase of the many-bodies scene (§5.2.2): which pairs of bodies are close
/// enough to need the exact (vertex-in-polygon) test. §5.2.2 proposes "fer comprovacions
/// amb quadrícules cada cop més fines": here one uniform grid of axis-aligned boxes, the
/// cheap first level. Each box goes into the cells it covers; a pair is tested only when
/// both share a cell, and reported once, by the cell that holds the top-left corner of
/// their overlap (Ericson, "Real-Time Collision Detection", §7.1). With bodies of similar
/// size the work grows linearly with the number of bodies instead of quadratically.

#include "core/base/vec2.h"
#include "core/softbody/polygon_geometry.h" // Aabb, boundingBox

#include <vector>

namespace granota {

/// Two bodies whose boxes overlap, first < second.
struct BodyPair {
    int first = 0;
    int second = 0;
    friend bool operator==(const BodyPair& a, const BodyPair& b) { return a.first == b.first && a.second == b.second; }
    friend bool operator<(const BodyPair& a, const BodyPair& b)
    {
        return a.first != b.first ? a.first < b.first : a.second < b.second;
    }
};

/// Every overlapping pair by testing all n(n−1)/2 of them: the reference for the grid.
void bruteForcePairs(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs);

/// The uniform grid. Keeps its buffers between calls, so that after the first steps it
/// allocates nothing. Output order is deterministic (cells in order, bodies by index).
class UniformGridBroadPhase {
public:
    /// Fills `pairs` with every pair of overlapping boxes (empty boxes never overlap).
    void findPairs(const std::vector<Aabb>& boxes, std::vector<BodyPair>& pairs);

    /// Makes room for `boxes` boxes, so that findPairs allocates nothing for up to that many
    /// (except for an unusually large number of overlapping pairs).
    void reserve(int boxes);

    /// Side of the cells of the last call, px (for overlays).
    double cellSize() const { return m_cell; }

private:
    double m_cell = 1;
    double m_originX = 0;
    double m_originY = 0;
    int m_nx = 0;
    int m_ny = 0;
    std::vector<int> m_cellStart; // CSR layout: entries of cell c are m_entries[start[c] .. start[c+1])
    std::vector<int> m_entries;
    std::vector<int> m_range; // per box: x0, y0, x1, y1 cell range, or x0 = −1 if not in the grid
    std::vector<int> m_large; // boxes covering too many cells: tested against every box
};

} // namespace granota
