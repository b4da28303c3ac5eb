#include "core/curves/bezier/rational_bezier.h"

#include "core/curves/bezier/gauss_legendre.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace granota {

namespace {

Error weightCountError(std::size_t pointCount, std::size_t weightCount)
{
    return makeError(ErrorCode::InvalidInput, std::to_string(weightCount) + " weights for " + std::to_string(pointCount) +
                                                  " control points: give one weight per point");
}

Error weightSignError(std::size_t i)
{
    return makeError(ErrorCode::OutOfRange, "weight " + std::to_string(i + 1) + " is not positive: every weight must be > 0");
}

/// The largest |coordinate| rounded up to a power of two, as its exponent (arc_length.cpp
/// does the same): dividing by 2^e is exact and keeps |c′|² away from overflow.
int scaleExponent(const std::vector<Point>& P)
{
    double m = 0;
    for (const Point& p : P)
        m = std::max({m, std::abs(p.x), std::abs(p.y)});
    int e = 0;
    if (m > 0 && std::isfinite(m))
        std::frexp(m, &e);
    return e;
}

/// |c′(t)| of the scaled curve: De Casteljau on the homogeneous points down to level n − 1,
/// then p, w, p′ = n Δp^{n−1}, w′ = n Δw^{n−1} and c′ = (p′ w − w′ p) / w². The work arrays
/// are the caller's, allocated once per arc length.
struct RationalSpeed {
    const std::vector<Point>* h = nullptr; // w_i P_i (scaled)
    const std::vector<double>* w = nullptr;
    mutable std::vector<Point> hw;
    mutable std::vector<double> ww;

    double operator()(double t) const
    {
        hw = *h;
        ww = *w;
        const double u = 1 - t;
        const std::size_t n = hw.size() - 1;
        for (std::size_t m = hw.size(); m > 2; --m)
            for (std::size_t i = 0; i + 1 < m; ++i) {
                hw[i] = Point(u * hw[i].x + t * hw[i + 1].x, u * hw[i].y + t * hw[i + 1].y);
                ww[i] = u * ww[i] + t * ww[i + 1];
            }
        const Point p(u * hw[0].x + t * hw[1].x, u * hw[0].y + t * hw[1].y);
        const double W = u * ww[0] + t * ww[1];
        const double k = static_cast<double>(n);
        const Point dp(k * (hw[1].x - hw[0].x), k * (hw[1].y - hw[0].y));
        const double dw = k * (ww[1] - ww[0]);
        const Point v((dp.x * W - dw * p.x) / (W * W), (dp.y * W - dw * p.y) / (W * W));
        return std::sqrt(v.x * v.x + v.y * v.y);
    }
};

constexpr int kGaussPoints = 16;
constexpr int kMaxDepth = 40;

/// The 16-point rule on [a, b].
double gaussRule(const RationalSpeed& f, const GaussLegendreRule& rule, double a, double b)
{
    const double h = 0.5 * (b - a), c = 0.5 * (a + b);
    double sum = 0;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i)
        sum += static_cast<double>(rule.weights[i]) * f(c + h * static_cast<double>(rule.nodes[i]));
    return h * sum;
}

} // namespace

Expected<void> checkRationalBezier(std::size_t pointCount, const std::vector<double>& weights)
{
    if (pointCount == 0)
        return makeError(ErrorCode::TooFewPoints, "a rational Bézier curve needs at least one control point");
    if (weights.size() != pointCount)
        return weightCountError(pointCount, weights.size());
    for (std::size_t i = 0; i < weights.size(); ++i) {
        if (!std::isfinite(weights[i]))
            return makeError(ErrorCode::InvalidInput, "weight " + std::to_string(i + 1) + " is not a finite number");
        if (!(weights[i] > 0))
            return weightSignError(i);
    }
    return {};
}

Expected<void> checkRationalBezier(std::size_t pointCount, const std::vector<Rational>& weights)
{
    if (pointCount == 0)
        return makeError(ErrorCode::TooFewPoints, "a rational Bézier curve needs at least one control point");
    if (weights.size() != pointCount)
        return weightCountError(pointCount, weights.size());
    for (std::size_t i = 0; i < weights.size(); ++i)
        if (weights[i] <= 0)
            return weightSignError(i);
    return {};
}

