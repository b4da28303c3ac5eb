#include "core/softbody/scenes/scene_layout.h"

#include "core/softbody/outline.h"
#include "core/softbody/regular_polygon.h"

#include <algorithm>
#include <cmath>

namespace granota {

namespace {

double layoutRadius(const SceneSpec& s) { return std::max(1.0, s.params.radius); }
double pitchOf(double r) { return 2.2 * r; } // a little more than a diameter apart

} // namespace

int bodiesPerRow(const SceneSpec& s)
{
    const double r = layoutRadius(s);
    // At most one row of all the bodies (a frame 1e300 px wide holds more than an int counts).
    const double across = (s.params.width - 2 * r) / pitchOf(r);
    return across >= s.bodies ? std::max(1, s.bodies) : std::max(1, static_cast<int>(across));
}

bool bodiesFitFrame(const SceneSpec& s)
{
    if (!s.shapes.empty() || s.bodies <= 1)
        return true;
    const double r = layoutRadius(s);
    const int perRow = bodiesPerRow(s);
    const int rows = (s.bodies + perRow - 1) / perRow;
    const double lastY = 2.1 * r + (rows - 1) * pitchOf(r);
    const double widest = 2.1 * r + (std::min(perRow, s.bodies) - 1) * pitchOf(r) + (rows > 1 ? 0.5 * r : 0);
    return lastY + r <= s.params.height && widest + r <= s.params.width;
}

FrameSize frameForBodies(const SceneSpec& scene, int bodies)
{
    const int before = std::max(1, scene.bodies);
    FrameSize f{scene.params.width, scene.params.height};
    if (bodies > before) {
        const double grow = std::sqrt(static_cast<double>(bodies) / before);
        f.width = std::round(f.width * grow);
        f.height = std::round(f.height * grow);
    }
    SceneSpec s = scene;
    s.bodies = bodies;
    s.params.width = f.width;
    s.params.height = f.height;
    if (!bodiesFitFrame(s)) {
        const double r = layoutRadius(s);
        const int perRow = bodiesPerRow(s);
        const int rows = (bodies + perRow - 1) / perRow;
        f.height = std::max(f.height, std::ceil(2.1 * r + (rows - 1) * pitchOf(r) + r));
    }
    return f;
}

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
    const double w = s.params.width, h = s.params.height, r = layoutRadius(s);
    const double pitch = pitchOf(r);
    const int perRow = bodiesPerRow(s);
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
    if (s.has(SceneComponent::OutlineBezier) && s.bezierSamples >= 3) // §4.9: the precomputed points
        return bezierBodyPoints(regularPolygon(Point(0, 0), s.params.radius, s.params.sides), s.bezierSamples);
    return std::nullopt;
}

} // namespace granota
