#pragma once
/// \file de_boor.h
/// De Boor's algorithm (de Boor 1972; Piegl & Tiller eq. (3.8), A3.1 and A4.1): c(u) by
/// repeated linear interpolation of the p + 1 control points of u's span k,
///   P_j^0 = P_j,   P_j^r = (1 − α_{j,r}) P_{j−1}^{r−1} + α_{j,r} P_j^{r−1},
///   α_{j,r} = (u − u_j) / (u_{j+p+1−r} − u_j),   j = k − p + r .. k,
/// and c(u) = P_k^p. It is De Casteljau's algorithm (Def 2.4) with the ratio t read on the knot
/// vector: on the clamped vector with no interior knot α_{j,r} = u and the two tables agree
/// entry by entry. A rational curve (NURBS) runs the same steps on the homogeneous points
/// (w x, w y, w) and divides at the end: every intermediate point is a point of the plane
/// with a weight, as in the rational De Casteljau algorithm.

#include "core/curves/bsplines/bspline_curve.h"
#include "core/curves/bsplines/knot_vector.h"

#include <array>
#include <cassert>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace granota {

template <class S> struct DeBoorTable {
    int span = 0; ///< k, with u_k ≤ u < u_{k+1} (findSpan)
    /// levels[r][i] = P_{k−p+r+i}^r, r = 0..p, i = 0..p − r: level 0 holds the span's p + 1
    /// control points P_{k−p}..P_k, the last level the point c(u). For a rational curve these
    /// are the points of the plane (the homogeneous points divided by their weights).
    std::vector<std::vector<Vec2<S>>> levels;
    /// The weights of those points, same shape; empty for a polynomial curve.
    std::vector<std::vector<S>> weightLevels;

    int degree() const { return static_cast<int>(levels.size()) - 1; }
    /// c(u).
    const Vec2<S>& point() const { return levels.back().front(); }
};

/// Every level of de Boor's algorithm at u. The curve must pass checkBSpline and u lie in
/// the domain [u_p, u_{n+1}] (outside it the end pieces are extended, which for a rational
/// curve may divide by a zero weight).
template <class S> DeBoorTable<S> deBoor(const BSplineCurve<S>& c, const S& u)
{
    const int p = c.degree;
    const int k = findSpan(c.knots, p, c.pointCount(), u);
    const auto K = [&](int i) -> const S& { return c.knots[static_cast<std::size_t>(i)]; };
    const bool rational = c.rational();
    DeBoorTable<S> t;
    t.span = k;
    t.levels.reserve(static_cast<std::size_t>(p + 1));
    // Homogeneous coordinates while computing: (w x, w y) in `h`, w in `w`.
    std::vector<Vec2<S>> h(c.points.begin() + (k - p), c.points.begin() + (k + 1));
    std::vector<S> w;
    t.levels.push_back(h);
    if (rational) {
        w.assign(c.weights.begin() + (k - p), c.weights.begin() + (k + 1));
        t.weightLevels.push_back(w);
        for (std::size_t i = 0; i < h.size(); ++i)
            h[i] = w[i] * h[i];
    }
    for (int r = 1; r <= p; ++r) {
        const std::size_t size = static_cast<std::size_t>(p - r + 1);
        for (std::size_t i = 0; i < size; ++i) {
            const int j = k - p + r + static_cast<int>(i);
            const S alpha = S(S(u - K(j)) / S(K(j + p + 1 - r) - K(j))); // the denominator ≥ u_{k+1} − u_k > 0
            const S beta = S(S(1) - alpha);
            h[i] = beta * h[i] + alpha * h[i + 1];
            if (rational)
                w[i] = S(beta * w[i] + alpha * w[i + 1]);
        }
        h.pop_back();
        if (rational) {
            w.pop_back();
            std::vector<Vec2<S>> level;
            level.reserve(size);
            for (std::size_t i = 0; i < size; ++i)
                level.emplace_back(S(h[i].x / w[i]), S(h[i].y / w[i]));
            t.levels.push_back(std::move(level));
            t.weightLevels.push_back(w);
        } else {
            t.levels.push_back(h);
        }
    }
    return t;
}

