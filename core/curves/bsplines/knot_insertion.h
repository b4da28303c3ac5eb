#pragma once
/// \file knot_insertion.h
/// Knot insertion (Boehm, "Inserting new knots into B-spline curves", CAD 12 (1980);
/// Piegl & Tiller A5.1): the same curve written on the knot vector with ū inserted r times,
/// with r more control points,
///   Q_i = α_i P_i + (1 − α_i) P_{i−1},   α_i = (ū − u_i)/(u_{i+p} − u_i),
/// repeated r times — the first r steps of de Boor's algorithm at ū (de_boor.h), kept. A
/// rational curve is done on its homogeneous points (w x, w y, w). Exact in Rational.
/// The span used is the largest k with u_k ≤ ū in the whole vector, not findSpan's span of
/// the domain: at the end of a floating domain they differ, and the domain's span gives a
/// wrong curve (the bug of NURBS-Python issue #158, a test in test_bspline_knots).

#include "core/curves/bsplines/bspline_curve.h"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <string>
#include <vector>

namespace granota {

/// Whether ū may be inserted `times` times into `c` (which passes checkBSpline): ū in the
/// domain [u_p, u_{n+1}], times ≥ 1, and ū's multiplicity s + times ≤ p afterwards (a knot of
/// multiplicity p already makes the curve pass through a control point; more would split it).
template <class S> Expected<void> checkKnotInsertion(const BSplineCurve<S>& c, const S& u, int times)
{
    if (times < 1)
        return makeError(ErrorCode::OutOfRange, "a knot is inserted at least once, not " + std::to_string(times) + " times",
                         MessageId::KnotInsertionTimes, {numberArg(times)});
    if (u < c.domainStart() || c.domainEnd() < u)
        return makeError(ErrorCode::OutOfRange,
                         "the knot " + bsplineNumberText(u) + " is outside the domain [" + bsplineNumberText(c.domainStart()) +
                             ", " + bsplineNumberText(c.domainEnd()) + "]",
                         MessageId::KnotOutsideDomain,
                         {bsplineNumberArg(u), bsplineNumberArg(c.domainStart()), bsplineNumberArg(c.domainEnd())});
    const auto range = std::equal_range(c.knots.begin(), c.knots.end(), u);
    const int s = static_cast<int>(range.second - range.first);
    if (s + times > c.degree)
        return makeError(ErrorCode::OutOfRange,
                         "the knot " + bsplineNumberText(u) + " has multiplicity " + std::to_string(s) + "; inserting it " +
                             std::to_string(times) + " more times would exceed the degree " + std::to_string(c.degree),
                         MessageId::KnotInsertionMultiplicity,
                         {bsplineNumberArg(u), numberArg(s), numberArg(times), numberArg(c.degree)});
    return {};
}

/// `c` with ū inserted `times` times (Boehm; Piegl & Tiller A5.1). checkKnotInsertion must
/// accept (c, ū, times).
template <class S> BSplineCurve<S> insertKnot(const BSplineCurve<S>& c, const S& u, int times = 1)
{
    assert(checkKnotInsertion(c, u, times).ok());
    const int p = c.degree, n = c.pointCount() - 1, r = times;
    const bool rational = c.rational();
    // k: the last knot ≤ ū; s: ū's multiplicity.
    const int k = static_cast<int>(std::upper_bound(c.knots.begin(), c.knots.end(), u) - c.knots.begin()) - 1;
    const int s = static_cast<int>(std::count(c.knots.begin(), c.knots.end(), u));
    const auto z = [](int i) { return static_cast<std::size_t>(i); };

    BSplineCurve<S> q;
    q.degree = p;
    q.knots.reserve(c.knots.size() + z(r));
    q.knots.insert(q.knots.end(), c.knots.begin(), c.knots.begin() + (k + 1));
    q.knots.insert(q.knots.end(), z(r), u);
    q.knots.insert(q.knots.end(), c.knots.begin() + (k + 1), c.knots.end());

    // Homogeneous points: (w x, w y) and w (w = 1 for a polynomial curve).
    std::vector<Vec2<S>> P(c.points);
    std::vector<S> W = rational ? c.weights : std::vector<S>(c.points.size(), S(1));
    if (rational)
        for (std::size_t i = 0; i < P.size(); ++i)
            P[i] = W[i] * P[i];
    std::vector<Vec2<S>> Q(z(n + r + 1));
    std::vector<S> QW(z(n + r + 1));
    for (int i = 0; i <= k - p; ++i) {
        Q[z(i)] = P[z(i)];
        QW[z(i)] = W[z(i)];
    }
    for (int i = k - s; i <= n; ++i) {
        Q[z(i + r)] = P[z(i)];
        QW[z(i + r)] = W[z(i)];
    }
    std::vector<Vec2<S>> R(P.begin() + (k - p), P.begin() + (k - s + 1));
    std::vector<S> RW(W.begin() + (k - p), W.begin() + (k - s + 1));
    int L = k - p;
    for (int j = 1; j <= r; ++j) {
        L = k - p + j;
        for (int i = 0; i <= p - j - s; ++i) {
            const S& a = c.knots[z(L + i)];
            const S alpha = S(S(u - a) / S(c.knots[z(i + k + 1)] - a));
            const S beta = S(S(1) - alpha);
            R[z(i)] = alpha * R[z(i + 1)] + beta * R[z(i)];
            RW[z(i)] = S(alpha * RW[z(i + 1)] + beta * RW[z(i)]);
        }
        Q[z(L)] = R[0];
        QW[z(L)] = RW[0];
        Q[z(k + r - j - s)] = R[z(p - j - s)];
        QW[z(k + r - j - s)] = RW[z(p - j - s)];
    }
    for (int i = L + 1; i < k - s; ++i) {
        Q[z(i)] = R[z(i - L)];
        QW[z(i)] = RW[z(i - L)];
    }
    if (rational) {
        for (std::size_t i = 0; i < Q.size(); ++i)
            Q[i] = Vec2<S>(S(Q[i].x / QW[i]), S(Q[i].y / QW[i]));
        q.weights = std::move(QW);
    }
    q.points = std::move(Q);
    return q;
}

} // namespace granota
