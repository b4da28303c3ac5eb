#include "core/base/aabb.h"

namespace granota {

Aabb boundingBox(const Point* x, int n)
{
    Aabb b;
    if (n <= 0)
        return b;
    b.minX = b.maxX = x[0].x;
    b.minY = b.maxY = x[0].y;
    for (int i = 1; i < n; ++i) {
        b.minX = std::min(b.minX, x[i].x);
        b.maxX = std::max(b.maxX, x[i].x);
        b.minY = std::min(b.minY, x[i].y);
        b.maxY = std::max(b.maxY, x[i].y);
    }
    return b;
}

std::optional<Aabb> finiteBox(const std::vector<Point>& a, const std::vector<Point>& b)
{
    Aabb box;
    for (const auto* list : {&a, &b})
        for (const Point& p : *list)
            if (isFinite(p))
                box.include(p);
    if (box.empty())
        return std::nullopt;
    return box;
}

} // namespace granota