CurvatureAt rationalCurvatureAt(const std::vector<Point>& points, const std::vector<double>& weights, double t)
{
    assert(checkRationalBezier(points.size(), weights).ok());
    t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
    const RationalDerivatives<double> d = rationalBezierDerivatives(points, weights, t);
    CurvatureAt out;
    out.t = t;
    out.point = d.point;
    out.tangent = d.first;
    // "c′ = 0" relative to the curve's size, as curvature.h decides it: |c′| ≤ 1e-12 · n · h,
    // h the largest coordinate difference between control points.
    double h = 0;
    for (const Point& p : points)
        h = std::max({h, std::abs(p.x - points[0].x), std::abs(p.y - points[0].y)});
    const double speed = norm(d.first);
    const double n = static_cast<double>(points.size() - 1);
    if (!(speed > 1e-12 * n * h))
        return out;
    out.normal = Point(-d.first.y / speed, d.first.x / speed);
    const double k = cross(d.first, d.second) / (speed * speed * speed);
    out.curvature = k;
    if (k == 0 || !std::isfinite(k))
        return out;
    const double r = 1 / std::abs(k);
    const double s = k > 0 ? r : -r;
    out.radius = r;
    out.center = Point(d.point.x + s * out.normal->x, d.point.y + s * out.normal->y);
    return out;
}

ExactCurvature exactRationalCurvatureAt(const std::vector<RPoint>& points, const std::vector<Rational>& weights,
                                        const Rational& t)
{
    const RationalDerivatives<Rational> d = rationalBezierDerivatives(points, weights, t);
    ExactCurvature k;
    k.speedSquared = d.first.x * d.first.x + d.first.y * d.first.y;
    k.numerator = k.speedSquared == 0 ? Rational(0) : Rational(d.first.x * d.second.y - d.first.y * d.second.x);
    return k;
}

double rationalArcLength(const std::vector<Point>& points, const std::vector<double>& weights, double t0, double t1,
                         double relativeTolerance)
{
    assert(checkRationalBezier(points.size(), weights).ok());
    t0 = std::isfinite(t0) ? std::clamp(t0, 0.0, 1.0) : 0.0;
    t1 = std::isfinite(t1) ? std::clamp(t1, 0.0, 1.0) : 0.0;
    if (t1 < t0)
        return -rationalArcLength(points, weights, t1, t0, relativeTolerance);
    if (points.size() < 2 || t0 == t1)
        return 0;
    // Scaled by powers of two (exact): coordinates to at most 1, weights to at most 1.
    const int e = scaleExponent(points);
    int ew = 0;
    std::frexp(*std::max_element(weights.begin(), weights.end()), &ew);
    std::vector<Point> h;
    std::vector<double> w;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double wi = std::ldexp(weights[i], -ew);
        w.push_back(wi);
        h.emplace_back(wi * std::ldexp(points[i].x, -e), wi * std::ldexp(points[i].y, -e));
    }
    const RationalSpeed f{&h, &w, {}, {}};
    static const GaussLegendreRule rule = gaussLegendreRule(kGaussPoints);
    const double rel = std::clamp(relativeTolerance, 1e-15, 0.1);
    const double whole = gaussRule(f, rule, t0, t1);
    if (!(whole > 0))
        return 0;
    const double tol = rel * whole;
    struct Item {
        double a, b, g;
        int depth;
    };
    std::array<Item, kMaxDepth + 2> stack;
    std::size_t top = 0;
    stack[top++] = {t0, t1, whole, 0};
    double total = 0;
    while (top > 0) {
        const Item it = stack[--top];
        const double mid = 0.5 * (it.a + it.b);
        const double gl = gaussRule(f, rule, it.a, mid), gr = gaussRule(f, rule, mid, it.b);
        if (std::abs(gl + gr - it.g) <= tol * (it.b - it.a) / (t1 - t0) || it.depth >= kMaxDepth || !(it.a < mid && mid < it.b)) {
            total += gl + gr;
            continue;
        }
        stack[top++] = {mid, it.b, gr, it.depth + 1};
        stack[top++] = {it.a, mid, gl, it.depth + 1};
    }
    return std::ldexp(total, e);
}

} // namespace granota
