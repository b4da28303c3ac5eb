#pragma once
/// \file segment_joins.h
/// The values on both sides of every join of a curve made of segments p_1, p_2, … on
/// s ∈ [0, 1] (Def 2.10): p_i^(k)(1) and p_{i+1}^(k)(0). checkSegmentJoins (continuity_check.h)
/// says whether a curve is C^k; this gives the numbers behind the verdict, join by join, so
/// that the Catmull-Rom tab can show Prop 2.3 (c_i′(1) = c_{i+1}′(0)) knot by knot with the
/// tangents themselves.
///
/// Beyond the thesis: with centripetal or chordal spacing the segments, each in its own
/// local s, join with *parallel* tangents (G¹) rather than equal ones: `parallel` reports it.

#include "core/exact/polynomial.h"
#include "core/exact/rational.h"
#include "core/base/vec2.h"

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace granota {

/// One join: the end of segment `fromSegment` meets the start of `toSegment`.
template <class S> struct JoinValues {
    int fromSegment = 0; ///< 0-based (the thesis's p_{fromSegment+1})
    int toSegment = 0;
    Vec2<S> left;          ///< p_from^(order)(1)
    Vec2<S> right;         ///< p_to^(order)(0)
    bool equal = false;    ///< left = right (exactly, or within the tolerance for doubles)
    bool parallel = false; ///< same direction (both non-zero and positively parallel, or both zero)
};

namespace detail {
inline bool joinScalarEqual(const Rational& a, const Rational& b, double) { return a == b; }
inline bool joinScalarEqual(double a, double b, double tolerance)
{
    if (a == b)
        return true;
    const double scale = std::fmax(1.0, std::fmax(std::fabs(a), std::fabs(b)));
    return std::fabs(a - b) <= tolerance * scale; // false for NaN
}
} // namespace detail

/// Values of the derivative of order `order` (0 = position, 1 = tangent) at every join, in
/// curve order; with `closedLoop` also the last segment's end against the first one's start
/// (a closed Catmull-Rom curve). Exact for Rational; for doubles `tolerance` is relative to
/// max(1, |a|, |b|) as in continuity_check.h.
template <class S>
std::vector<JoinValues<S>> segmentJoinValues(const std::vector<Vec2<Polynomial<S>>>& segments, int order, bool closedLoop = false,
                                             double tolerance = 0)
{
    std::vector<JoinValues<S>> out;
    const int count = static_cast<int>(segments.size());
    if (count == 0)
        return out;
    const int joins = closedLoop ? count : count - 1;
    std::vector<Vec2<Polynomial<S>>> d = segments;
    for (int k = 0; k < order; ++k)
        for (auto& p : d)
            p = Vec2<Polynomial<S>>(p.x.derivative(), p.y.derivative());
    const S zero(0), one(1);
    for (int j = 0; j < joins; ++j) {
        const int to = (j + 1) % count;
        const auto& pf = d[static_cast<std::size_t>(j)];
        const auto& pt = d[static_cast<std::size_t>(to)];
        JoinValues<S> v;
        v.fromSegment = j;
        v.toSegment = to;
        v.left = Vec2<S>(pf.x(one), pf.y(one));
        v.right = Vec2<S>(pt.x(zero), pt.y(zero));
        v.equal = detail::joinScalarEqual(v.left.x, v.right.x, tolerance) &&
                  detail::joinScalarEqual(v.left.y, v.right.y, tolerance);
        // Parallel and pointing the same way: cross product 0 and dot product > 0.
        const S cross = S(v.left.x * v.right.y - v.left.y * v.right.x);
        const S dotp = S(v.left.x * v.right.x + v.left.y * v.right.y);
        const S normL = S(v.left.x * v.left.x + v.left.y * v.left.y);
        const S normR = S(v.right.x * v.right.x + v.right.y * v.right.y);
        const bool bothZero = normL == zero && normR == zero;
        if constexpr (std::is_floating_point_v<S>) {
            const double scale = std::sqrt(static_cast<double>(normL) * static_cast<double>(normR));
            v.parallel = v.equal || bothZero || (scale > 0 && std::fabs(cross) <= tolerance * scale && dotp > 0);
        } else {
            v.parallel = v.equal || bothZero || (cross == zero && dotp > zero);
        }
        out.push_back(std::move(v));
    }
    return out;
}

extern template std::vector<JoinValues<double>> segmentJoinValues(const std::vector<Vec2<Polynomial<double>>>&, int, bool,
                                                                  double);
extern template std::vector<JoinValues<Rational>> segmentJoinValues(const std::vector<Vec2<Polynomial<Rational>>>&, int, bool,
                                                                    double);

} // namespace granota
