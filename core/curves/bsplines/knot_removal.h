#pragma once
/// \file knot_removal.h
/// Knot removal (Tiller, "Knot-removal algorithms for NURBS curves and surfaces", CAD 24
/// (1992); Piegl & Tiller A5.8): the inverse of knot insertion. Removing ū once solves the
/// insertion equations of knot_insertion.h for the old control points from both ends; the
/// two solutions meet in the middle, and ū is removable exactly when they agree there. Only
/// what leaves the curve unchanged is removed: exactly (the two solutions equal) in Rational
/// with tolerance 0; for doubles up to `tolerance`, the distance between the two solutions
/// (Tiller's bound on how far the curve moves), the largest reported as maxError. A rational
/// curve is done on its homogeneous points (w x, w y, w), the distance measured there.

#include "core/curves/bsplines/bspline_curve.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <vector>

namespace granota {

template <class S> struct KnotRemoval {
    BSplineCurve<S> curve; ///< the curve with `removed` copies of ū fewer
    int removed = 0;       ///< 0..times: how many copies could be removed within the tolerance
    double maxError = 0;   ///< the largest distance accepted by Tiller's test (0 when exact)
};

namespace detail {
/// A homogeneous control point (w x, w y, w).
template <class S> struct Homogeneous {
    S x{}, y{}, w{};
};
template <class S> Homogeneous<S> combine(const S& a, const Homogeneous<S>& p, const S& b, const Homogeneous<S>& q)
{
    return {S(a * p.x + b * q.x), S(a * p.y + b * q.y), S(a * p.w + b * q.w)};
}
template <class S> S squaredDistance(const Homogeneous<S>& p, const Homogeneous<S>& q)
{
    const S dx = S(p.x - q.x), dy = S(p.y - q.y), dw = S(p.w - q.w);
    return S(dx * dx + dy * dy + dw * dw);
}
} // namespace detail

/// `c` (passing checkBSpline) with ū removed up to `times` times, as far as the curve stays
/// the same within `tolerance` ≥ 0 (exactly when 0). ū must be a knot strictly inside the
/// domain (u_p, u_{n+1}); any other ū removes nothing.
template <class S> KnotRemoval<S> removeKnot(const BSplineCurve<S>& c, const S& u, int times = 1, double tolerance = 0)
{
    using H = detail::Homogeneous<S>;
    KnotRemoval<S> result{c, 0, 0.0};
    const int p = c.degree, n = c.pointCount() - 1, m = n + p + 1;
    const auto z = [](int i) { return static_cast<std::size_t>(i); };
    const auto& U = c.knots;
    const int s = static_cast<int>(std::count(U.begin(), U.end(), u));
    if (times < 1 || s == 0 || !(c.domainStart() < u && u < c.domainEnd()))
        return result;
    const int num = std::min(times, s);
    // r: the last index with u_r = ū.
    const int r = static_cast<int>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
    const bool rational = c.rational();
    std::vector<H> Pw(z(n + 1));
    for (int i = 0; i <= n; ++i) {
        const S w = rational ? c.weights[z(i)] : S(1);
        Pw[z(i)] = {S(w * c.points[z(i)].x), S(w * c.points[z(i)].y), w};
    }
    const double tol2 = tolerance * tolerance;
    // Accepts a squared distance within the tolerance; exact equality when it is 0.
    const auto accept = [&](const S& d2) {
        const double d = std::sqrt(toDouble(d2));
        if (tolerance == 0 ? d2 == S(0) : toDouble(d2) <= tol2) {
            result.maxError = std::max(result.maxError, d);
            return true;
        }
        return false;
    };
    const int ord = p + 1;
    const int fout = (2 * r - s - p) / 2; // the first control point to go
    int last = r - s, first = r - p;
    std::vector<H> temp(z(2 * p + 1));
    int t = 0;
    for (; t < num; ++t) {
        const int off = first - 1; // temp[i − off] stands for P_i
        temp[0] = Pw[z(off)];
        temp[z(last + 1 - off)] = Pw[z(last + 1)];
        int i = first, j = last, ii = 1, jj = last - off;
        // Solve from both ends towards the middle (Boehm's equations backwards).
        while (j - i > t) {
            const S alfi = S(S(u - U[z(i)]) / S(U[z(i + ord + t)] - U[z(i)]));
            const S alfj = S(S(u - U[z(j - t)]) / S(U[z(j + ord)] - U[z(j - t)]));
            temp[z(ii)] = detail::combine(S(S(1) / alfi), Pw[z(i)], S(S(alfi - S(1)) / alfi), temp[z(ii - 1)]);
            temp[z(jj)] = detail::combine(S(S(1) / S(S(1) - alfj)), Pw[z(j)], S(-alfj / S(S(1) - alfj)), temp[z(jj + 1)]);
            ++i;
            ++ii;
            --j;
            --jj;
        }
        bool removable;
        if (j - i < t) { // the two solutions meet: they must agree
            removable = accept(detail::squaredDistance(temp[z(ii - 1)], temp[z(jj + 1)]));
        } else { // one point left in the middle: it must be the combination of its neighbours
            const S alfi = S(S(u - U[z(i)]) / S(U[z(i + ord + t)] - U[z(i)]));
            const H mid = detail::combine(alfi, temp[z(ii + t + 1)], S(S(1) - alfi), temp[z(ii - 1)]);
            removable = accept(detail::squaredDistance(Pw[z(i)], mid));
        }
        if (!removable)
            break;
        i = first;
        j = last;
        while (j - i > t) {
            Pw[z(i)] = temp[z(i - off)];
            Pw[z(j)] = temp[z(j - off)];
            ++i;
            --j;
        }
        --first;
        ++last;
    }
    if (t == 0)
        return result;
    // Shift the knots and the control points down over the removed ones.
    std::vector<S> knots(U);
    for (int k = r + 1; k <= m; ++k)
        knots[z(k - t)] = knots[z(k)];
    knots.resize(knots.size() - z(t));
    int j = fout, i = fout;
    for (int k = 1; k < t; ++k) {
        if (k % 2 == 1)
            ++i;
        else
            --j;
    }
    for (int k = i + 1; k <= n; ++k) {
        Pw[z(j)] = Pw[z(k)];
        ++j;
    }
    Pw.resize(Pw.size() - z(t));
    result.removed = t;
    result.curve.knots = std::move(knots);
    result.curve.points.clear();
    result.curve.weights.clear();
    for (const H& h : Pw) {
        result.curve.points.emplace_back(S(h.x / h.w), S(h.y / h.w));
        if (rational)
            result.curve.weights.push_back(h.w);
    }
    return result;
}

} // namespace granota