/// c(u) alone: the hot path for sampling, with the p + 1 points on the stack (no allocation
/// for doubles). Same preconditions as deBoor.
template <class S> Vec2<S> bsplinePoint(const BSplineCurve<S>& c, const S& u);

namespace detail {
/// The polynomial doubles' de Boor of bsplinePointInSpan with the degree P known when compiling:
/// the loops unrolled, the same operations in the same order (the same values to the bit).
template <int P, class S> Vec2<S> polynomialPointOfDegree(const BSplineCurve<S>& c, const S& u, int k)
{
    const S* knots = c.knots.data();
    S x[P + 1], y[P + 1];
    const Vec2<S>* points = c.points.data() + (k - P);
    for (int i = 0; i <= P; ++i) {
        x[i] = points[i].x;
        y[i] = points[i].y;
    }
    for (int r = 1; r <= P; ++r)
        for (int i = 0; i <= P - r; ++i) {
            const int j = k - P + r + i;
            const S alpha = (u - knots[j]) / (knots[j + P + 1 - r] - knots[j]);
            const S beta = S(1) - alpha;
            x[i] = beta * x[i] + alpha * x[i + 1];
            y[i] = beta * y[i] + alpha * y[i + 1];
        }
    return Vec2<S>(x[0], y[0]);
}
} // namespace detail

/// bsplinePoint with u's span k already known (k = findSpan(c.knots, p, n + 1, u)):
/// bspline_sampling.h finds it by stepping from the last parameter's span.
template <class S> Vec2<S> bsplinePointInSpan(const BSplineCurve<S>& c, const S& u, int k)
{
    const int p = c.degree;
    assert(p >= 0 && p <= kMaxBSplineDegree);
    const S* knots = c.knots.data();
    if constexpr (std::is_floating_point_v<S>) {
        if (!c.rational()) {
            switch (p) { // the usual degrees unrolled (issue 36's benchmark: a cubic)
            case 2: return detail::polynomialPointOfDegree<2>(c, u, k);
            case 3: return detail::polynomialPointOfDegree<3>(c, u, k);
            default: break;
            }
            // Plain arrays, left uninitialised: the doubles' path does no work it need not.
            S x[kMaxBSplineDegree + 1], y[kMaxBSplineDegree + 1];
            const Vec2<S>* P = c.points.data() + (k - p);
            for (int i = 0; i <= p; ++i) {
                x[i] = P[i].x;
                y[i] = P[i].y;
            }
            for (int r = 1; r <= p; ++r)
                for (int i = 0; i <= p - r; ++i) {
                    const int j = k - p + r + i;
                    const S alpha = (u - knots[j]) / (knots[j + p + 1 - r] - knots[j]);
                    const S beta = S(1) - alpha;
                    x[i] = beta * x[i] + alpha * x[i + 1];
                    y[i] = beta * y[i] + alpha * y[i + 1];
                }
            return Vec2<S>(x[0], y[0]);
        }
    }
    std::array<Vec2<S>, kMaxBSplineDegree + 1> h;
    std::array<S, kMaxBSplineDegree + 1> w;
    const bool rational = c.rational();
    for (int i = 0; i <= p; ++i) {
        const auto src = static_cast<std::size_t>(k - p + i);
        const auto dst = static_cast<std::size_t>(i);
        if (rational) {
            w[dst] = c.weights[src];
            h[dst] = w[dst] * c.points[src];
        } else {
            h[dst] = c.points[src];
        }
    }
    for (int r = 1; r <= p; ++r)
        for (int i = 0; i <= p - r; ++i) {
            const int j = k - p + r + i;
            const auto ii = static_cast<std::size_t>(i);
            const S alpha = S(S(u - knots[j]) / S(knots[j + p + 1 - r] - knots[j]));
            const S beta = S(S(1) - alpha);
            h[ii] = beta * h[ii] + alpha * h[ii + 1];
            if (rational)
                w[ii] = S(beta * w[ii] + alpha * w[ii + 1]);
        }
    if (rational)
        return Vec2<S>(S(h[0].x / w[0]), S(h[0].y / w[0]));
    return h[0];
}

template <class S> Vec2<S> bsplinePoint(const BSplineCurve<S>& c, const S& u)
{
    return bsplinePointInSpan(c, u, findSpan(c.knots, c.degree, c.pointCount(), u));
}

} // namespace granota
