#pragma once
/// \file bspline_clamping.h
/// Clamped and floating ends. A clamped end repeats its knot p + 1 times and the curve starts
/// (ends) at its first (last) control point; a floating end has p + 1 distinct knots there.
/// Both write the same curve on the domain [u_p, u_{n+1}] (Piegl & Tiller §12.2):
///  - clampCurve inserts u_p and u_{n+1} until they have multiplicity p (knot_insertion.h) and
///    drops the control points and knots that then shape nothing on the domain;
///  - unclampCurve chooses the outer knots equally spaced as the first and the last span and
///    computes the new end control points as blossoms (polar forms) of the end pieces:
///    P_i = c[u_{i+1}, …, u_{i+p}] (Ramshaw, "Blossoms are polar forms", CAGD 6 (1989)), each a
///    De Casteljau table (Def 2.4) with a different t at every level.
/// A rational curve is done on its homogeneous points. Exact in Rational.

#include "core/curves/bsplines/bezier_extraction.h"
#include "core/curves/bsplines/bspline_curve.h"
#include "core/curves/bsplines/knot_insertion.h"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <vector>

namespace granota {

/// `c` (passing checkBSpline) with both ends clamped: the same curve on the domain, starting
/// at its first control point and ending at its last.
template <class S> BSplineCurve<S> clampCurve(const BSplineCurve<S>& c)
{
    const int p = c.degree;
    BSplineCurve<S> q = c;
    const S a = c.domainStart(), b = c.domainEnd();
    const int sa = static_cast<int>(std::count(q.knots.begin(), q.knots.end(), a));
    if (sa < p)
        q = insertKnot(q, a, p - sa);
    const int sb = static_cast<int>(std::count(q.knots.begin(), q.knots.end(), b));
    if (sb < p)
        q = insertKnot(q, b, p - sb);
    // Left: a is now at indices f..f+p−1 (or 0..p, already clamped); the first span is
    // [u_{f+p−1}, u_{f+p}), and P_{f−1} is c(a).
    const int f = static_cast<int>(std::lower_bound(q.knots.begin(), q.knots.end(), a) - q.knots.begin());
    if (f > 0) {
        q.knots.erase(q.knots.begin(), q.knots.begin() + (f - 1));
        q.knots.front() = a;
        q.points.erase(q.points.begin(), q.points.begin() + (f - 1));
        if (q.rational())
            q.weights.erase(q.weights.begin(), q.weights.begin() + (f - 1));
    }
    // Right: b is now at indices g..g+p−1 (or g..g+p, already clamped); P_{g−1} is c(b).
    const int g = static_cast<int>(std::lower_bound(q.knots.begin(), q.knots.end(), b) - q.knots.begin());
    q.points.resize(static_cast<std::size_t>(g));
    if (q.rational())
        q.weights.resize(static_cast<std::size_t>(g));
    q.knots.resize(static_cast<std::size_t>(g + p + 1));
    q.knots.back() = b;
    return q;
}

namespace detail {
/// The blossom of a Bézier piece on [start, end] at the arguments ts (one per degree):
/// De Casteljau's table with the parameter of level r taken from ts[r − 1]. Homogeneous
/// points in `h`, weights (w, 0) in `w` (empty for a polynomial curve).
template <class S>
void blossom(std::vector<Vec2<S>> h, std::vector<Vec2<S>> w, const S& start, const S& end, const std::vector<S>& ts,
             Vec2<S>& point, S& weight)
{
    for (std::size_t r = 0; r < ts.size(); ++r) {
        const S t = S(S(ts[r] - start) / S(end - start));
        const S s = S(S(1) - t);
        for (std::size_t i = 0; i + 1 < h.size() - r; ++i) {
            h[i] = s * h[i] + t * h[i + 1];
            if (!w.empty())
                w[i] = s * w[i] + t * w[i + 1];
        }
    }
    weight = w.empty() ? S(1) : w[0].x;
    // A zero weight (refused by the caller) has no point of the plane: keep the homogeneous one.
    point = w.empty() || weight == S(0) ? h[0] : Vec2<S>(S(h[0].x / weight), S(h[0].y / weight));
}
} // namespace detail

/// How many times unclampCurve halves the outer knots' spacing looking for positive weights.
constexpr int kUnclampHalvings = 30;

/// `c` (passing checkBSpline) with floating ends: p + 1 distinct knots at each end, the outer
/// ones spaced as the first and the last non-empty span; the same curve on the domain. A
/// rational curve's new end weights are blossoms of its weight function, and may come out ≤ 0
/// (extrapolated beyond the domain): the spacing is then halved (the weights tend to the
/// clamped ones) until they are positive, up to kUnclampHalvings times; an error after that.
template <class S> Expected<BSplineCurve<S>> unclampCurve(const BSplineCurve<S>& c)
{
    const int p = c.degree, n = c.pointCount() - 1;
    const auto z = [](int i) { return static_cast<std::size_t>(i); };
    const auto pieces = toBezierSegments(c);
    const auto& first = pieces.front();
    const auto& last = pieces.back();
    const auto homogeneous = [&](const RationalBezierSegment<S>& seg, std::vector<Vec2<S>>& h, std::vector<Vec2<S>>& w) {
        h = seg.points;
        w.clear();
        if (c.rational())
            for (std::size_t i = 0; i < h.size(); ++i) {
                h[i] = seg.weights[i] * h[i];
                w.emplace_back(seg.weights[i], S(0));
            }
    };
    S hFirst = S(first.end - first.start), hLast = S(last.end - last.start);
    for (int attempt = 0; attempt <= kUnclampHalvings; ++attempt) {
        BSplineCurve<S> f = c;
        for (int i = 0; i < p; ++i) // u_i = u_p − (p − i) h
            f.knots[z(i)] = S(c.domainStart() - S(p - i) * hFirst);
        for (int i = n + 2; i <= n + p + 1; ++i) // u_i = u_{n+1} + (i − n − 1) h
            f.knots[z(i)] = S(c.domainEnd() + S(i - n - 1) * hLast);
        std::vector<Vec2<S>> h, w;
        // P_i depends on u_{i+1}..u_{i+p}: the left outer knots change P_0..P_{p−2}, the right
        // ones P_{n−p+2}..P_n. Each is a blossom of an end piece its support covers (when the
        // support reaches no piece, P_i shapes nothing and any value does).
        const auto set = [&](int i, const RationalBezierSegment<S>& seg) {
            homogeneous(seg, h, w);
            std::vector<S> ts(f.knots.begin() + (i + 1), f.knots.begin() + (i + p + 1));
            S weight;
            detail::blossom(h, w, seg.start, seg.end, ts, f.points[z(i)], weight);
            if (f.rational())
                f.weights[z(i)] = weight;
        };
        // Computed from the end pieces, which do not change: the order of the two loops is free.
        for (int i = 0; i <= p - 2 && i <= n; ++i)
            set(i, first);
        for (int i = std::max(n - p + 2, 0); i <= n; ++i)
            set(i, last);
        if (std::all_of(f.weights.begin(), f.weights.end(), [](const S& v) { return v > S(0); }))
            return f;
        hFirst = S(hFirst / S(2));
        hLast = S(hLast / S(2));
    }
    return makeError(ErrorCode::OutOfRange,
                     "this rational B-spline cannot float its ends: every choice of outer knots tried needs a weight "
                     "that is not positive",
                     MessageId::BSplineCannotUnclamp, {});
}

} // namespace granota
