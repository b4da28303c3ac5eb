#pragma once
/// \file aabb.h
/// An axis-aligned box, the one form of a bounding box in the core: the tight box of a Bézier
/// curve (curve_features.h), the soft bodies' boxes of the broad phase and the contacts
/// (xpbd_broad_phase.h), the boxes of points, and the frame of a curve tab's canvas (finiteBox:
/// each tab adds its own margin). A default box is empty (min > max); a box of one
/// point has zero width and height.

#include "core/base/vec2.h"

#include <algorithm>
#include <optional>
#include <vector>

namespace granota {

struct Aabb {
    double minX = 0;
    double minY = 0;
    double maxX = -1;
    double maxY = -1;

    /// The box of the single point `p`.
    static Aabb around(const Point& p) { return {p.x, p.y, p.x, p.y}; }

    bool empty() const { return !(minX <= maxX && minY <= maxY); }
    double width() const { return maxX - minX; }
    double height() const { return maxY - minY; }
    Point minCorner() const { return {minX, minY}; }
    Point maxCorner() const { return {maxX, maxY}; }

    /// Grows a non-empty box to hold `p` (an empty one becomes around(p)).
    void include(const Point& p)
    {
        if (empty()) {
            *this = around(p);
            return;
        }
        includeX(p.x);
        includeY(p.y);
    }
    void includeX(double x)
    {
        minX = std::min(minX, x);
        maxX = std::max(maxX, x);
    }
    void includeY(double y)
    {
        minY = std::min(minY, y);
        maxY = std::max(maxY, y);
    }

    bool overlaps(const Aabb& o) const { return minX <= o.maxX && o.minX <= maxX && minY <= o.maxY && o.minY <= maxY; }
    bool contains(const Point& p, double margin = 0) const
    {
        return p.x >= minX - margin && p.x <= maxX + margin && p.y >= minY - margin && p.y <= maxY + margin;
    }
};

/// The box of n points (empty for none).
Aabb boundingBox(const Point* x, int n);
/// The box of the finite points of `a` and `b` together (NaN and infinite points skipped);
/// nullopt when none is finite. It may have zero width or height (points on a line, one point).
std::optional<Aabb> finiteBox(const std::vector<Point>& a, const std::vector<Point>& b = {});

} // namespace granota
