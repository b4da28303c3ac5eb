#include "core/softbody/regular_polygon.h"
#include "core/base/math_constants.h"

#include <cassert>
#include <cmath>

namespace granota {

std::vector<Point> regularPolygon(const Point& centre, double radius, int sides, double startAngle)
{
    assert(sides >= 3 && radius >= 0);
    std::vector<Point> v;
    v.reserve(static_cast<std::size_t>(sides));
    const double step = 2.0 * kPi / sides; // α = 2π/n
    for (int i = 0; i < sides; ++i) {
        const double a = startAngle + i * step;
        v.emplace_back(centre.x + radius * std::cos(a), centre.y + radius * std::sin(a));
    }
    return v;
}

} // namespace granota
