#include "core/softbody/polygon_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace granota {

double signedArea(const Point* x, int n)
{
    // ½ Σ (xᵢ − xᵢ₊₁)(yᵢ + yᵢ₊₁) of §4.5 equals ½ Σ xᵢ × xᵢ₊₁ (the xᵢyᵢ terms telescope).
    // Taken relative to x[0] so that a small polygon far from the origin loses no digits.
    if (n < 3)
        return 0;
    const Point o = x[0];
    double twice = 0;
    Point prev = x[1] - o;
    for (int i = 2; i < n; ++i) {
        const Point cur = x[i] - o;
        twice += cross(prev, cur);
        prev = cur;
    }
    return 0.5 * twice;
}

double signedAreaSign(const Point* poly, int n)
{
    double twice = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        twice += cross(poly[j], poly[i]);
    return twice < 0 ? -1.0 : 1.0;
}

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

bool pointInPolygon(const Point* poly, int n, const Point& p) { return pointInPolygon(poly, n, p, nullptr); }

bool pointInPolygon(const Point* poly, int n, const Point& p, int* nearestCrossing)
{
    // §4.6 as the std::vector form above: x interval half-open, vertical edges skipped. "p
    // lies above the edge" (p.y ≤ y of the edge at p.x) is tested without a division:
    // (p.y − a.y)(b.x − a.x) ≤ (p.x − a.x)(b.y − a.y), the inequality flipping when b.x < a.x.
    // Written without branches on the data: in a pile nearly every vertex is near an edge,
    // so which edges straddle p is a coin toss that a branch predictor keeps losing.
    bool inside = false;
    double closest = std::numeric_limits<double>::infinity();
    for (int i = 0, j = n - 1; i < n; j = i++) {
        const Point& a = poly[j];
        const Point& b = poly[i];
        // Half-open on both orders: a.x ≤ p.x < b.x or b.x ≤ p.x < a.x.
        const bool straddles = (a.x <= p.x) != (b.x <= p.x);
        const double lhs = (p.y - a.y) * (b.x - a.x);
        const double rhs = (p.x - a.x) * (b.y - a.y);
        const bool above = b.x > a.x ? lhs <= rhs : lhs >= rhs;
        const bool crosses = straddles && above;
        inside ^= crosses;
        if (nearestCrossing && crosses) { // the crossed edge closest along the ray: edge j → i
            const double gap = (rhs - lhs) / (b.x - a.x);
            if (gap < closest) {
                closest = gap;
                *nearestCrossing = j;
            }
        }
    }
    return inside;
}

Point vertexCentroid(const Point* x, int n)
{
    Point c;
    for (int i = 0; i < n; ++i)
        c += x[i];
    return n > 0 ? Point(c.x / n, c.y / n) : c;
}

} // namespace granota
