#pragma once
/// \file catmull_rom.h
/// Catmull-Rom curves with tension τ (§2.2).
///
/// A segment (Def 2.8) through b = p_1 and c = p_2 with p(0) = p_1, p(1) = p_2,
/// p′(0) = τ(p_2 − p_0), p′(1) = τ(p_3 − p_1) is, in matrix form (Lemma 2.3),
///     p(t) = [1 t t² t³] M(τ) [p_0 p_1 p_2 p_3]ᵀ,
///     M(τ) = [0 1 0 0; −τ 0 τ 0; 2τ τ−3 3−2τ −τ; −τ 2−τ τ−2 τ],
/// and the columns of M(τ) are the blending functions w_j(t, τ) (Def 2.9, Cor 2.1).
/// A curve through q_0..q_n (Def 2.10) strings segments p_1..p_n together, p_i from
/// (q_{i−2}, q_{i−1}, q_i, q_{i+1}); the ends are open (repeated end points), cyclic
/// (q_{−1} = q_n, q_{n+1} = q_0) or closed (cyclic plus the segment q_n → q_0), as in the
/// Matlab `Rep_CatmullRom`. Every curve is C¹ (Prop 2.3; see continuity_check.h).
///
/// Generic code is templated on the scalar S: Rational reproduces Ex 2.11–2.13 exactly,
/// double draws. Beyond the thesis: centripetal (α = 1/2) and chordal (α = 1) knot
/// spacing, and Processing's curveTightness.

#include "core/base/expected.h"
#include "core/exact/polynomial.h"
#include "core/exact/rational.h"
#include "core/base/vec2.h"
#include "core/curves/splines/hermite_segment.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace granota {

/// How the two end segments of Def 2.10 get their missing neighbours.
enum class CatmullRomMode {
    Open,   ///< option 2: p_1′(0) = τ(q_1 − q_0), p_n′(1) = τ(q_n − q_{n−1}) (repeat the end points)
    Cyclic, ///< option 1: q_{−1} = q_n, q_{n+1} = q_0; n segments, not closed ("quasi cíclica")
    Closed, ///< option 1 plus the segment q_n → q_0 from (q_{n−1}, q_n, q_0, q_1), last
};

/// "open", "cyclic", "closed" (case-insensitive, surrounding spaces ignored); nullopt otherwise.
std::optional<CatmullRomMode> parseCatmullRomMode(std::string_view text);
/// The name parseCatmullRomMode() reads back.
std::string toString(CatmullRomMode mode);

template <class S> using Matrix4 = std::array<std::array<S, 4>, 4>;

/// M(τ) of Lemma 2.3; row r gives c_r, the coefficient of t^r.
template <class S> Matrix4<S> catmullRomMatrix(const S& tau)
{
    const S z(0), one(1), two(2), three(3);
    return {{
        {{z, one, z, z}},
        {{S(-tau), z, tau, z}},
        {{S(two * tau), S(tau - three), S(three - S(two * tau)), S(-tau)}},
        {{S(-tau), S(two - tau), S(tau - two), tau}},
    }};
}

/// The blending functions w_0..w_3 (Def 2.9, Cor 2.1): column j of M(τ) read as a
/// polynomial in t, so that p(t) = Σ w_j(t, τ) p_j.
///   w_0 = −τt + 2τt² − τt³,  w_1 = 1 + (τ−3)t² + (2−τ)t³,
///   w_2 = τt + (3−2τ)t² + (τ−2)t³,  w_3 = −τt² + τt³.
template <class S> std::array<Polynomial<S>, 4> blendingFunctions(const S& tau)
{
    const Matrix4<S> m = catmullRomMatrix(tau);
    std::array<Polynomial<S>, 4> w;
    for (std::size_t j = 0; j < 4; ++j)
        w[j] = Polynomial<S>(std::vector<S>{m[0][j], m[1][j], m[2][j], m[3][j]});
    return w;
}

/// The coefficient matrix M(τ)·[p_0 p_1 p_2 p_3]ᵀ of Lemma 2.3: c_0..c_3 with
/// p(t) = c_0 + c_1 t + c_2 t² + c_3 t³ (the middle matrices printed in Ex 2.11 and Ex 2.13).
template <class S>
std::array<Vec2<S>, 4> catmullRomCoefficients(const Vec2<S>& p0, const Vec2<S>& p1, const Vec2<S>& p2, const Vec2<S>& p3,
                                              const S& tau)
{
    const Matrix4<S> m = catmullRomMatrix(tau);
    const std::array<const Vec2<S>*, 4> p{&p0, &p1, &p2, &p3};
    std::array<Vec2<S>, 4> c;
    for (std::size_t r = 0; r < 4; ++r) {
        Vec2<S> sum(S(0), S(0));
        for (std::size_t j = 0; j < 4; ++j)
            sum += m[r][j] * *p[j];
        c[r] = sum;
    }
    return c;
}

