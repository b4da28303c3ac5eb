#pragma once
/// \file rational_bezier.h
/// Rational Bézier curves (beyond the thesis, which stops at polynomial curves, §2.1; Farin,
/// "Curves and Surfaces for CAGD", ch. 13; Piegl & Tiller, "The NURBS Book", §1.4):
///   c(t) = Σ w_i P_i B_i^n(t) / Σ w_i B_i^n(t),   weights w_i > 0.
/// c is the central projection of the polynomial curve with control points (w_i x_i, w_i y_i,
/// w_i) in homogeneous coordinates, so De Casteljau's construction (Def 2.4) runs on those
/// and every level is projected back:
///   w_i^r = (1 − t) w_i^{r−1} + t w_{i+1}^{r−1},
///   P_i^r = ((1 − t) w_i^{r−1} P_i^{r−1} + t w_{i+1}^{r−1} P_{i+1}^{r−1}) / w_i^r,
/// and c(t) = P_0^n(t). With every weight 1 this is Def 2.4 operation for operation apart from
/// divisions by 1, so the points are the polynomial curve's exactly. Templated on the scalar
/// like de_casteljau.h: Rational gives exact points at rational t (the weights (1, 1, 2) on
/// (1,0), (1,1), (0,1) give the unit circle's rational points, x = (1 − t²)/(1 + t²)).
///
/// The derivative (Farin, §13.6) is read off the last level but one:
///   c′(t) = n · w_0^{n−1} w_1^{n−1} / (w_0^n)² · (P_1^{n−1} − P_0^{n−1}),
/// and c″ from the homogeneous curve p(t) = Σ w_i P_i B_i^n, w(t) = Σ w_i B_i^n:
///   c″ = (p″ − 2 w′ c′ − w″ c) / w.
/// Every weight must be positive and t in [0, 1]: then every w_i^r is positive and nothing
/// divides by zero (checkRationalBezier; outside [0, 1] a weight sum can vanish).

#include "core/base/expected.h"
#include "core/base/vec2.h"
#include "core/curves/bezier/curvature.h"

#include <cassert>
#include <optional>
#include <vector>

