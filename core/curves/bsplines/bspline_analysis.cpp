#include "core/curves/bsplines/bspline_analysis.h"

#include "core/curves/bezier/arc_length.h"
#include "core/curves/bezier/curve_features.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace granota {

namespace {

/// The derivative of one coordinate at the start (t = 0) and at the end (t = 1) of a piece:
/// p (P_1 − P_0) and p (P_p − P_{p−1}) (the hodograph's end points).
double derivativeAtStart(const std::vector<Point>& P, int coordinate)
{
    const double p = static_cast<double>(P.size() - 1);
    return coordinate == 0 ? p * (P[1].x - P[0].x) : p * (P[1].y - P[0].y);
}
double derivativeAtEnd(const std::vector<Point>& P, int coordinate)
{
    const std::size_t n = P.size() - 1;
    const double p = static_cast<double>(n);
    return coordinate == 0 ? p * (P[n].x - P[n - 1].x) : p * (P[n].y - P[n - 1].y);
}

/// The sign (−1, 0, 1) of the first coefficient in [first, last) that is not 0 within
/// 1e-12 of the largest one.
template <class It> int sideSign(It first, It last)
{
    double largest = 0;
    for (It it = first; it != last; ++it)
        largest = std::max(largest, std::abs(*it));
    for (It it = first; it != last; ++it)
        if (std::abs(*it) > 1e-12 * largest)
            return *it > 0 ? 1 : -1;
    return 0;
}

/// Appends u unless it repeats the last value (a point found at the end of one piece and at
/// the start of the next).
void appendOnce(std::vector<double>& out, double u)
{
    if (out.empty() || out.back() != u)
        out.push_back(u);
}

} // namespace

BSplineAnalysis::BSplineAnalysis(const BSplineCurve<double>& c) : m_segments(toBezierSegments(c))
{
    assert(!c.rational() && !m_segments.empty());
}

double BSplineAnalysis::toU(std::size_t piece, double t) const
{
    const auto& s = m_segments[piece];
    if (t <= 0)
        return s.start;
    if (t >= 1)
        return s.end;
    return s.start + t * (s.end - s.start);
}

int BSplineAnalysis::segmentAt(double u, double* t) const
{
    // The first piece whose end is beyond u, else the last: pieces are half-open but the last.
    std::size_t j = 0;
    while (j + 1 < m_segments.size() && !(u < m_segments[j].end))
        ++j;
    const auto& s = m_segments[j];
    if (t)
        *t = std::clamp((u - s.start) / (s.end - s.start), 0.0, 1.0);
    return static_cast<int>(j);
}

CurvatureAt BSplineAnalysis::curvatureAt(double u) const
{
    double t = 0;
    const auto& s = m_segments[static_cast<std::size_t>(segmentAt(u, &t))];
    CurvatureAt k = granota::curvatureAt(s.points, t);
    // κ, the normal and the circle do not depend on the parametrization; c′ does: du = (end − start) dt.
    const double h = s.end - s.start;
    k.tangent = Point(k.tangent.x / h, k.tangent.y / h);
    k.t = std::clamp(u, m_segments.front().start, m_segments.back().end);
    return k;
}

double BSplineAnalysis::arcLength(double u0, double u1) const
{
    if (u1 < u0)
        return -arcLength(u1, u0);
    double total = 0;
    for (const auto& s : m_segments) {
        const double a = std::max(u0, s.start), b = std::min(u1, s.end);
        if (!(a < b))
            continue;
        const double h = s.end - s.start;
        const double t0 = a == s.start ? 0.0 : (a - s.start) / h;
        const double t1 = b == s.end ? 1.0 : (b - s.start) / h;
        total += granota::arcLength(s.points, t0, t1);
    }
    return total;
}

double BSplineAnalysis::arcLength() const { return arcLength(m_segments.front().start, m_segments.back().end); }

std::vector<double> BSplineAnalysis::extrema(int coordinate) const
{
    std::vector<double> out;
    for (std::size_t j = 0; j < m_segments.size(); ++j) {
        const auto& P = m_segments[j].points;
        if (j > 0) {
            // The knot between piece j − 1 and piece j: x′ on each side, zero within the
            // rounding of the hodograph's size (as cuspParameters, 1e-12 of it).
            const auto& L = m_segments[j - 1].points;
            const double left = derivativeAtEnd(L, coordinate), right = derivativeAtStart(P, coordinate);
            double size = 0;
            for (const auto* Q : {&L, &P})
                for (std::size_t i = 0; i + 1 < Q->size(); ++i)
                    size = std::max(size, std::abs(coordinate == 0 ? (*Q)[i + 1].x - (*Q)[i].x : (*Q)[i + 1].y - (*Q)[i].y));
            const double eps = 1e-12 * static_cast<double>(P.size()) * size;
            const bool zero = std::abs(left) <= eps || std::abs(right) <= eps;
            if (size > 0 && (zero || (left < 0) != (right < 0)))
                appendOnce(out, m_segments[j].start);
        }
        for (double t : extremaParameters(P, coordinate))
            appendOnce(out, toU(j, t));
    }
    return out;
}

Aabb BSplineAnalysis::tightBox() const
{
    Aabb box;
    for (const auto& s : m_segments) {
        const Aabb b = tightBoundingBox(s.points);
        box.include(b.minCorner());
        box.include(b.maxCorner());
    }
    return box;
}

std::vector<double> BSplineAnalysis::inflections() const
{
    std::vector<double> out;
    for (std::size_t j = 0; j < m_segments.size(); ++j) {
        const auto& P = m_segments[j].points;
        if (j > 0 && P.size() >= 3) {
            // x′y″ − y′x″ at the knot from each side: the last and the first Bernstein
            // coefficients of the pieces' curvature numerators (curve_features.h).
            // Where one is 0 (an inflection on the knot), the sign next to the knot is that of
            // the next coefficient that is not (Bernstein: f(t) ≈ m t D_1 when D_0 = 0).
            const auto left = curvatureNumerator(m_segments[j - 1].points);
            const auto right = curvatureNumerator(P);
            const int a = sideSign(left.rbegin(), left.rend()), b = sideSign(right.begin(), right.end());
            if (a * b < 0)
                appendOnce(out, m_segments[j].start);
        }
        for (double t : inflectionParameters(P))
            appendOnce(out, toU(j, t));
    }
    return out;
}

std::vector<double> BSplineAnalysis::cusps() const
{
    std::vector<double> out;
    for (std::size_t j = 0; j < m_segments.size(); ++j)
        for (double t : cuspParameters(m_segments[j].points))
            appendOnce(out, toU(j, t));
    return out;
}

ClosestPoint BSplineAnalysis::closestPoint(Point p) const
{
    ClosestPoint best;
    bool found = false;
    for (std::size_t j = 0; j < m_segments.size(); ++j) {
        ClosestPoint c = granota::closestPoint(m_segments[j].points, p);
        if (!found || c.distance < best.distance) {
            c.t = toU(j, c.t);
            best = c;
            found = true;
        }
    }
    return best;
}

} // namespace granota
