#include "core/softbody/xpbd/xpbd_recovery.h"

#include "core/softbody/polygon_geometry.h"
#include "core/softbody/xpbd/xpbd_collisions.h"

#include <algorithm>
#include <cmath>

namespace granota {

double bestFitRotation(const Point* x, const Point* rest, int n, const Point& centroid)
{
    double axx = 0, axy = 0, ayx = 0, ayy = 0;
    for (int i = 0; i < n; ++i) {
        const Point p = x[i] - centroid;
        axx += p.x * rest[i].x;
        axy += p.x * rest[i].y;
        ayx += p.y * rest[i].x;
        ayy += p.y * rest[i].y;
    }
    // max over θ of trace(R(θ)ᵀ A) = cos θ (A₁₁ + A₂₂) + sin θ (A₂₁ − A₁₂).
    return std::atan2(ayx - axy, axx + ayy);
}

bool polygonSelfIntersects(const Point* x, int n)
{
    for (int i = 0; i < n; ++i) {
        const Point& a = x[i];
        const Point& b = x[i + 1 == n ? 0 : i + 1];
        const double minX = std::min(a.x, b.x), maxX = std::max(a.x, b.x);
        const double minY = std::min(a.y, b.y), maxY = std::max(a.y, b.y);
        // Edges i and j share a vertex when j = i ± 1 (mod n): skip those.
        for (int j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1)
                continue;
            const Point& c = x[j];
            const Point& d = x[j + 1 == n ? 0 : j + 1];
            if (std::max(c.x, d.x) < minX || std::min(c.x, d.x) > maxX || std::max(c.y, d.y) < minY || std::min(c.y, d.y) > maxY)
                continue;
            if (segmentsCross(a, b, c, d))
                return true;
        }
    }
    return false;
}

void shapeMatchingPull(Point* x, const Point* rest, int n, double rate)
{
    const Point c = vertexCentroid(x, n);
    const double theta = bestFitRotation(x, rest, n, c);
    const double cs = std::cos(theta), sn = std::sin(theta);
    for (int i = 0; i < n; ++i) {
        const Point goal(c.x + cs * rest[i].x - sn * rest[i].y, c.y + sn * rest[i].x + cs * rest[i].y);
        x[i] += Point(rate * (goal.x - x[i].x), rate * (goal.y - x[i].y));
    }
}

} // namespace granota
