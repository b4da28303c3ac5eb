#pragma once
/// \file hermite_segment.h
/// The cubic Hermite segment: the common form of every spline family in Granota.
///
/// Def 2.8 builds a Catmull-Rom segment from two points and two tangents: p(0) = p_1,
/// p(1) = p_2, p′(0) = τ(p_2 − p_0), p′(1) = τ(p_3 − p_1). Only the tangents' rule is
/// Catmull-Rom's; the cubic through two points with two given end derivatives is the cubic
/// Hermite segment, and cardinal, Kochanek–Bartels and the C² spline differ from Catmull-Rom
/// only in how they choose the tangents. On the local parameter s ∈ [0, 1]
///     p(s) = h_00(s) p_0 + h_10(s) m_0 + h_01(s) p_1 + h_11(s) m_1,
///     h_00 = 1 − 3s² + 2s³,  h_10 = s − 2s² + s³,  h_01 = 3s² − 2s³,  h_11 = −s² + s³,
/// so in powers of s (the coefficients the thesis prints, Ex 2.11–2.13)
///     c_0 = p_0,  c_1 = m_0,  c_2 = 3(p_1 − p_0) − 2m_0 − m_1,  c_3 = 2(p_0 − p_1) + m_0 + m_1,
/// and as a cubic Bézier curve (Def 2.5: the end tangents of a cubic Bézier curve are
/// 3(b_1 − b_0) and 3(b_3 − b_2))
///     b_0 = p_0,  b_1 = p_0 + m_0/3,  b_2 = p_1 − m_1/3,  b_3 = p_1.
/// Everything is templated on the scalar S: Rational is exact, double draws.

#include "core/base/vec2.h"
#include "core/exact/polynomial.h"

#include <array>
#include <vector>

namespace granota {

/// p(0) = p0, p(1) = p1, p′(0) = m0, p′(1) = m1 on the local s ∈ [0, 1].
template <class S> struct HermiteSegment {
    Vec2<S> p0; ///< the start point, p(0)
    Vec2<S> p1; ///< the end point, p(1)
    Vec2<S> m0; ///< the start tangent, p′(0) (in the local s)
    Vec2<S> m1; ///< the end tangent, p′(1) (in the local s)

    friend bool operator==(const HermiteSegment& a, const HermiteSegment& b)
    {
        return a.p0 == b.p0 && a.p1 == b.p1 && a.m0 == b.m0 && a.m1 == b.m1;
    }
    friend bool operator!=(const HermiteSegment& a, const HermiteSegment& b) { return !(a == b); }
};

/// c_0..c_3 with p(s) = c_0 + c_1 s + c_2 s² + c_3 s³ (formulas in the file comment; the
/// operations in this order are those of the non-uniform Catmull-Rom curve, bit for bit).
template <class S> std::array<Vec2<S>, 4> hermiteCoefficients(const HermiteSegment<S>& seg)
{
    const S two(2), three(3);
    return {seg.p0, seg.m0, three * (seg.p1 - seg.p0) - two * seg.m0 - seg.m1, two * (seg.p0 - seg.p1) + seg.m0 + seg.m1};
}

/// The inverse of hermiteCoefficients(): any cubic c_0 + c_1 s + c_2 s² + c_3 s³ is the Hermite
/// segment with p0 = c_0, p1 = c_0 + c_1 + c_2 + c_3, m0 = c_1, m1 = c_1 + 2c_2 + 3c_3.
template <class S> HermiteSegment<S> hermiteFromCoefficients(const std::array<Vec2<S>, 4>& c)
{
    const S two(2), three(3);
    return {c[0], c[0] + c[1] + c[2] + c[3], c[1], c[1] + two * c[2] + three * c[3]};
}

/// The segment as two polynomials in s (the form catmullRomSegments() returns and
/// bezierSegments(), knot_continuity.h and the CLI read).
template <class S> Vec2<Polynomial<S>> hermitePolynomial(const HermiteSegment<S>& seg)
{
    const std::array<Vec2<S>, 4> c = hermiteCoefficients(seg);
    return Vec2<Polynomial<S>>(Polynomial<S>(std::vector<S>{c[0].x, c[1].x, c[2].x, c[3].x}),
                               Polynomial<S>(std::vector<S>{c[0].y, c[1].y, c[2].y, c[3].y}));
}

/// The Hermite segment of a cubic (or lower-degree) segment polynomial.
template <class S> HermiteSegment<S> hermiteFromPolynomial(const Vec2<Polynomial<S>>& p)
{
    std::array<Vec2<S>, 4> c;
    for (int k = 0; k < 4; ++k)
        c[static_cast<std::size_t>(k)] = Vec2<S>(p.x.coefficient(k), p.y.coefficient(k));
    return hermiteFromCoefficients(c);
}

/// p(s), by Horner's rule on the power form.
template <class S> Vec2<S> hermitePoint(const HermiteSegment<S>& seg, const S& s)
{
    const std::array<Vec2<S>, 4> c = hermiteCoefficients(seg);
    return c[0] + s * (c[1] + s * (c[2] + s * c[3]));
}

/// p′(s) = c_1 + 2c_2 s + 3c_3 s² (in the local s: divide by the segment's length in a global
/// parameter to get the derivative there).
template <class S> Vec2<S> hermiteDerivative(const HermiteSegment<S>& seg, const S& s)
{
    const std::array<Vec2<S>, 4> c = hermiteCoefficients(seg);
    const S two(2), three(3);
    return c[1] + s * (two * c[2] + s * (three * c[3]));
}

/// p″(s) = 2c_2 + 6c_3 s.
template <class S> Vec2<S> hermiteSecondDerivative(const HermiteSegment<S>& seg, const S& s)
{
    const std::array<Vec2<S>, 4> c = hermiteCoefficients(seg);
    const S two(2), six(6);
    return two * c[2] + s * (six * c[3]);
}

/// The control points b_0..b_3 of the same cubic as a Bézier curve (Def 2.5):
/// (p0, p0 + m0/3, p1 − m1/3, p1).
template <class S> std::array<Vec2<S>, 4> hermiteToBezier(const HermiteSegment<S>& seg)
{
    const S three(3);
    const auto third = [&three](const Vec2<S>& v) { return Vec2<S>(S(v.x / three), S(v.y / three)); };
    return {seg.p0, seg.p0 + third(seg.m0), seg.p1 - third(seg.m1), seg.p1};
}

/// The inverse of hermiteToBezier(): p0 = b_0, p1 = b_3, m0 = 3(b_1 − b_0), m1 = 3(b_3 − b_2).
template <class S> HermiteSegment<S> hermiteFromBezier(const std::array<Vec2<S>, 4>& b)
{
    const S three(3);
    return {b[0], b[3], three * (b[1] - b[0]), three * (b[3] - b[2])};
}

/// hermiteToBezier() of each segment, in order.
template <class S> std::vector<std::array<Vec2<S>, 4>> hermiteToBezier(const std::vector<HermiteSegment<S>>& segments)
{
    std::vector<std::array<Vec2<S>, 4>> out;
    out.reserve(segments.size());
    for (const auto& seg : segments)
        out.push_back(hermiteToBezier(seg));
    return out;
}

/// hermitePolynomial() of each segment, in order.
template <class S> std::vector<Vec2<Polynomial<S>>> hermitePolynomials(const std::vector<HermiteSegment<S>>& segments)
{
    std::vector<Vec2<Polynomial<S>>> out;
    out.reserve(segments.size());
    for (const auto& seg : segments)
        out.push_back(hermitePolynomial(seg));
    return out;
}

} // namespace granota