/// Lemma 2.3: the segment through p_1 (s = 0) and p_2 (s = 1), coefficients in powers of
/// the local parameter s ∈ [0, 1].
template <class S>
Vec2<Polynomial<S>> catmullRomSegment(const Vec2<S>& p0, const Vec2<S>& p1, const Vec2<S>& p2, const Vec2<S>& p3, const S& tau)
{
    const std::array<Vec2<S>, 4> c = catmullRomCoefficients(p0, p1, p2, p3, tau);
    return Vec2<Polynomial<S>>(Polynomial<S>(std::vector<S>{c[0].x, c[1].x, c[2].x, c[3].x}),
                               Polynomial<S>(std::vector<S>{c[0].y, c[1].y, c[2].y, c[3].y}));
}

/// Def 2.10: for `count` = n + 1 points q_0..q_n, the indices of the four points feeding
/// each segment, in curve order. Open: (0,0,1,2), (i−2,i−1,i,i+1), …, (n−2,n−1,n,n), with
/// (0,0,1,1) for exactly two points. Cyclic: indices mod n + 1, n segments. Closed: cyclic
/// plus (n−1, n, 0, 1) last. Errors: TooFewPoints (open needs 2, cyclic and closed 3).
Expected<std::vector<std::array<int, 4>>> catmullRomQuadruples(std::size_t count, CatmullRomMode mode);

namespace detail {
Error catmullRomNonFinitePoint(std::size_t index);
Error catmullRomNonFiniteTension();
Error catmullRomOverflow();
} // namespace detail

/// The uniform curve of Def 2.10 (segment i in its local s ∈ [0, 1], interpolating q_i and
/// q_{i+1}, indices mod n + 1 for the closing segment). Errors: TooFewPoints; for floating
/// point also InvalidInput (a point or τ not finite) and OutOfRange (overflow).
template <class S>
Expected<std::vector<Vec2<Polynomial<S>>>> catmullRomSegments(const std::vector<Vec2<S>>& q, const S& tau, CatmullRomMode mode)
{
    constexpr bool floating = std::is_floating_point_v<S>;
    if constexpr (floating) {
        for (std::size_t i = 0; i < q.size(); ++i)
            if (!std::isfinite(q[i].x) || !std::isfinite(q[i].y))
                return detail::catmullRomNonFinitePoint(i);
        if (!std::isfinite(tau))
            return detail::catmullRomNonFiniteTension();
    }
    auto quads = catmullRomQuadruples(q.size(), mode);
    if (!quads)
        return quads.error();
    std::vector<Vec2<Polynomial<S>>> segments;
    segments.reserve(quads->size());
    for (const auto& k : *quads) {
        const auto at = [&q](int i) -> const Vec2<S>& { return q[static_cast<std::size_t>(i)]; };
        segments.push_back(catmullRomSegment(at(k[0]), at(k[1]), at(k[2]), at(k[3]), tau));
    }
    if constexpr (floating) {
        for (const auto& s : segments)
            for (const auto* p : {&s.x, &s.y})
                for (const S& c : p->coefficients())
                    if (!std::isfinite(c))
                        return detail::catmullRomOverflow();
    }
    return segments;
}

/// The same uniform curve as cubic Hermite segments (hermite_segment.h): segment i from
/// q_i to q_{i+1} with Def 2.8's tangents m0 = τ(p_2 − p_0), m1 = τ(p_3 − p_1) of its four
/// points (catmullRomQuadruples()). hermitePolynomial() of each is, exactly for Rational,
/// the segment catmullRomSegments() returns; that one is computed as Lemma 2.3's matrix
/// product M(τ)·[p_0 p_1 p_2 p_3]ᵀ (the thesis's form, and bit for bit the figures' doubles),
/// so in doubles the two agree only to rounding. Errors as catmullRomSegments().
template <class S>
Expected<std::vector<HermiteSegment<S>>> catmullRomHermiteSegments(const std::vector<Vec2<S>>& q, const S& tau,
                                                                   CatmullRomMode mode)
{
    if constexpr (std::is_floating_point_v<S>) {
        for (std::size_t i = 0; i < q.size(); ++i)
            if (!std::isfinite(q[i].x) || !std::isfinite(q[i].y))
                return detail::catmullRomNonFinitePoint(i);
        if (!std::isfinite(tau))
            return detail::catmullRomNonFiniteTension();
    }
    auto quads = catmullRomQuadruples(q.size(), mode);
    if (!quads)
        return quads.error();
    std::vector<HermiteSegment<S>> segments;
    segments.reserve(quads->size());
    for (const auto& k : *quads) {
        const auto at = [&q](int i) -> const Vec2<S>& { return q[static_cast<std::size_t>(i)]; };
        segments.push_back({at(k[1]), at(k[2]), tau * (at(k[2]) - at(k[0])), tau * (at(k[3]) - at(k[1]))});
    }
    if constexpr (std::is_floating_point_v<S>) {
        for (const auto& g : segments)
            for (const Vec2<S>* v : {&g.m0, &g.m1})
                if (!std::isfinite(v->x) || !std::isfinite(v->y))
                    return detail::catmullRomOverflow();
    }
    return segments;
}

