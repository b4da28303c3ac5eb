#include "core/curves/bsplines/circle_arcs.h"

#include "core/base/math_constants.h"
#include "core/curves/bezier/bernstein_roots.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace granota {

RationalBezierSegment<double> circleArc(const Point& centre, double radius, double start, double sweep)
{
    assert(sweep != 0 && std::abs(sweep) <= kPi / 2 * (1 + 1e-15));
    const double half = sweep / 2, mid = start + half;
    const double w = std::cos(half);
    const auto on = [&](double angle, double r) { return Point(centre.x + r * std::cos(angle), centre.y + r * std::sin(angle)); };
    RationalBezierSegment<double> s;
    // The end tangents meet on the bisector at r / cos(θ/2) from the centre.
    s.points = {on(start, radius), on(mid, radius / w), on(start + sweep, radius)};
    s.weights = {1, w, 1};
    s.start = 0;
    s.end = 1;
    return s;
}

std::vector<RationalBezierSegment<double>> circleArcs(const Point& centre, double radius, double start, double sweep)
{
    assert(sweep != 0 && std::abs(sweep) <= 2 * kPi * (1 + 1e-15));
    const int m = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (kPi / 2) - 1e-12)));
    const double piece = sweep / m;
    std::vector<RationalBezierSegment<double>> out;
    for (int j = 0; j < m; ++j) {
        RationalBezierSegment<double> s = circleArc(centre, radius, start + j * piece, piece);
        s.start = static_cast<double>(j) / m;
        s.end = static_cast<double>(j + 1) / m;
        out.push_back(std::move(s));
    }
    return out;
}

BSplineCurve<double> fullCircle(const Point& centre, double radius)
{
    const double h = std::sqrt(2.0) / 2; // cos 45°: the corners' weight
    BSplineCurve<double> c;
    c.degree = 2;
    const double corner[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    for (int i = 0; i < 9; ++i) {
        c.points.emplace_back(centre.x + radius * corner[i][0], centre.y + radius * corner[i][1]);
        c.weights.push_back(i % 2 ? h : 1.0);
    }
    c.knots = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    return c;
}

double cubicCircleHandle() { return 4 * (std::sqrt(2.0) - 1) / 3; }

std::vector<Point> cubicQuarterCircle(double k) { return {Point(1, 0), Point(1, k), Point(k, 1), Point(0, 1)}; }

CubicCircleError cubicCircleRadialError(double k)
{
    const std::vector<Point> P = cubicQuarterCircle(k);
    std::vector<double> x, y;
    for (const Point& p : P) {
        x.push_back(p.x);
        y.push_back(p.y);
    }
    // |c|² = x² + y² in Bernstein form of degree 6, then its derivative, of degree 5:
    // d/dt Σ b_i B_i^6 = 6 Σ (b_{i+1} − b_i) B_i^5.
    const std::vector<double> xx = bernsteinProduct(x, x), yy = bernsteinProduct(y, y);
    std::vector<double> derivative;
    for (std::size_t i = 0; i + 1 < xx.size(); ++i)
        derivative.push_back(6 * ((xx[i + 1] + yy[i + 1]) - (xx[i] + yy[i])));
    std::vector<double> candidates = bernsteinRoots(derivative).roots;
    candidates.push_back(0);
    candidates.push_back(1);
    std::sort(candidates.begin(), candidates.end());
    CubicCircleError e;
    bool first = true;
    for (double t : candidates) {
        // |c(t)| − 1 = (|c|² − 1)/(|c| + 1): no cancellation where |c| ≈ 1.
        const double s2 = bernsteinValue(xx, t) + bernsteinValue(yy, t);
        const double err = (s2 - 1) / (std::sqrt(s2) + 1);
        if (first || err > e.maxError) {
            e.maxError = err;
            e.maxT = t;
        }
        if (first || err < e.minError)
            e.minError = err;
        first = false;
    }
    e.maxError = std::max(e.maxError, 0.0);
    e.minError = std::min(e.minError, 0.0);
    return e;
}

} // namespace granota
