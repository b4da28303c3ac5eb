#pragma once
/// \file bezier_extraction.h
/// Bézier extraction (Piegl & Tiller §5.3, A5.6 "DecomposeCurve"; Boehm 1980): the same curve
/// written as one Bézier piece (Def 2.4) per non-empty knot span — the §2.3 dilemma seen from
/// the other side: a B-spline is many Bézier curves joined with the continuity its knots allow.
/// It is what inserting every distinct knot of the domain until it has multiplicity p gives
/// (the ends included), done in one pass from left to right: each piece's p + 1 points are
/// refined in place while the first points of the next piece are saved on the way, O(n p²)
/// work instead of the O(n² p²) of inserting the knots one by one into the whole curve.
/// A rational curve is done on its homogeneous points (w x, w y, w) and gives rational Bézier
/// pieces with their weights. Exact in Rational: the pieces are unique, so the result equals
/// the one-by-one insertion's exactly (test_bspline_extraction).

#include "core/curves/bsplines/bspline_curve.h"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <utility>
#include <vector>

namespace granota {

template <class S> struct RationalBezierSegment {
    std::vector<Vec2<S>> points; ///< the p + 1 Bézier control points of the piece
    std::vector<S> weights;      ///< their weights; empty for a polynomial curve
    S start{};                   ///< the knot interval [start, end] of the domain the piece covers:
    S end{};                     ///< the Bézier parameter t ∈ [0, 1] is u = start + t (end − start)
};

/// The Bézier pieces of `c` (which passes checkBSpline), one per non-empty span of the
/// domain [u_p, u_{n+1}], in order of u (Piegl & Tiller A5.6, with a floating start).
template <class S> std::vector<RationalBezierSegment<S>> toBezierSegments(const BSplineCurve<S>& c)
{
    const int p = c.degree, n = c.pointCount() - 1;
    const int lastKnot = n + p + 1;
    const bool rational = c.rational();
    const auto z = [](int i) { return static_cast<std::size_t>(i); };
    const auto U = [&](int i) -> const S& { return c.knots[z(i)]; };
    // The working piece: homogeneous points (w x, w y) in Q and their w in QW (polynomial: no w).
    std::vector<Vec2<S>> Q(z(p + 1)), next(z(p + 1));
    std::vector<S> QW(rational ? z(p + 1) : 0), nextW(rational ? z(p + 1) : 0);
    const auto load = [&](std::vector<Vec2<S>>& to, std::vector<S>& toW, int slot, int i) {
        if (rational) {
            toW[z(slot)] = c.weights[z(i)];
            to[z(slot)] = c.weights[z(i)] * c.points[z(i)];
        } else {
            to[z(slot)] = c.points[z(i)];
        }
    };
    // Q_k ← α Q_i + (1 − α) Q_j (i, j ∈ {k − 1, k, k + 1}), the step of every knot insertion (A5.1).
    const auto blend = [&](int k, const S& alpha, int i, int j) {
        const S beta = S(S(1) - alpha);
        Q[z(k)] = alpha * Q[z(i)] + beta * Q[z(j)];
        if (rational)
            QW[z(k)] = S(alpha * QW[z(i)] + beta * QW[z(j)]);
    };

    // a: the last index of the knot u_p, so that [u_a, u_{a+1}) is the first non-empty span;
    // its p + 1 control points P_{a−p..a}.
    int a = p;
    while (!(U(a) < U(a + 1)))
        ++a;
    assert(a <= n);
    for (int i = 0; i <= p; ++i)
        load(Q, QW, i, a - p + i);
    // A floating start (u_a of multiplicity s < p): insert u_a p − s times on the left of the
    // piece (A5.1 restricted to these points, in place: the j-th insertion leaves its last
    // point final), so that every piece begins, as A5.6 assumes, with its left knot p times.
    int s = 1;
    while (a - s >= 0 && U(a - s) == U(a))
        ++s;
    for (int j = 1; j <= p - s; ++j)
        for (int i = 0; i <= p - j - s; ++i) {
            const S& left = U(a - p + j + i);
            // α = (u_a − u_{a−p+j+i}) / (u_{a+1+i} − u_{a−p+j+i}); u_{a+1+i} > u_a ≥ the left knot.
            blend(i, S(S(U(a) - left) / S(U(a + 1 + i) - left)), i + 1, i);
        }

    std::vector<RationalBezierSegment<S>> out;
    std::vector<S> alphas(z(p));
    for (;;) {
        // u_b, the piece's right end, and its multiplicity mult (b..last).
        const int b = a + 1;
        int last = b;
        while (last < lastKnot && U(last + 1) == U(b))
            ++last;
        const int mult = last - b + 1;
        // Insert u_b p − mult times (A5.6): the left knots of the piece are u_a p times, so α
        // depends only on the right knot u_{a+j}; each insertion's last point is a point of the
        // next piece.
        if (mult < p) {
            for (int j = p; j > mult; --j)
                alphas[z(j - mult - 1)] = S(S(U(b) - U(a)) / S(U(a + j) - U(a)));
            const int r = p - mult;
            for (int j = 1; j <= r; ++j) {
                const int first = mult + j;
                for (int k = p; k >= first; --k)
                    blend(k, alphas[z(k - first)], k, k - 1);
                next[z(r - j)] = Q[z(p)];
                if (rational)
                    nextW[z(r - j)] = QW[z(p)];
            }
        }
        RationalBezierSegment<S> seg;
        seg.start = U(a);
        seg.end = U(b);
        seg.points.resize(z(p + 1));
        if (rational) {
            seg.weights = QW;
            for (int i = 0; i <= p; ++i)
                seg.points[z(i)] = Vec2<S>(S(Q[z(i)].x / QW[z(i)]), S(Q[z(i)].y / QW[z(i)]));
        } else {
            seg.points = Q;
        }
        out.push_back(std::move(seg));
        if (last >= n + 1) // u_b is the domain's end
            break;
        // The next piece: the saved points, then P_{last−p+i} for the rest (all of them after a
        // knot of multiplicity p).
        for (int i = std::max(0, p - mult); i <= p; ++i)
            load(next, nextW, i, last - p + i);
        std::swap(Q, next);
        std::swap(QW, nextW);
        a = last;
    }
    return out;
}

} // namespace granota
