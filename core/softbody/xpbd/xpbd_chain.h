#pragma once
/// \file xpbd_chain.h
/// Chains of joints for the stable solver: the pendulum of §4.13–4.15 and the frog's legs
/// of §4.16. A chain is a row of joints joined by links of fixed length; its first joint
/// (the seed's "clau", the nail) sits on a fixed point or on a point of a body between two
/// of its vertices, as Annex II l. 553–563 places the shoulders. Links may carry angle
/// limits (§4.15).

#include "core/softbody/scenes/frog_params.h"
#include "core/base/math_constants.h"
#include "core/base/vec2.h"

#include <vector>

namespace granota {

/// What a link's angle is measured from. Angles follow the seed (Annex II l. 466–491): 0 is
/// straight down the screen, growing towards −x, in radians.
enum class AngleReference {
    /// From the downward vertical, whatever the body does (the seed's legs).
    World,
    /// From the previous link; for the first link, from the anchor's two vertices as they
    /// have turned since the chain was added.
    Parent,
};

struct AngleLimit {
    double min = -kPi; ///< rad, in [−π, π]
    double max = kPi;  ///< rad, in [min, π]
    AngleReference reference = AngleReference::Parent;
};

/// Where a chain's first joint sits.
struct ChainAnchor {
    int body = -1;   ///< body index, or −1 for the fixed point `point`
    int vertexA = 0; ///< the anchor is (1 − t)·v_A + t·v_B of that body
    int vertexB = 0;
    double t = 0; ///< in [0, 1]
    Point point;  ///< the fixed anchor, px (body = −1); move it with XpbdWorld::moveChainAnchor
};

struct ChainDef {
    ChainAnchor anchor;
    /// Initial joint positions, px; the chain is moved as a whole so that the first one sits
    /// on the anchor. Link lengths are the distances between consecutive joints (Annex II
    /// l. 419–420), each > 0.
    std::vector<Point> joints;
    /// One limit per link (joints.size() − 1 entries), or empty for free links.
    std::vector<AngleLimit> limits;
    double jointMass = 1; ///< mass of each joint, mass units (> 0)
    /// Whether a chain hanging from a body pulls it (its first link acts on the body's two
    /// vertices). false: the chain follows the body and never acts on it, as Annex II's legs
    /// (§4.16, Granota.actualitza places the shoulders, then steps the legs); its first
    /// limit may then not be measured from the body (AngleReference::Parent).
    bool pullsBody = true;
};

/// The shoulder of leg `leg` (FrogParams::legs order: front right, front left, back right,
/// back left) on a body of `sides` vertices, as Annex II l. 553–563 computes it for 10:
/// front legs at 1/5 and 4/5 of the way from vertex 2 to vertex 8, back legs at the
/// middle of vertices 6–7 and 3–4. Other side counts scale the indices by sides/10.
ChainAnchor frogLegAnchor(int body, int leg, int sides);

/// A two-link leg hanging straight down from `shoulder`, with the seed's lengths and its
/// absolute angle limits (AngleReference::World), Annex II l. 411–423. Like the seed's, it
/// hangs from the body without acting on it (pullsBody = false): a frog whose rigid legs
/// carried its body would land standing on them, a balance it tips over from onto its side.
ChainDef frogLegChain(const LegParams& leg, const ChainAnchor& anchor, Point shoulder, double jointMass = 0.25);

} // namespace granota
