#pragma once
/// \file polygon_area.h
/// Area of a polygon by the trapezoid rule of §4.5: walk the vertices in order and add,
/// for each edge v_i → v_{i+1}, the trapezoid between the edge and the x axis,
/// (x_i − x_{i+1}) (y_i + y_{i+1}) / 2, signed by the direction of travel. The sum is
/// the signed area (the shoelace formula in disguise); its absolute value is the area.

#include "core/base/vec2.h"

#include <vector>

namespace granota {

/// Signed area, closing the polygon from the last vertex back to the first. With the
/// thesis's screen coordinates (y down) a polygon built as in §4.1 comes out positive.
template <class S> S trapezoidArea(const std::vector<Vec2<S>>& polygon)
{
    S area(0);
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2<S>& a = polygon[i];
        const Vec2<S>& b = polygon[(i + 1) % n];
        area += S(S(a.x - b.x) * S(a.y + b.y));
    }
    return S(area / S(2));
}

/// |trapezoidArea|, as §4.5 takes it "to avoid problems".
inline double polygonArea(const std::vector<Point>& polygon)
{
    const double a = trapezoidArea(polygon);
    return a < 0 ? -a : a;
}

} // namespace granota