extern template Expected<std::vector<Vec2<Polynomial<double>>>> catmullRomSegments(const std::vector<Vec2<double>>&,
                                                                                   const double&, CatmullRomMode);
extern template Expected<std::vector<Vec2<Polynomial<Rational>>>> catmullRomSegments(const std::vector<Vec2<Rational>>&,
                                                                                     const Rational&, CatmullRomMode);

/// Beyond the thesis: non-uniform knot spacing h_i = |q_{i+1} − q_i|^α — α = 0 uniform
/// (exactly the generic function above), α = 1/2 centripetal (no cusps or self-
/// intersections within a segment), α = 1 chordal. The tangent at an interior knot in the
/// global parameter is the weighted mean of the neighbouring difference quotients
///     m_i = ((q_i − q_{i−1})/h_{i−1} · h_i + (q_{i+1} − q_i)/h_i · h_{i−1}) / (h_{i−1} + h_i)
/// (a quotient with zero spacing counts as 0; a zero denominator gives m_i = 0), and
/// segment i is the cubic Hermite piece from q_i to q_{i+1} in its local s ∈ [0, 1] with
/// T_0 = 2τ m_i h_i, T_1 = 2τ m_{i+1} h_i — for α = 0 that is τ(q_{i+1} − q_{i−1}), the
/// thesis's tangent (Def 2.8). Open ends keep Def 2.10 option 2: local end tangents
/// τ(q_1 − q_0) and τ(q_n − q_{n−1}). Cyclic and closed wrap around. Coincident points give
/// finite (constant) segments. Segments join with parallel tangents (G¹), not equal ones.
/// Errors: as above, and OutOfRange when α is not a number in [0, 1].
Expected<std::vector<Vec2<Polynomial<double>>>> catmullRomSegments(const std::vector<Point>& q, double tau, CatmullRomMode mode,
                                                                   double alpha);

/// The curve above as cubic Hermite segments: catmullRomSegments(q, τ, mode, α) is
/// hermitePolynomial() of each, bit for bit (α = 0: the uniform catmullRomHermiteSegments()).
Expected<std::vector<HermiteSegment<double>>> catmullRomHermiteSegments(const std::vector<Point>& q, double tau,
                                                                        CatmullRomMode mode, double alpha);

/// The knot spacing of the curve above, one h_i per segment in the order of its segments:
/// segment i covers an interval of length h_i of the curve's global parameter u, so that
/// s = (u − u_i)/h_i; the segments join with equal derivatives in u (C¹), which the local
/// tangents, parallel but of unequal length (G¹), hide (knot_continuity.h takes these h_i).
/// h_i = |q_{i+1} − q_i|^α (the closing segment of a closed curve: |q_0 − q_n|^α), all 1 for
/// α = 0 (the thesis's uniform spacing), and 0 where q_{i+1} = q_i (that segment is a single
/// point, whatever its length in u). Empty where catmullRomSegments() refuses the points
/// (too few for the mode, α outside [0, 1], a point not finite).
std::vector<double> catmullRomIntervals(const std::vector<Point>& q, CatmullRomMode mode, double alpha);

/// `samplesPerSegment` points of each segment at s = j/(samplesPerSegment − 1), both ends
/// included (so a join appears twice: at the end of one segment and the start of the
/// next), segments in order. samplesPerSegment ≥ 2. The Matlab `SegmentCatmullRom` with
/// part = samplesPerSegment − 1.
std::vector<Point> sampleSegments(const std::vector<Vec2<Polynomial<double>>>& segments, int samplesPerSegment);

/// Processing's curveTightness(s) as a tension: its basis matrix is M(τ) with τ = (1 − s)/2,
/// so s = 0 (Processing's default) is τ = 1/2 and s = 1 is τ = 0.
constexpr double curveTightnessToTau(double s) { return (1.0 - s) / 2.0; }
/// The inverse: s = 1 − 2τ.
constexpr double tauToCurveTightness(double tau) { return 1.0 - 2.0 * tau; }

} // namespace granota
