#pragma once
/// \file segment_clip.h
/// The part of a segment inside a rectangle (Liang–Barsky): what a canvas draws of a line
/// whose ends may lie millions of pixels away. Qt's stroker spends seconds on a path with such
/// far-off points (a blown-up seed's trail, issue 34), though only the part in view shows.

#include "core/base/vec2.h"

#include <QRectF>

#include <cmath>
#include <optional>
#include <utility>

namespace granota::ui {

/// The part of the segment a–b inside `box` (its edges included), or nothing when the
/// segment misses it or an end is not finite.
inline std::optional<std::pair<Point, Point>> clipSegment(Point a, Point b, const QRectF& box)
{
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y))
        return std::nullopt;
    const double dx = b.x - a.x, dy = b.y - a.y;
    double t0 = 0, t1 = 1;
    // Each side: p t ≤ q keeps the point a + t (b − a) on the inner side.
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x - box.left(), box.right() - a.x, a.y - box.top(), box.bottom() - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0)
                return std::nullopt; // parallel to this side, and outside it
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1)
            return std::nullopt;
    }
    const Point from = t0 > 0 ? Point(a.x + t0 * dx, a.y + t0 * dy) : a;
    const Point to = t1 < 1 ? Point(a.x + t1 * dx, a.y + t1 * dy) : b;
    return std::pair{from, to};
}

} // namespace granota::ui
