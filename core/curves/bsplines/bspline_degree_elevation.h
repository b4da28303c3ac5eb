#pragma once
/// \file bspline_degree_elevation.h
/// Degree elevation of a B-spline: the same curve written with degree p + 1 (Piegl & Tiller
/// §5.5; the book's A5.9 does it in one pass). Done here in the three steps that explain it:
/// Bézier extraction (bezier_extraction.h), degree elevation of each Bézier piece
/// (core/curves/bezier/degree_elevation.h), and knot removal (knot_removal.h) of what the
/// pieces' joins do not need: a knot of multiplicity m on the degree-p curve ends with
/// multiplicity m + 1, the continuity C^{p−m} unchanged. A rational curve is elevated on its
/// homogeneous points. Exact in Rational; the removals are then exact too.

#include "core/curves/bezier/degree_elevation.h"
#include "core/curves/bsplines/bezier_extraction.h"
#include "core/curves/bsplines/bspline_curve.h"
#include "core/curves/bsplines/knot_removal.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace granota {

/// `c` (passing checkBSpline, degree p < kMaxBSplineDegree) with degree p + 1, the same curve
/// on the domain. The result is clamped at the domain's ends: a floating end's knots outside
/// the domain shape nothing on it, and are not kept. For doubles the removals allow a
/// rounding-sized error (1e-9 of the control points' extent).
template <class S> BSplineCurve<S> elevateDegree(const BSplineCurve<S>& c)
{
    const int p = c.degree, q = p + 1;
    const bool rational = c.rational();
    const auto segments = toBezierSegments(c);
    BSplineCurve<S> e;
    e.degree = q;
    for (std::size_t j = 0; j < segments.size(); ++j) {
        const auto& seg = segments[j];
        // Homogeneous points (w x, w y) and the weights as points (w, 0): both elevate linearly.
        std::vector<Vec2<S>> h = seg.points, w;
        if (rational)
            for (std::size_t i = 0; i < h.size(); ++i) {
                h[i] = seg.weights[i] * h[i];
                w.emplace_back(seg.weights[i], S(0));
            }
        const auto eh = granota::elevateDegree(h);
        const auto ew = rational ? granota::elevateDegree(w) : std::vector<Vec2<S>>{};
        for (std::size_t i = j == 0 ? 0 : 1; i < eh.size(); ++i) { // the pieces share their ends
            if (rational) {
                e.points.emplace_back(S(eh[i].x / ew[i].x), S(eh[i].y / ew[i].x));
                e.weights.push_back(ew[i].x);
            } else {
                e.points.push_back(eh[i]);
            }
        }
        const int copies = j == 0 ? q + 1 : q;
        for (int i = 0; i < copies; ++i)
            e.knots.push_back(seg.start);
    }
    for (int i = 0; i <= q; ++i)
        e.knots.push_back(segments.back().end);

    double tolerance = 0;
    if constexpr (std::is_floating_point_v<S>) {
        double extent = 0;
        for (const auto& pt : c.points)
            extent = std::max({extent, std::abs(static_cast<double>(pt.x)), std::abs(static_cast<double>(pt.y))});
        tolerance = 1e-9 * std::max(extent, 1.0);
    }
    // Each interior knot of multiplicity m in c goes back from q to m + 1.
    for (std::size_t j = 1; j < segments.size(); ++j) {
        const S& u = segments[j].start;
        const int m = static_cast<int>(std::count(c.knots.begin(), c.knots.end(), u));
        if (q - (m + 1) > 0)
            e = removeKnot(e, u, q - (m + 1), tolerance).curve;
    }
    return e;
}

} // namespace granota
