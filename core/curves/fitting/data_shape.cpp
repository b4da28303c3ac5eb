#include "core/curves/fitting/data_shape.h"

#include "core/base/aabb.h"

#include <algorithm>
#include <cmath>

namespace granota {

DataShape analyseDataShape(const std::vector<Point>& q, double relativeTolerance)
{
    DataShape shape;
    std::vector<Point> finite;
    finite.reserve(q.size());
    for (const Point& p : q)
        if (isFinite(p))
            finite.push_back(p);
    for (std::size_t i = 1; i < q.size(); ++i)
        if (q[i] == q[i - 1]) {
            ++shape.zeroChords;
            if (shape.firstZeroChord < 0)
                shape.firstZeroChord = static_cast<int>(i);
        }
    if (finite.size() < 2) {
        shape.allCoincide = shape.collinear = true;
        return shape;
    }
    // The extent of the data, and the point farthest from Q_0 (an end of a line through them).
    const Aabb box = boundingBox(finite.data(), static_cast<int>(finite.size()));
    const double extent = std::max(box.width(), box.height());
    if (!(extent > 0)) {
        shape.allCoincide = shape.collinear = true;
        return shape;
    }
    // Work relative to the extent (no overflow for coordinates near 1e300).
    const Point origin = finite[0];
    auto local = [&](const Point& p) { return Point((p.x - origin.x) / extent, (p.y - origin.y) / extent); };
    Point far = local(finite[0]);
    double farDistance = 0;
    for (const Point& p : finite) {
        const Point l = local(p);
        const double d = norm(l);
        if (d > farDistance) {
            farDistance = d;
            far = l;
        }
    }
    const Point direction(far.x / farDistance, far.y / farDistance);
    shape.collinear = std::all_of(finite.begin(), finite.end(),
                                  [&](const Point& p) { return std::fabs(cross(local(p), direction)) <= relativeTolerance; });
    return shape;
}

} // namespace granota
