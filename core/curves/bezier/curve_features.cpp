#include "core/base/math_constants.h"
#include "core/curves/bezier/curve_features.h"

#include "core/curves/bezier/bernstein_roots.h"
#include "core/curves/bezier/exact_hodograph.h"
#include "core/curves/bezier/hodograph.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace granota {

namespace {

/// |c′(t)| below this fraction of the hodograph's size counts as c′ = 0 (a cusp).
constexpr double kCuspTolerance = 1e-9;

std::vector<double> coordinate(const std::vector<Point>& P, int which)
{
    std::vector<double> out;
    out.reserve(P.size());
    for (const Point& p : P)
        out.push_back(which == 0 ? p.x : p.y);
    return out;
}

std::vector<double> openInterval(std::vector<double> roots)
{
    roots.erase(std::remove_if(roots.begin(), roots.end(), [](double t) { return !(t > 0.0 && t < 1.0); }), roots.end());
    return roots;
}

double hodographSize(const std::vector<Point>& A)
{
    double size = 0.0;
    for (const Point& a : A)
        size = std::max(size, norm(a));
    return size;
}

Point pointAt(const std::vector<double>& xs, const std::vector<double>& ys, double t)
{
    return {bernsteinValue(xs, t), bernsteinValue(ys, t)};
}

/// The hodograph of P scaled by a power of two (exact) that brings every coordinate to at
/// most 1 in magnitude: the differences n (P_{i+1} − P_i) of points near ±1e308 would
/// overflow to infinity. Every feature here is a zero or a sign change, or a comparison
/// relative to the hodograph's size, so the scale changes none of them.
std::vector<Point> scaledHodograph(const std::vector<Point>& P)
{
    double m = 0;
    for (const Point& p : P)
        m = std::max({m, std::abs(p.x), std::abs(p.y)});
    int e = 0;
    if (m > 0 && std::isfinite(m))
        std::frexp(m, &e);
    std::vector<Point> Q(P);
    for (Point& q : Q)
        q = Point(std::ldexp(q.x, -e), std::ldexp(q.y, -e));
    return hodograph(Q);
}

} // namespace

std::vector<double> extremaParameters(const std::vector<Point>& P, int which)
{
    if (P.size() < 2)
        return {};
    const BernsteinRoots r = bernsteinRoots(coordinate(scaledHodograph(P), which));
    return openInterval(r.roots);
}

Aabb tightBoundingBox(const std::vector<Point>& P)
{
    if (P.empty())
        return {};
    Aabb box = Aabb::around(P.front());
    box.includeX(P.back().x); // not include(): a NaN corner stays in the box, as callers check
    box.includeY(P.back().y);
    const std::vector<double> xs = coordinate(P, 0), ys = coordinate(P, 1);
    for (double t : extremaParameters(P, 0)) {
        const double x = bernsteinValue(xs, t);
        box.includeX(x);
    }
    for (double t : extremaParameters(P, 1)) {
        const double y = bernsteinValue(ys, t);
        box.includeY(y);
    }
    return box;
}

namespace {

/// The cusps of P among the zeros rx of x′ and ry of y′ (the coordinates ax, ay of its
/// scaled hodograph, of size `size` > 0): those where |c′| is 0 within kCuspTolerance, unless
/// the control points taken exactly show that x′ and y′ never vanish together
/// (exact_hodograph.h: near ±1e308 the doubles' rounding hides a c′ of (21/4, 0)).
std::vector<double> cuspsAmong(const std::vector<Point>& P, const std::vector<double>& ax, const std::vector<double>& ay,
                               const BernsteinRoots& rx, const BernsteinRoots& ry, double size)
{
    struct Candidate {
        double t;
        double speed;
    };
    std::vector<Candidate> candidates;
    for (const BernsteinRoots* r : {&rx, &ry}) {
        for (double t : r->roots) {
            const double speed = norm(pointAt(ax, ay, t));
            if (speed <= kCuspTolerance * size)
                candidates.push_back({t, speed});
        }
    }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.t < b.t; });
    // The same cusp from x′ and from y′ (one of them often a double zero, known only to
    // about √ε): keep the t where |c′| is smaller.
    std::vector<Candidate> merged;
    for (const Candidate& c : candidates) {
        if (!merged.empty() && c.t - merged.back().t <= 1e-6) {
            if (c.speed < merged.back().speed)
                merged.back() = c;
            continue;
        }
        merged.push_back(c);
    }
    if (!merged.empty() && hodographVanishesSomewhere(P) == std::optional<bool>(false))
        return {};
    std::vector<double> out;
    for (const Candidate& c : merged)
        out.push_back(c.t);
    return out;
}

} // namespace

