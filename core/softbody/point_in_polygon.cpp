#include "core/softbody/point_in_polygon.h"

namespace granota {

bool pointInPolygon(const Point& p, const std::vector<Point>& polygon)
{
    bool inside = false;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Point& a = polygon[i];
        const Point& b = polygon[(i + 1) % n];
        const bool spans = (a.x <= p.x && p.x < b.x) || (b.x <= p.x && p.x < a.x);
        if (!spans)
            continue;
        // y of the edge at p.x; a.x != b.x here because the interval is non-empty.
        const double y = a.y + (p.x - a.x) / (b.x - a.x) * (b.y - a.y);
        if (p.y <= y)
            inside = !inside;
    }
    return inside;
}

} // namespace granota
