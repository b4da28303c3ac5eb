#pragma once
/// \file grab_mode.h
/// Which vertices of a body hold on to the mouse when it is grabbed: the three choices of
/// chapter 4, one scene parameter (`grab`, docs/scenes.md) that both solvers obey — the seed
/// with springs to the mouse (SeedBody), the stable solver with grab constraints (XpbdWorld).

namespace granota {

/// Which vertices hold on to the mouse when a body is grabbed.
enum class GrabMode {
    All,     ///< §4.6: every vertex, at its distance from the grab point
    Above,   ///< §4.7: the vertices above the grab point (smaller screen y)
    Anchors, ///< §4.10, §4.16: Annex II's fixed anchors {0, 1, N−1, N} (l. 361–372), vertex N being vertex 0
};

} // namespace granota