namespace granota {

/// The fault in a rational Bézier curve's data, or nothing: at least one point, as many
/// weights as points, every weight positive (and finite, for doubles).
Expected<void> checkRationalBezier(std::size_t pointCount, const std::vector<double>& weights);
Expected<void> checkRationalBezier(std::size_t pointCount, const std::vector<Rational>& weights);

template <class S> struct RationalDeCasteljauTable {
    /// levels[r][i] = P_i^r(t), projected (Cartesian) points, r = 0..n, i = 0..n−r.
    std::vector<std::vector<Vec2<S>>> levels;
    /// weights[r][i] = w_i^r(t), the homogeneous coordinate of the same point.
    std::vector<std::vector<S>> weights;

    int degree() const { return static_cast<int>(levels.size()) - 1; }
    /// c(t) = P_0^n(t).
    const Vec2<S>& point() const { return levels.back().front(); }
    /// w(t) = w_0^n(t) = Σ w_i B_i^n(t).
    const S& weight() const { return weights.back().front(); }
    /// c′(t) = n w_0^{n−1} w_1^{n−1} / (w_0^n)² (P_1^{n−1} − P_0^{n−1}) (Farin, §13.6).
    Vec2<S> tangent() const
    {
        const int n = degree();
        if (n < 1)
            return Vec2<S>(S(0), S(0));
        const auto r = static_cast<std::size_t>(n - 1);
        const S& w = weight();
        const S factor = S(S(S(n) * weights[r][0]) * weights[r][1] / S(w * w));
        return factor * (levels[r][1] - levels[r][0]);
    }
    /// The curve on [0, t]: points P_0^0 … P_0^n with weights w_0^0 … w_0^n.
    std::vector<Vec2<S>> leftPoints() const
    {
        std::vector<Vec2<S>> out;
        for (const auto& level : levels)
            out.push_back(level.front());
        return out;
    }
    std::vector<S> leftWeights() const
    {
        std::vector<S> out;
        for (const auto& level : weights)
            out.push_back(level.front());
        return out;
    }
    /// The curve on [t, 1]: P_0^n, P_1^{n−1}, …, P_n^0 with their weights.
    std::vector<Vec2<S>> rightPoints() const
    {
        std::vector<Vec2<S>> out;
        for (auto it = levels.rbegin(); it != levels.rend(); ++it)
            out.push_back(it->back());
        return out;
    }
    std::vector<S> rightWeights() const
    {
        std::vector<S> out;
        for (auto it = weights.rbegin(); it != weights.rend(); ++it)
            out.push_back(it->back());
        return out;
    }
};

/// De Casteljau with weights, every level kept (the header's recurrence). points and weights
/// of the same size ≥ 1, weights positive, t in [0, 1] (checkRationalBezier).
template <class S>
RationalDeCasteljauTable<S> rationalDeCasteljau(const std::vector<Vec2<S>>& points, const std::vector<S>& weights, const S& t)
{
    assert(!points.empty() && points.size() == weights.size());
    RationalDeCasteljauTable<S> table;
    table.levels.reserve(points.size());
    table.weights.reserve(points.size());
    table.levels.push_back(points);
    table.weights.push_back(weights);
    const S u = S(S(1) - t);
    // The homogeneous points w_i^r P_i^r of the level before, carried along so that each
    // level costs one division per point.
    std::vector<Vec2<S>> homogeneous;
    homogeneous.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        homogeneous.push_back(weights[i] * points[i]);
    for (std::size_t r = 1; r < points.size(); ++r) {
        const auto& prevW = table.weights.back();
        std::vector<Vec2<S>> level;
        std::vector<S> levelW;
        level.reserve(prevW.size() - 1);
        levelW.reserve(prevW.size() - 1);
        for (std::size_t i = 0; i + 1 < prevW.size(); ++i) {
            const S w = S(u * prevW[i] + t * prevW[i + 1]);
            homogeneous[i] = u * homogeneous[i] + t * homogeneous[i + 1];
            const S inverse = S(S(1) / w);
            level.push_back(inverse * homogeneous[i]);
            levelW.push_back(w);
        }
        homogeneous.pop_back();
        table.levels.push_back(std::move(level));
        table.weights.push_back(std::move(levelW));
    }
    return table;
}

/// c(t) alone (the same homogeneous De Casteljau, one division at the end).
template <class S> Vec2<S> rationalBezierPoint(const std::vector<Vec2<S>>& points, const std::vector<S>& weights, const S& t)
{
    assert(!points.empty() && points.size() == weights.size());
    std::vector<Vec2<S>> h;
    std::vector<S> w = weights;
    h.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        h.push_back(weights[i] * points[i]);
    const S u = S(S(1) - t);
    for (std::size_t m = h.size(); m > 1; --m)
        for (std::size_t i = 0; i + 1 < m; ++i) {
            h[i] = u * h[i] + t * h[i + 1];
            w[i] = S(u * w[i] + t * w[i + 1]);
        }
    return S(S(1) / w[0]) * h[0];
}

/// c(t), c′(t) and c″(t) of a rational Bézier curve.
template <class S> struct RationalDerivatives {
    Vec2<S> point;
    Vec2<S> first;
    Vec2<S> second;
};

/// The header's formulas: p, w and their first two derivatives from the last three levels of
/// the homogeneous triangle (p′ = n Δp^{n−1}, p″ = n(n−1) Δ²p^{n−2}), then the quotient rule.
template <class S>
RationalDerivatives<S> rationalBezierDerivatives(const std::vector<Vec2<S>>& points, const std::vector<S>& weights, const S& t)
{
    const RationalDeCasteljauTable<S> table = rationalDeCasteljau(points, weights, t);
    const int n = table.degree();
    RationalDerivatives<S> d;
    d.point = table.point();
    d.first = table.tangent();
    d.second = Vec2<S>(S(0), S(0));
    if (n < 2)
        return d;
    const auto r = static_cast<std::size_t>(n - 2);
    const auto& P = table.levels[r];
    const auto& W = table.weights[r];
    const S nn1 = S(S(n) * S(n - 1));
    // Second differences of the homogeneous level n − 2 (w_i P_i and w_i).
    const Vec2<S> p0 = W[0] * P[0], p1 = W[1] * P[1], p2 = W[2] * P[2];
    const Vec2<S> pSecond = nn1 * (p2 - S(2) * p1 + p0);
    const S wSecond = S(nn1 * S(W[2] - S(2) * W[1] + W[0]));
    const auto q = static_cast<std::size_t>(n - 1);
    const S wFirst = S(S(n) * S(table.weights[q][1] - table.weights[q][0]));
    const S& w = table.weight();
    d.second = S(S(1) / w) * (pSecond - S(S(2) * wFirst) * d.first - wSecond * d.point);
    return d;
}

/// Curvature of a rational Bézier curve at t in doubles: the fields of curvature.h
/// (κ = (x′y″ − y′x″)/|c′|³; nullopt where c′ = 0 exactly or below 1e-12 of the curve's size).
CurvatureAt rationalCurvatureAt(const std::vector<Point>& points, const std::vector<double>& weights, double t);

/// κ exactly for rational points, weights and t, in the form of curvature.h (numerator
/// x′y″ − y′x″ and |c′|², both rational): exactCurvatureText writes it.
ExactCurvature exactRationalCurvatureAt(const std::vector<RPoint>& points, const std::vector<Rational>& weights,
                                        const Rational& t);

/// ∫_{t0}^{t1} |c′(t)| dt of a rational Bézier curve, 0 ≤ t0 ≤ t1 ≤ 1, by adaptive 16-point
/// Gauss–Legendre (gauss_legendre.h; the method of arc_length.h without its polynomial
/// speed-up): a panel is halved until its two halves agree with it to its share of
/// relativeTolerance × the length. The quarter circle gives π/2 to 1e-15.
double rationalArcLength(const std::vector<Point>& points, const std::vector<double>& weights, double t0 = 0, double t1 = 1,
                         double relativeTolerance = 1e-14);

} // namespace granota
