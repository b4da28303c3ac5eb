#pragma once
/// \file point_extent.h
/// The extent of a list of points: the smallest axis-parallel box that holds its finite
/// points. The curve tabs frame their canvas with it (each adds its own margin: CurveTab's
/// contentBounds()); a box may have zero width or height (points on a line, one point).

#include "core/base/vec2.h"

#include <optional>
#include <vector>

namespace granota::ui {

struct PointExtent {
    double minX = 0, minY = 0, maxX = 0, maxY = 0;

    double width() const { return maxX - minX; }
    double height() const { return maxY - minY; }
    /// Grows the box to hold `p`.
    void include(const Point& p);
};

/// The extent of the finite points of `points`; nullopt when none is finite (or there are none).
std::optional<PointExtent> finiteExtent(const std::vector<Point>& points);
/// The extent of both lists together.
std::optional<PointExtent> finiteExtent(const std::vector<Point>& a, const std::vector<Point>& b);

} // namespace granota::ui
