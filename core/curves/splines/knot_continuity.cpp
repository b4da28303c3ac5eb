#include "core/curves/splines/knot_continuity.h"

#include "core/curves/splines/continuity_check.h"

#include <cassert>
#include <cmath>
#include <array>
#include <cstddef>
#include <type_traits>

namespace granota {

namespace {

template <class S> Vec2<S> valueAt(const Vec2<Polynomial<S>>& p, const S& s) { return Vec2<S>(p.x(s), p.y(s)); }
template <class S> Vec2<Polynomial<S>> derivativeOf(const Vec2<Polynomial<S>>& p)
{
    return Vec2<Polynomial<S>>(p.x.derivative(), p.y.derivative());
}
template <class S> Vec2<S> divided(const Vec2<S>& v, const S& d) { return Vec2<S>(S(v.x / d), S(v.y / d)); }
template <class S> S crossOf(const Vec2<S>& a, const Vec2<S>& b) { return S(a.x * b.y - a.y * b.x); }
template <class S> S dotOf(const Vec2<S>& a, const Vec2<S>& b) { return S(a.x * b.x + a.y * b.y); }
Point toPoint(const Vec2<double>& v) { return v; }
Point toPoint(const Vec2<Rational>& v) { return Point(toDouble(v.x), toDouble(v.y)); }

/// Σ|coefficients| of p′: an upper bound of |p′(s)| on [0, 1], the scale a vanishing tangent
/// is judged against in doubles.
template <class S> double tangentScale(const Vec2<Polynomial<S>>& d1)
{
    double sum = 0;
    for (int k = 0; k <= std::max(d1.x.degree(), d1.y.degree()); ++k)
        sum += std::fabs(toDouble(d1.x.coefficient(k))) + std::fabs(toDouble(d1.y.coefficient(k)));
    return sum;
}

/// The tangent v vanishes: exactly for Rational; below 1e-12 of the segment's tangent scale
/// for doubles (in the segment's local parameter, so h does not enter).
template <class S> bool vanishes(const Vec2<S>& localTangent, double scale)
{
    if constexpr (std::is_floating_point_v<S>)
        return !(std::hypot(localTangent.x, localTangent.y) > 1e-12 * scale);
    else {
        (void)scale;
        return localTangent.x == S(0) && localTangent.y == S(0);
    }
}

/// κ = (v × a)/|v|³ in doubles, without overflowing |v|³.
std::optional<double> signedCurvature(const Point& v, const Point& a)
{
    const double speed = std::hypot(v.x, v.y);
    if (!(speed > 0))
        return std::nullopt;
    const double k = cross(v, a) / speed / speed / speed;
    if (!std::isfinite(k))
        return std::nullopt;
    return k;
}

} // namespace

template <class S>
std::vector<KnotContinuity<S>> knotContinuity(const std::vector<Vec2<Polynomial<S>>>& segments, const std::vector<S>& intervals,
                                              bool closedLoop, double tolerance)
{
    assert(intervals.empty() || intervals.size() == segments.size());
    std::vector<KnotContinuity<S>> out;
    const int count = static_cast<int>(segments.size());
    const int knots = closedLoop ? count : count - 1;
    if (knots <= 0)
        return out;
    // Derivatives of order 0..2 in the local s.
    std::vector<std::array<Vec2<Polynomial<S>>, 3>> d(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        d[i][0] = segments[i];
        d[i][1] = derivativeOf(d[i][0]);
        d[i][2] = derivativeOf(d[i][1]);
    }
    const S zero(0), one(1);
    auto h = [&](int i) { return intervals.empty() ? one : intervals[static_cast<std::size_t>(i)]; };
    out.reserve(static_cast<std::size_t>(knots));
    for (int j = 0; j < knots; ++j) {
        const int to = (j + 1) % count;
        KnotContinuity<S> k;
        k.fromSegment = j;
        k.toSegment = to;
        // Local values: v = p′, a = p″ in s; the global ones divide by h and h² (Def 2.10's
        // segments each on s ∈ [0, 1]; the curve's parameter advances by h_i on segment i).
        Vec2<S> localL[3], localR[3];
        for (int o = 0; o < 3; ++o) {
            localL[o] = valueAt(d[static_cast<std::size_t>(j)][o], one);
            localR[o] = valueAt(d[static_cast<std::size_t>(to)][o], zero);
        }
        const S hl = h(j), hr = h(to);
        k.left[0] = localL[0];
        k.right[0] = localR[0];
        k.left[1] = divided(localL[1], hl);
        k.right[1] = divided(localR[1], hr);
        k.left[2] = divided(localL[2], S(hl * hl));
        k.right[2] = divided(localR[2], S(hr * hr));
        for (int o = 0; o < 3; ++o)
            k.equal[o] = detail::nearlyEqual(k.left[o], k.right[o], tolerance);

        // Geometry does not depend on h: use the local derivatives.
        const bool zeroL = vanishes(localL[1], tangentScale(d[static_cast<std::size_t>(j)][1]));
        const bool zeroR = vanishes(localR[1], tangentScale(d[static_cast<std::size_t>(to)][1]));
        const Point vL = toPoint(localL[1]), vR = toPoint(localR[1]);
        const Point aL = toPoint(localL[2]), aR = toPoint(localR[2]);
        if (!zeroL)
            k.curvatureLeft = signedCurvature(vL, aL);
        if (!zeroR)
            k.curvatureRight = signedCurvature(vR, aR);
        if (!zeroL && !zeroR) {
            k.tangentTurn = std::atan2(cross(vL, vR), dot(vL, vR));
            const S c = crossOf(localL[1], localR[1]);
            const S dp = dotOf(localL[1], localR[1]);
            if constexpr (std::is_floating_point_v<S>) {
                const double scale = std::hypot(vL.x, vL.y) * std::hypot(vR.x, vR.y);
                k.g1 = k.equal[0] && dp > 0 && std::fabs(c) <= tolerance * scale;
            } else {
                k.g1 = k.equal[0] && c == zero && dp > zero;
            }
            if (k.g1) {
                k.tangentTurn = 0.0;
                const S cl = crossOf(localL[1], localL[2]);
                const S cr = crossOf(localR[1], localR[2]);
                if constexpr (std::is_floating_point_v<S>) {
                    // κ is known to about `tolerance` of |a|/|v|², the largest it could be.
                    const double floor = tolerance *
                                         (std::hypot(aL.x, aL.y) / dot(vL, vL) + std::hypot(aR.x, aR.y) / dot(vR, vR));
                    k.g2 = k.curvatureLeft && k.curvatureRight && std::fabs(*k.curvatureLeft - *k.curvatureRight) <= floor;
                } else {
                    // sign(c_L) = sign(c_R) and c_L²|v_R|⁶ = c_R²|v_L|⁶: κ_L = κ_R without roots.
                    const S nl = dotOf(localL[1], localL[1]), nr = dotOf(localR[1], localR[1]);
                    const bool sameSign = (cl > zero) == (cr > zero) && (cl < zero) == (cr < zero);
                    k.g2 = sameSign && S(cl * cl * nr * nr * nr) == S(cr * cr * nl * nl * nl);
                }
            }
        }
        out.push_back(std::move(k));
    }
    return out;
}

template std::vector<KnotContinuity<double>> knotContinuity(const std::vector<Vec2<Polynomial<double>>>&,
                                                            const std::vector<double>&, bool, double);
template std::vector<KnotContinuity<Rational>> knotContinuity(const std::vector<Vec2<Polynomial<Rational>>>&,
                                                              const std::vector<Rational>&, bool, double);

} // namespace granota
