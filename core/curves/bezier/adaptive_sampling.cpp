#include "core/curves/bezier/adaptive_sampling.h"

#include "core/curves/bezier/de_casteljau.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace granota {

namespace {

double distanceToSegment(Point p, Point a, Point b)
{
    const Point ab = b - a;
    const double len2 = dot(ab, ab);
    const double s = len2 > 0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return distance(p, a + s * ab);
}

struct Sampler {
    const std::vector<Point>& control;
    std::vector<Point> work;
    double tolerance;
    int minDepth, maxDepth;
    AdaptiveSample out;

    Point at(double t)
    {
        std::copy(control.begin(), control.end(), work.begin());
        return deCasteljauInPlace(work, t);
    }
    // Appends the samples of (a, b]: the interval's start is already in `out`.
    void split(double a, Point pa, double b, Point pb, int depth)
    {
        const double m = 0.5 * (a + b);
        const Point pm = at(m);
        if (depth < maxDepth && (depth < minDepth || distanceToSegment(pm, pa, pb) > tolerance)) {
            split(a, pa, m, pm, depth + 1);
            split(m, pm, b, pb, depth + 1);
            return;
        }
        out.t.push_back(b);
        out.points.push_back(pb);
    }
};

} // namespace

AdaptiveSample sampleBezierAdaptive(const std::vector<Point>& controlPoints, double tolerance, int minDepth, int maxDepth)
{
    assert(!controlPoints.empty());
    Sampler s{controlPoints,
              std::vector<Point>(controlPoints.size()),
              std::max(tolerance, 0.0),
              minDepth,
              std::clamp(maxDepth, 0, 30),
              {}};
    const Point p0 = controlPoints.front(), p1 = controlPoints.back();
    s.out.t.push_back(0.0);
    s.out.points.push_back(p0);
    s.split(0.0, p0, 1.0, p1, 0);
    return std::move(s.out);
}

double polylineDeviation(const std::vector<Point>& controlPoints, const std::vector<double>& t, int probes)
{
    using LPoint = Vec2<long double>;
    std::vector<LPoint> control, work(controlPoints.size());
    for (const Point& p : controlPoints)
        control.emplace_back(p.x, p.y);
    auto at = [&](long double u) {
        std::copy(control.begin(), control.end(), work.begin());
        return deCasteljauInPlace(work, u);
    };
    double worst = 0;
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
        const LPoint a = at(t[i]), b = at(t[i + 1]);
        for (int j = 1; j < probes; ++j) {
            const long double u = t[i] + (t[i + 1] - t[i]) * j / static_cast<long double>(probes);
            const LPoint p = at(u);
            // Distance from p to the chord ab, in long double.
            const long double abx = b.x - a.x, aby = b.y - a.y;
            const long double len2 = abx * abx + aby * aby;
            long double s = len2 > 0 ? ((p.x - a.x) * abx + (p.y - a.y) * aby) / len2 : 0;
            s = std::clamp(s, 0.0L, 1.0L);
            const long double dx = p.x - (a.x + s * abx), dy = p.y - (a.y + s * aby);
            worst = std::max(worst, static_cast<double>(std::sqrt(dx * dx + dy * dy)));
        }
    }
    return worst;
}

} // namespace granota