std::vector<double> cuspParameters(const std::vector<Point>& P)
{
    if (P.size() < 2)
        return {};
    const std::vector<Point> A = scaledHodograph(P);
    const double size = hodographSize(A);
    if (size == 0.0)
        return {}; // stationary: c′ ≡ 0 (see CurveFeatures::stationary)
    const std::vector<double> ax = coordinate(A, 0), ay = coordinate(A, 1);
    return cuspsAmong(P, ax, ay, bernsteinRoots(ax), bernsteinRoots(ay), size);
}

namespace {

/// curvatureNumerator from the hodograph A of P (P with at least 3 points).
std::vector<double> curvatureNumeratorOf(const std::vector<Point>& A)
{
    const int m = static_cast<int>(A.size()) - 1;
    const std::vector<double> cm = binomialRow(m), c2 = binomialRow(2 * m - 2);
    std::vector<double> D(static_cast<std::size_t>(2 * m - 1), 0.0);
    for (int i = 0; i <= m; ++i)
        for (int j = i + 1; j <= m; ++j) {
            const int k = i + j - 1;
            D[static_cast<std::size_t>(k)] += (j - i) * cm[static_cast<std::size_t>(i)] * cm[static_cast<std::size_t>(j)] *
                                              cross(A[static_cast<std::size_t>(i)], A[static_cast<std::size_t>(j)]);
        }
    for (int k = 0; k <= 2 * m - 2; ++k)
        D[static_cast<std::size_t>(k)] /= c2[static_cast<std::size_t>(k)];
    return D;
}

} // namespace

std::vector<double> curvatureNumerator(const std::vector<Point>& P)
{
    if (P.size() < 3)
        return {};
    return curvatureNumeratorOf(hodograph(P));
}

namespace {

/// Whether x′y″ − y′x″ is 0 up to the rounding of its coefficients (collinear control
/// points given as decimals are rarely collinear in binary); A is the hodograph, `size`
/// its hodographSize.
bool straightWithinRounding(const std::vector<Point>& A, double size, const std::vector<double>& D)
{
    if (D.empty())
        return true;
    const int m = static_cast<int>(A.size()) - 1;
    // A generous bound: (m + 1)² terms of size at most |A_i||A_j| ≤ size², each rounded.
    const double bound = 64.0 * (m + 1) * (m + 1) * kMachineEpsilon * size * size;
    return std::all_of(D.begin(), D.end(), [bound](double d) { return std::fabs(d) <= bound; });
}

std::vector<double> signChangesOf(const std::vector<double>& D);

} // namespace

std::vector<double> inflectionParameters(const std::vector<Point>& P)
{
    if (P.size() < 3)
        return {};
    const std::vector<Point> A = scaledHodograph(P);
    const std::vector<double> D = curvatureNumeratorOf(A);
    if (straightWithinRounding(A, hodographSize(A), D))
        return {};
    return signChangesOf(D);
}

namespace {

std::vector<double> signChangesOf(const std::vector<double>& D)
{
    const BernsteinRoots r = bernsteinRoots(D);
    std::vector<double> out;
    for (std::size_t k = 0; k < r.roots.size(); ++k)
        if (r.crossing[k] && r.roots[k] > 0.0 && r.roots[k] < 1.0)
            out.push_back(r.roots[k]);
    return out;
}

} // namespace

CurveFeatures curveFeatures(const std::vector<Point>& P)
{
    CurveFeatures f;
    if (P.empty()) {
        f.stationary = f.straight = true;
        return f;
    }
    const std::vector<Point> A = scaledHodograph(P);
    const double size = hodographSize(A);
    f.stationary = size == 0.0;
    const std::vector<double> D = P.size() < 3 ? std::vector<double>{} : curvatureNumeratorOf(A);
    f.straight = straightWithinRounding(A, size, D);
    if (!f.stationary) {
        // The zeros of x′ and y′ once, for the extrema and for the cusps.
        const std::vector<double> ax = coordinate(A, 0), ay = coordinate(A, 1);
        const BernsteinRoots rx = bernsteinRoots(ax), ry = bernsteinRoots(ay);
        f.extremaX = openInterval(rx.roots);
        f.extremaY = openInterval(ry.roots);
        f.cusps = cuspsAmong(P, ax, ay, rx, ry, size);
    }
    // The box from the extrema already found (tightBoundingBox would find them again).
    f.bbox = Aabb::around(P.front());
    const std::vector<double> xs = coordinate(P, 0), ys = coordinate(P, 1);
    const auto includeX = [&f](double x) { f.bbox.includeX(x); };
    const auto includeY = [&f](double y) { f.bbox.includeY(y); };
    includeX(P.back().x);
    includeY(P.back().y);
    for (double t : f.extremaX)
        includeX(bernsteinValue(xs, t));
    for (double t : f.extremaY)
        includeY(bernsteinValue(ys, t));
    if (!f.straight)
        f.inflections = signChangesOf(D);
    return f;
}

} // namespace granota
