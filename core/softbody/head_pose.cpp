#include "core/softbody/head_pose.h"

#include <cmath>

namespace granota {

HeadPose annexIIHeadPose(const std::vector<Point>& vertices)
{
    if (vertices.empty())
        return {};
    // The corner (integer halves of the size, as Java divides ints) plus half the size (exact).
    const Point corner(vertices[0].x - 1109 / 16, vertices[0].y - 747 / 16);
    return {Point(corner.x + kHeadImageWidth / 2.0, corner.y + kHeadImageHeight / 2.0), 0.0};
}

HeadPose turningHeadPose(const std::vector<Point>& vertices)
{
    const std::size_t n = vertices.size();
    if (n == 0)
        return {};
    if (n < 3)
        return {vertices[0], 0.0};
    const Point along = vertices[1] - vertices[n - 1];
    return {vertices[0], norm(along) > 1e-9 ? std::atan2(along.y, along.x) : 0.0};
}

} // namespace granota
