#pragma once
/// \file bezier_segments.h
/// Catmull-Rom segments (Lemma 2.3, Def 2.10) rewritten as cubic Bézier curves, so that
/// they can be drawn, subdivided and analysed with the tools of §2.1 (De Casteljau).
///
/// Beyond the thesis: the change from the power basis to the Bernstein basis of degree 3
/// (Farin, "Curves and Surfaces for CAGD", ch. 5 and 22). For p(s) = c_0 + c_1 s + c_2 s² + c_3 s³
///     b_0 = c_0,  b_1 = c_0 + c_1/3,  b_2 = c_0 + 2c_1/3 + c_2/3,  b_3 = c_0 + c_1 + c_2 + c_3.
/// For a uniform Catmull-Rom segment (Def 2.8: p′(0) = τ(p_2 − p_0), p′(1) = τ(p_3 − p_1)) the
/// end tangents of a cubic Bézier curve are 3(b_1 − b_0) and 3(b_3 − b_2), so this is
///     b_0 = p_1,  b_1 = p_1 + τ(p_2 − p_0)/3,  b_2 = p_2 − τ(p_3 − p_1)/3,  b_3 = p_2.
/// The conversion is exact for Rational and works for any cubic segment (every τ, every
/// mode, and the non-uniform α ≠ 0 segments in doubles).

#include "core/base/vec2.h"
#include "core/exact/polynomial.h"
#include "core/exact/rational.h"

#include <array>
#include <vector>

namespace granota {

/// The control points b_0..b_3 of one cubic Bézier segment.
template <class S> using BezierSegment = std::array<Vec2<S>, 4>;

/// One cubic Bézier segment per segment polynomial (degree ≤ 3; missing coefficients are
/// 0), in the same order, each on the same local parameter s ∈ [0, 1].
template <class S> std::vector<BezierSegment<S>> bezierSegments(const std::vector<Vec2<Polynomial<S>>>& segments)
{
    std::vector<BezierSegment<S>> out;
    out.reserve(segments.size());
    const S three(3), two(2);
    for (const auto& p : segments) {
        const Vec2<S> c0(p.x.coefficient(0), p.y.coefficient(0));
        const Vec2<S> c1(p.x.coefficient(1), p.y.coefficient(1));
        const Vec2<S> c2(p.x.coefficient(2), p.y.coefficient(2));
        const Vec2<S> c3(p.x.coefficient(3), p.y.coefficient(3));
        const auto third = [&three](const Vec2<S>& v) { return Vec2<S>(S(v.x / three), S(v.y / three)); };
        BezierSegment<S> b;
        b[0] = c0;
        b[1] = c0 + third(c1);
        b[2] = c0 + third(two * c1) + third(c2);
        b[3] = c0 + c1 + c2 + c3;
        out.push_back(b);
    }
    return out;
}

extern template std::vector<BezierSegment<double>> bezierSegments(const std::vector<Vec2<Polynomial<double>>>&);
extern template std::vector<BezierSegment<Rational>> bezierSegments(const std::vector<Vec2<Polynomial<Rational>>>&);

} // namespace granota
