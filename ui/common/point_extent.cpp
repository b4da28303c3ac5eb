#include "ui/common/point_extent.h"

#include <algorithm>

namespace granota::ui {

void PointExtent::include(const Point& p)
{
    minX = std::min(minX, p.x);
    maxX = std::max(maxX, p.x);
    minY = std::min(minY, p.y);
    maxY = std::max(maxY, p.y);
}

std::optional<PointExtent> finiteExtent(const std::vector<Point>& points) { return finiteExtent(points, {}); }

std::optional<PointExtent> finiteExtent(const std::vector<Point>& a, const std::vector<Point>& b)
{
    std::optional<PointExtent> extent;
    for (const auto* list : {&a, &b})
        for (const Point& p : *list) {
            if (!isFinite(p))
                continue;
            if (extent)
                extent->include(p);
            else
                extent = PointExtent{p.x, p.y, p.x, p.y};
        }
    return extent;
}

} // namespace granota::ui
