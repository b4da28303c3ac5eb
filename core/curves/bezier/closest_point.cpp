#include "core/curves/bezier/closest_point.h"

#include "core/curves/bezier/bernstein_roots.h"
#include "core/curves/bezier/hodograph.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace granota {

std::vector<double> projectionPolynomial(const std::vector<Point>& P, Point p)
{
    if (P.size() < 2)
        return {};
    const std::vector<Point> A = hodograph(P);
    std::vector<double> qx, qy, ax, ay;
    qx.reserve(P.size());
    qy.reserve(P.size());
    for (const Point& q : P) {
        qx.push_back(q.x - p.x);
        qy.push_back(q.y - p.y);
    }
    for (const Point& a : A) {
        ax.push_back(a.x);
        ay.push_back(a.y);
    }
    std::vector<double> f = bernsteinProduct(qx, ax);
    const std::vector<double> g = bernsteinProduct(qy, ay);
    for (std::size_t k = 0; k < f.size(); ++k)
        f[k] += g[k];
    return f;
}

ClosestPoint closestPoint(const std::vector<Point>& P, Point p)
{
    assert(!P.empty());
    std::vector<double> xs, ys;
    xs.reserve(P.size());
    ys.reserve(P.size());
    double size = 0.0;
    for (const Point& q : P) {
        xs.push_back(q.x);
        ys.push_back(q.y);
        size = std::max(size, distance(q, P.front()));
    }
    auto at = [&](double t) {
        ClosestPoint c;
        c.t = t;
        c.point = Point(bernsteinValue(xs, t), bernsteinValue(ys, t));
        c.distance = distance(c.point, p);
        return c;
    };
    ClosestPoint best = at(0.0);
    if (P.size() < 2)
        return best;
    const BernsteinRoots r = bernsteinRoots(projectionPolynomial(P, p));
    // Candidates in ascending t, so that a later one replaces the best only when it is
    // strictly closer than the tie tolerance: the smallest t wins a tie.
    std::vector<double> candidates = r.roots;
    candidates.push_back(1.0);
    const double tie = 1e-12 * (size + best.distance);
    for (double t : candidates) {
        if (t <= 0.0)
            continue;
        const ClosestPoint c = at(t);
        if (c.distance < best.distance - tie)
            best = c;
    }
    return best;
}

} // namespace granota
