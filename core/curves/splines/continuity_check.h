#pragma once
/// \file continuity_check.h
/// Checks the smoothness a spline claims, knot by knot.
///  - checkContinuity: a function spline (Def 2.2, Def 2.3): at every interior knot x_i
///    compares s^(k)(x_i−) and s^(k)(x_i+) for k = 0..maxOrder, and checks that every data
///    point (x_i, y_i) is interpolated by each piece whose closed interval holds x_i.
///    This is what exposes Ex 2.1's slip: its s₂ as printed misses a constant +1/53, so
///    s jumps by −1/53 at x = 1 and x = 2 and s₂ does not pass through (1, 3) and (2, 1),
///    while s′ and s″ do match.
///  - checkSegmentJoins: a parametric curve made of segments p_1, p_2, … on s ∈ [0, 1]
///    (Def 2.10): compares p_i^(k)(1) with p_{i+1}^(k)(0), and the last segment with the
///    first for a closed loop. Prop 2.3 (Catmull-Rom curves are C¹) is the case k ≤ 1.
///
/// Exact for Rational (tolerance 0). For doubles a tolerance > 0 accepts |a − b| ≤
/// tolerance · max(1, |a|, |b|) (relative for large values, absolute near 0).

#include "core/curves/splines/piecewise_polynomial.h"
#include "core/exact/polynomial.h"
#include "core/exact/rational.h"
#include "core/base/vec2.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace granota {

namespace detail {
/// Exact text of a scalar: "158/53" for Rational, shortest round-trip for doubles.
std::string scalarText(const Rational& v);
std::string scalarText(double v);
inline std::string scalarText(const Vec2<Rational>& v) { return "(" + scalarText(v.x) + ", " + scalarText(v.y) + ")"; }
inline std::string scalarText(const Vec2<double>& v) { return "(" + scalarText(v.x) + ", " + scalarText(v.y) + ")"; }
/// "s", "s'", "s''", "s'''", "s^(4)": the k-th derivative of `name`.
std::string derivativeName(const std::string& name, int order);

inline Rational absValue(const Rational& v) { return Rational(abs(v)); }
inline double absValue(double v) { return std::fabs(v); }

/// a = b exactly, or within the relative/absolute tolerance described in the file comment.
template <class S> bool nearlyEqual(const S& a, const S& b, double tolerance)
{
    if (a == b)
        return true;
    if (!(tolerance > 0))
        return false;
    const S scale = std::max({S(1), absValue(a), absValue(b)});
    return absValue(S(a - b)) <= S(S(tolerance) * scale); // false for NaN
}
template <class S> bool nearlyEqual(const Vec2<S>& a, const Vec2<S>& b, double tolerance)
{
    return nearlyEqual(a.x, b.x, tolerance) && nearlyEqual(a.y, b.y, tolerance);
}

/// What ContinuityReport and JoinReport share. The highest k below the order of every
/// defect that `counts`, capped at maxOrder (−1: not even continuous).
template <class Defects, class Counts> int continuityOrder(const Defects& defects, int maxOrder, Counts counts)
{
    int k = maxOrder;
    for (const auto& d : defects)
        if (counts(d))
            k = std::min(k, d.order - 1);
    return k;
}
/// The first line of a report on order c: `broken` when c < 0, "<subject> is C^c but not
/// C^(c+1)<where>" below maxOrder, else "<subject> is C^c<everywhere> (derivatives checked
/// up to order maxOrder)".
inline std::string continuitySummary(int c, int maxOrder, const std::string& broken, const std::string& subject,
                                     const std::string& where, const std::string& everywhere)
{
    if (c < 0)
        return broken;
    if (c < maxOrder)
        return subject + " is C^" + std::to_string(c) + " but not C^" + std::to_string(c + 1) + where;
    return subject + " is C^" + std::to_string(c) + everywhere + " (derivatives checked up to order " + std::to_string(maxOrder) +
           ")";
}
/// One line per defect, each starting with a newline and ending with a full stop.
template <class Defects> std::string defectLines(const Defects& defects)
{
    std::string out;
    for (const auto& d : defects)
        out += "\n" + d.describe() + ".";
    return out;
}
} // namespace detail

enum class DefectKind {
    Jump,            ///< a derivative of some order differs left and right of a knot
    NotInterpolated, ///< a piece misses a data point inside its interval
    OutsideDomain,   ///< a data point lies outside [x_0, x_k]
};

