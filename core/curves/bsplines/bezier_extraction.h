#pragma once
/// \file bezier_extraction.h
/// Bézier extraction (Piegl & Tiller §5.3 and A5.6; Boehm 1980): every distinct knot of the
/// domain inserted until it has multiplicity p, the control points of each non-empty span
/// are the Bézier control points of that piece (Def 2.4) — the §2.3 dilemma seen from the
/// other side: a B-spline is many Bézier curves joined with the continuity its knots allow.
/// A rational curve gives rational Bézier pieces with their weights. Exact in Rational.

#include "core/curves/bsplines/bspline_curve.h"
#include "core/curves/bsplines/knot_insertion.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace granota {

template <class S> struct RationalBezierSegment {
    std::vector<Vec2<S>> points; ///< the p + 1 Bézier control points of the piece
    std::vector<S> weights;      ///< their weights; empty for a polynomial curve
    S start{};                   ///< the knot interval [start, end] of the domain the piece covers:
    S end{};                     ///< the Bézier parameter t ∈ [0, 1] is u = start + t (end − start)
};

/// The curve refined so that every distinct knot of the domain [u_p, u_{n+1}] has
/// multiplicity p (the ends included): the same curve, made of Bézier pieces.
template <class S> BSplineCurve<S> bezierKnotRefinement(const BSplineCurve<S>& c)
{
    BSplineCurve<S> q = c;
    std::vector<S> distinct;
    for (std::size_t i = static_cast<std::size_t>(c.degree); i <= c.points.size(); ++i)
        if (distinct.empty() || distinct.back() != c.knots[i])
            distinct.push_back(c.knots[i]);
    for (const S& u : distinct) {
        const int s = static_cast<int>(std::count(q.knots.begin(), q.knots.end(), u));
        if (s < q.degree)
            q = insertKnot(q, u, q.degree - s);
    }
    return q;
}

/// The Bézier pieces of `c` (which passes checkBSpline), one per non-empty span of the
/// domain, in order of u.
template <class S> std::vector<RationalBezierSegment<S>> toBezierSegments(const BSplineCurve<S>& c)
{
    const BSplineCurve<S> q = bezierKnotRefinement(c);
    const int p = q.degree, n = q.pointCount() - 1;
    std::vector<RationalBezierSegment<S>> out;
    for (int k = p; k <= n; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        if (!(q.knots[kk] < q.knots[kk + 1]))
            continue;
        RationalBezierSegment<S> seg;
        seg.points.assign(q.points.begin() + (k - p), q.points.begin() + (k + 1));
        if (q.rational())
            seg.weights.assign(q.weights.begin() + (k - p), q.weights.begin() + (k + 1));
        seg.start = q.knots[kk];
        seg.end = q.knots[kk + 1];
        out.push_back(std::move(seg));
    }
    return out;
}

} // namespace granota
