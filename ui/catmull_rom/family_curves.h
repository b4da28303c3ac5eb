#pragma once
/// \file family_curves.h
/// The curve of the family chosen in the Catmull-Rom tab (curve_family.h) when it is not
/// Catmull-Rom (whose curves, one per τ, are CatmullRomScene::curves): computed by the core
/// from the points and the settings, as Hermite segments (hermite_segment.h) with the tangents
/// at each point, as cubic Bézier segments (drawn and exported) and samples. No mathematics
/// here: only calls to core/curves/splines and the translation of their errors.

#include "core/base/vec2.h"
#include "core/curves/splines/bezier_segments.h"
#include "core/curves/splines/curvature_profile.h"
#include "core/curves/splines/hermite_segment.h"
#include "core/curves/splines/kochanek_bartels.h"
#include "core/exact/polynomial.h"
#include "ui/catmull_rom/catmull_rom_settings.h"

#include <QString>

#include <vector>

namespace granota::ui {

/// One curve of a family other than Catmull-Rom.
struct FamilyCurve {
    CurveFamily family = CurveFamily::CatmullRom;   ///< CatmullRom: no family curve (the τ curves are drawn)
    std::vector<HermiteSegment<double>> hermite;    ///< Def 2.8's form of every segment (empty for the solved families)
    std::vector<Vec2<Polynomial<double>>> segments; ///< the same in powers of the local s
    std::vector<double> intervals;                  ///< h_i per segment (1 uniform)
    /// The tangents at each point in the local s, in and out (equal where the curve is C¹ in
    /// s); empty for the families without point tangents.
    std::vector<KbTangents<double>> tangents;
    std::vector<Point> points;                 ///< where the tangents sit (the tab's points when computed)
    std::vector<BezierSegment<double>> bezier; ///< the segments as cubic Bézier curves (drawn, exported)
    std::vector<Point> samples;                ///< for the key's placement and the view's box
    CurvatureProfile curvature;                ///< κ(s), when the plot shows it
    QString error;                             ///< translated; empty when the curve exists
};

/// Segment mode (Def 2.8) keeps the open curve's interior segments only.
template <class T> std::vector<T> familyShownSegments(std::vector<T> all, CatmullRomEnds ends)
{
    if (ends != CatmullRomEnds::Segment)
        return all;
    if (all.size() < 2)
        return {};
    return std::vector<T>(all.begin() + 1, all.end() - 1);
}

/// The tangents at each point of segments that run from point (first + k) mod n to the next:
/// out = p′(0) of the segment leaving the point, in = p′(1) of the one arriving; a point with
/// one of the two takes it for both (an open curve's ends), with neither both are 0.
template <class S>
std::vector<KbTangents<S>> familyTangentsOf(const std::vector<HermiteSegment<S>>& segments, std::size_t n, int first)
{
    std::vector<KbTangents<S>> t(n);
    std::vector<bool> hasIn(n, false), hasOut(n, false);
    for (std::size_t k = 0; k < segments.size() && n > 0; ++k) {
        const std::size_t a = (static_cast<std::size_t>(first) + k) % n, b = (a + 1) % n;
        t[a].out = segments[k].m0;
        hasOut[a] = true;
        t[b].in = segments[k].m1;
        hasIn[b] = true;
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (hasOut[i] && !hasIn[i])
            t[i].in = t[i].out;
        if (hasIn[i] && !hasOut[i])
            t[i].out = t[i].in;
    }
    return t;
}

/// The Catmull-Rom tangent at each point for the selected τ, ends and spacing (p′(0) of the
/// segment leaving it, p′(1) at an open curve's last point): where the Hermite family starts.
std::vector<Point> catmullRomTangents(const std::vector<Point>& points, const CatmullRomSettings& settings);

/// The Hermite family's tangent at each point: settings.hermiteTangents, cut to the points or
/// completed by catmullRomTangents() for points added since.
std::vector<Point> hermiteTangentsOf(const std::vector<Point>& points, const CatmullRomSettings& settings);

/// The family's curve through `points` with `settings` (an empty FamilyCurve for Catmull-Rom).
FamilyCurve computeFamilyCurve(const std::vector<Point>& points, const CatmullRomSettings& settings);

} // namespace granota::ui
