#pragma once
/// \file cardinal_spline.h
/// Cardinal splines: the Catmull-Rom curve of Def 2.10 with its tension written the way
/// graphics texts write it (Foley et al.; d3-shape's `curveCardinal.tension(c)`): the tangent
/// at q_i is (1 − c)(q_{i+1} − q_{i−1})/2, so c is the thesis's τ through τ = (1 − c)/2 — c = 0
/// is Catmull-Rom's τ = 1/2, c = 1 zero tangents (straight segments meeting in corners). Also
/// Kochanek–Bartels with tension T = c and no continuity or bias (kochanek_bartels.h).
/// The segments are the Catmull-Rom Hermite segments of that τ (catmull_rom.h).

#include "core/base/expected.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/hermite_segment.h"

#include <vector>

namespace granota {

/// τ = (1 − c)/2: the thesis's tension of the cardinal tension c.
template <class S> S cardinalTau(const S& c) { return S((S(1) - c) / S(2)); }
/// c = 1 − 2τ: the inverse (Processing's curveTightness is this same c).
template <class S> S tauToCardinal(const S& tau) { return S(S(1) - S(2) * tau); }

/// The cardinal spline through q with tension c, uniform parameters (Def 2.10's modes).
template <class S>
Expected<std::vector<HermiteSegment<S>>> cardinalHermiteSegments(const std::vector<Vec2<S>>& q, const S& c, CatmullRomMode mode)
{
    return catmullRomHermiteSegments(q, cardinalTau(c), mode);
}

/// The same with knot spacing |q_{i+1} − q_i|^α (catmullRomHermiteSegments() with α).
inline Expected<std::vector<HermiteSegment<double>>> cardinalHermiteSegments(const std::vector<Point>& q, double c,
                                                                             CatmullRomMode mode, double alpha)
{
    return catmullRomHermiteSegments(q, cardinalTau(c), mode, alpha);
}

} // namespace granota
