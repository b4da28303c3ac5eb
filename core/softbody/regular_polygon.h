#pragma once
/// \file regular_polygon.h
/// The regular polygon of §4.1, the frog's body at rest:
///   v_i = (c_1 + r cos(θ_0 + i·2π/n), c_2 + r sin(θ_0 + i·2π/n)),  0 ≤ i < n.

#include "core/base/vec2.h"

#include <vector>

namespace granota {

/// θ_0 = −π/2 as in Annex II (`ang = -HALF_PI`): in screen coordinates (y down) the
/// first vertex is the top one and the angle grows clockwise on the screen. §4.1's
/// π/2 + iα would start at the bottom on Processing's screen; read with y up it starts at
/// the top but runs the other way round (docs/thesis-errata.md, “§4.1”).
constexpr double kSeedStartAngle = -1.5707963267948966;

/// `sides` ≥ 3 vertices; radius ≥ 0.
std::vector<Point> regularPolygon(const Point& centre, double radius, int sides, double startAngle = kSeedStartAngle);

} // namespace granota