/// One thing wrong with a function spline.
template <class S> struct ContinuityDefect {
    DefectKind kind = DefectKind::Jump;
    int knot = -1;  ///< Jump: index i of the interior knot x_i (1..k−1)
    int order = 0;  ///< Jump: derivative order (0 = the value)
    int point = -1; ///< NotInterpolated / OutsideDomain: index of the data point
    int piece = -1; ///< NotInterpolated: the piece (0-based; the thesis's s_{piece+1})
    S x{};          ///< where: the knot or the data point's abscissa
    S left{};       ///< Jump: s^(order)(x−), from the piece on the left
    S right{};      ///< Jump: s^(order)(x+), from the piece on the right
    S expected{};   ///< NotInterpolated / OutsideDomain: the data value y_i
    S got{};        ///< NotInterpolated: s_{piece+1}(x_i)

    S jump() const { return S(right - left); }
    /// e.g. "s is discontinuous at x = 1: left 3, right 158/53 (jump -1/53)",
    /// "s_2 does not interpolate (1, 3): s_2(1) = 158/53".
    std::string describe() const
    {
        using detail::scalarText;
        switch (kind) {
        case DefectKind::Jump:
            return detail::derivativeName("s", order) + " is discontinuous at x = " + scalarText(x) + ": left " +
                   scalarText(left) + ", right " + scalarText(right) + " (jump " + scalarText(jump()) + ")";
        case DefectKind::NotInterpolated: {
            const std::string name = "s_" + std::to_string(piece + 1);
            return name + " does not interpolate (" + scalarText(x) + ", " + scalarText(expected) + "): " + name + "(" +
                   scalarText(x) + ") = " + scalarText(got);
        }
        case DefectKind::OutsideDomain:
            return "the point (" + scalarText(x) + ", " + scalarText(expected) + ") lies outside the domain";
        }
        return {};
    }
};

template <class S> struct ContinuityReport {
    int maxOrder = 2;      ///< derivatives 0..maxOrder were compared
    double tolerance = 0;  ///< 0 = exact comparison
    int interiorKnots = 0; ///< knots checked (x_1..x_{k−1})
    int dataPoints = 0;    ///< data points checked
    std::vector<ContinuityDefect<S>> defects;

    bool ok() const { return defects.empty(); }
    /// Every data point is interpolated (by every piece that reaches it).
    bool interpolates() const
    {
        return std::none_of(defects.begin(), defects.end(),
                            [](const ContinuityDefect<S>& d) { return d.kind != DefectKind::Jump; });
    }
    /// Highest k such that s, s′, …, s^(k) match at every knot; −1 if s is not even
    /// continuous. Capped at maxOrder: nothing above it was looked at.
    int continuityOrder() const
    {
        return detail::continuityOrder(defects, maxOrder,
                                       [](const ContinuityDefect<S>& d) { return d.kind == DefectKind::Jump; });
    }
    /// A summary line, then one line per defect.
    std::string describe() const
    {
        std::string out = detail::continuitySummary(continuityOrder(), maxOrder, "s is not continuous", "s", "",
                                                    " at every knot");
        if (dataPoints > 0)
            out += interpolates() ? "; it interpolates all " + std::to_string(dataPoints) + " points"
                                  : "; it does not interpolate every point";
        return out + "." + detail::defectLines(defects);
    }
};

/// See the file comment. `pp` must be valid (pp.isValid()); maxOrder ≥ 0.
template <class S>
ContinuityReport<S> checkContinuity(const PiecewisePolynomial<S>& pp, int maxOrder = 2, const std::vector<Vec2<S>>& data = {},
                                    double tolerance = 0)
{
    assert(pp.isValid() && maxOrder >= 0);
    ContinuityReport<S> report;
    report.maxOrder = maxOrder;
    report.tolerance = tolerance;
    report.interiorKnots = pp.pieceCount() - 1;
    report.dataPoints = static_cast<int>(data.size());

    // Def 2.3, 3.: s ∈ C² means s, s′, s″ agree from both sides at each x_i.
    PiecewisePolynomial<S> d = pp;
    for (int order = 0; order <= maxOrder; ++order) {
        for (int i = 1; i < pp.pieceCount(); ++i) {
            const S& x = pp.knots[static_cast<std::size_t>(i)];
            const S left = d.evaluatePiece(i - 1, x);
            const S right = d.evaluatePiece(i, x);
            if (!detail::nearlyEqual(left, right, tolerance)) {
                ContinuityDefect<S> defect;
                defect.kind = DefectKind::Jump;
                defect.knot = i;
                defect.order = order;
                defect.x = x;
                defect.left = left;
                defect.right = right;
                report.defects.push_back(std::move(defect));
            }
        }
        if (order < maxOrder)
            d = d.derivative();
    }

    // Def 2.3, 1.: s(x_i) = y_i, asked of every piece that reaches x_i.
    for (std::size_t p = 0; p < data.size(); ++p) {
        const S& x = data[p].x;
        const S& y = data[p].y;
        if (x < pp.domainBegin() || pp.domainEnd() < x || !(x == x)) {
            ContinuityDefect<S> defect;
            defect.kind = DefectKind::OutsideDomain;
            defect.point = static_cast<int>(p);
            defect.x = x;
            defect.expected = y;
            report.defects.push_back(std::move(defect));
            continue;
        }
        for (int i = 0; i < pp.pieceCount(); ++i) {
            const S& a = pp.knots[static_cast<std::size_t>(i)];
            const S& b = pp.knots[static_cast<std::size_t>(i + 1)];
            if (x < a || b < x)
                continue;
            const S got = pp.evaluatePiece(i, x);
            if (!detail::nearlyEqual(got, y, tolerance)) {
                ContinuityDefect<S> defect;
                defect.kind = DefectKind::NotInterpolated;
                defect.point = static_cast<int>(p);
                defect.piece = i;
                defect.x = x;
                defect.expected = y;
                defect.got = got;
                report.defects.push_back(std::move(defect));
            }
        }
    }
    return report;
}

