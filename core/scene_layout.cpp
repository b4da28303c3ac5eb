#include "core/scene_layout.h"

#include "core/outline.h"
#include "core/regular_polygon.h"

#include <algorithm>

namespace granota {

std::vector<Point> bodyStarts(const SceneSpec& s)
{
    std::vector<Point> at;
    if (!s.shapes.empty()) {
        for (const auto& sh : s.shapes)
            at.push_back(sh.at);
        return at;
    }
    if (s.bodies <= 1)
        return {s.params.center};
    const double w = s.params.width, h = s.params.height, r = std::max(1.0, s.params.radius);
    const double pitch = 2.2 * r; // a little more than a diameter apart
    // At most one row of all the bodies (a frame 1e300 px wide holds more than an int counts).
    const double across = (w - 2 * r) / pitch;
    const int perRow = across >= s.bodies ? s.bodies : std::max(1, static_cast<int>(across));
    for (int i = 0; i < s.bodies; ++i) {
        const int row = i / perRow, col = i % perRow;
        const double x = 2.1 * r + col * pitch + (row % 2) * 0.5 * r; // every other row shifted
        const double y = 2.1 * r + row * pitch;
        at.emplace_back(std::min(x, w - 1), std::min(y, h - 1));
    }
    return at;
}

std::optional<std::vector<Point>> customRestShape(const SceneSpec& s, std::size_t i)
{
    if (!s.shapes.empty())
        return s.shapes[i].points;
    if (s.has("outline-bezier") && s.bezierSamples >= 3) // §4.9: the precomputed points
        return bezierBodyPoints(regularPolygon(Point(0, 0), s.params.radius, s.params.sides), s.bezierSamples);
    return std::nullopt;
}

} // namespace granota
