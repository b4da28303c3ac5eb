#pragma once
/// \file point_in_polygon.h
/// Is a point inside a polygon? The crossing test of §4.6: start "outside", walk the
/// edges, and flip each time the point lies between the x of an edge's ends and on one
/// side (above, in screen coordinates) of that edge.

#include "core/base/vec2.h"

#include <vector>

namespace granota {

/// Unlike the seed's `estadins`, the x interval is half-open, [min x, max x), so that a
/// vertical line through a vertex counts the two edges meeting there once, not twice,
/// and vertical edges are skipped: the answer is then right for every point not on the
/// boundary. Works for any simple polygon, convex or not, in either orientation.
bool pointInPolygon(const Point& p, const std::vector<Point>& polygon);

} // namespace granota
