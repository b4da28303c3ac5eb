#pragma once
/// \file head_pose.h
/// Where the frog's head is drawn (docs/scenes.md, component `head`): the centre of the head's
/// box, which Annex II fills with cap_granota.png, and the angle the box is turned by. The
/// Frog tab draws its own head art in that box; the tests check the pose.

#include "core/base/vec2.h"

#include <vector>

namespace granota {

struct HeadPose {
    Point centre;     ///< the centre of the head's box, px
    double angle = 0; ///< radians, screen coordinates (y down): 0 = upright
};

/// Annex II's head image, 1109/8 × 747/8 px in Java's integer division: 138 × 93.
inline constexpr int kHeadImageWidth = 1109 / 8;
inline constexpr int kHeadImageHeight = 747 / 8;

/// Annex II, Granota.dibuixar (l. 543): image(cap, vert[0].x − 1109/16, vert[0].y − 747/16,
/// 1109/8, 747/8). In integer division the corner is vertex 0 − (69, 46) and the image is
/// 138 × 93, so its centre is vertex 0 + (0, ½); image() never turns it, whatever the body
/// does. (0, 0) pose if there is no vertex.
HeadPose annexIIHeadPose(const std::vector<Point>& vertices);

/// Granota's turning head (the stable solver): centred on vertex 0 and turned with the body,
/// along the chord v_{N−1} → v_1 across vertex 0 (0 when that chord is shorter than 1e-9).
HeadPose turningHeadPose(const std::vector<Point>& vertices);

} // namespace granota