/// Segments p_from and p_to (0-based; the thesis's p_{from+1}, p_{to+1}) do not agree in
/// the derivative of order `order` where they meet.
template <class S> struct JoinDefect {
    int join = 0; ///< index of the join: p_from(1) meets p_to(0), to = from + 1 (or 0)
    int fromSegment = 0;
    int toSegment = 0;
    int order = 0; ///< derivative order (0 = position)
    Vec2<S> left;  ///< p_from^(order)(1)
    Vec2<S> right; ///< p_to^(order)(0)

    Vec2<S> jump() const { return right - left; }
    /// e.g. "p' jumps at the join of p_2 and p_3: p_2'(1) = (1, 2), p_3'(0) = (1, 3) (jump (0, 1))".
    std::string describe() const
    {
        using detail::scalarText;
        const std::string a = detail::derivativeName("p_" + std::to_string(fromSegment + 1), order);
        const std::string b = detail::derivativeName("p_" + std::to_string(toSegment + 1), order);
        return detail::derivativeName("p", order) + " jumps at the join of p_" + std::to_string(fromSegment + 1) + " and p_" +
               std::to_string(toSegment + 1) + ": " + a + "(1) = " + scalarText(left) + ", " + b + "(0) = " + scalarText(right) +
               " (jump " + scalarText(jump()) + ")";
    }
};

template <class S> struct JoinReport {
    int maxOrder = 1;
    double tolerance = 0;
    int joins = 0; ///< number of joins compared
    std::vector<JoinDefect<S>> defects;

    bool ok() const { return defects.empty(); }
    /// Highest k with positions and derivatives up to order k matching at every join
    /// (−1: some segments do not even meet). Capped at maxOrder.
    int continuityOrder() const
    {
        return detail::continuityOrder(defects, maxOrder, [](const JoinDefect<S>&) { return true; });
    }
    std::string describe() const
    {
        return detail::continuitySummary(continuityOrder(), maxOrder, "the segments do not join up", "the curve", " at its joins",
                                         " at all " + std::to_string(joins) + " joins") +
               "." + detail::defectLines(defects);
    }
};

/// Compares p_i^(k)(1) with p_{i+1}^(k)(0) for k = 0..maxOrder; with closedLoop also the
/// last segment's end with the first segment's start (a closed Catmull-Rom curve, Def 2.10
/// option 1 plus its closing segment). Segments are in the local s ∈ [0, 1] (Def 2.10).
template <class S>
JoinReport<S> checkSegmentJoins(const std::vector<Vec2<Polynomial<S>>>& segments, int maxOrder = 1, bool closedLoop = false,
                                double tolerance = 0)
{
    assert(maxOrder >= 0);
    JoinReport<S> report;
    report.maxOrder = maxOrder;
    report.tolerance = tolerance;
    const int count = static_cast<int>(segments.size());
    const int joins = count < 2 && !closedLoop ? 0 : (closedLoop ? count : count - 1);
    report.joins = std::max(joins, 0);
    std::vector<Vec2<Polynomial<S>>> d = segments;
    const S zero(0), one(1);
    for (int order = 0; order <= maxOrder; ++order) {
        for (int j = 0; j < report.joins; ++j) {
            const int from = j;
            const int to = (j + 1) % count;
            const auto& pf = d[static_cast<std::size_t>(from)];
            const auto& pt = d[static_cast<std::size_t>(to)];
            const Vec2<S> left(pf.x(one), pf.y(one));
            const Vec2<S> right(pt.x(zero), pt.y(zero));
            if (!detail::nearlyEqual(left, right, tolerance))
                report.defects.push_back(JoinDefect<S>{j, from, to, order, left, right});
        }
        if (order < maxOrder)
            for (auto& p : d)
                p = Vec2<Polynomial<S>>(p.x.derivative(), p.y.derivative());
    }
    return report;
}

extern template ContinuityReport<double> checkContinuity(const PiecewisePolynomial<double>&, int,
                                                         const std::vector<Vec2<double>>&, double);
extern template ContinuityReport<Rational> checkContinuity(const PiecewisePolynomial<Rational>&, int,
                                                           const std::vector<Vec2<Rational>>&, double);
extern template JoinReport<double> checkSegmentJoins(const std::vector<Vec2<Polynomial<double>>>&, int, bool, double);
extern template JoinReport<Rational> checkSegmentJoins(const std::vector<Vec2<Polynomial<Rational>>>&, int, bool, double);

} // namespace granota
