#pragma once
/// \file curvature_profile.h
/// Signed curvature κ against arc length s along a curve made of Bézier segments: the plot
/// that makes §2.3 visible — κ jumps at the knots of a Catmull-Rom curve (C¹, not G²) and
/// is continuous along the C² spline and a single Bézier curve.
///
/// Each segment is sampled at equal steps of arc length (arc_length.h, t(s)), both ends
/// included, so a knot appears twice: the end of one segment and the start of the next, at
/// the same s — the two values of κ there are its jump. κ comes from curvature.h: where the
/// tangent vanishes (a cusp) it is undefined and the sample says so (nullopt), which the plot
/// draws as a gap, never as 0.

#include "core/base/vec2.h"

#include <optional>
#include <vector>

namespace granota {

struct CurvatureSample {
    double s = 0;                ///< arc length from the start of the whole curve
    std::optional<double> kappa; ///< signed κ (y up); nullopt where undefined
};

struct CurvatureProfile {
    /// samples[i]: segment i, from its start to its end, s ascending.
    std::vector<std::vector<CurvatureSample>> samples;
    std::vector<double> knots; ///< s at the start of each segment, then the total length
    double length() const { return knots.empty() ? 0.0 : knots.back(); }
};

/// One profile for segments of any degree (each a control polygon: a cubic Bézier segment
/// has 4 points; a single Bézier curve is one segment). samplesPerSegment ≥ 2. Every value
/// is finite; an empty segment list gives an empty profile.
CurvatureProfile curvatureProfile(const std::vector<std::vector<Point>>& segments, int samplesPerSegment);

/// The same for rational Bézier segments (rational_bezier.h): weights[i] are segment i's
/// weights (each > 0; an empty list: the polynomial segment). A rational segment is sampled at
/// equal steps of its parameter t, s summed piece by piece (rationalArcLength), κ from
/// rationalCurvatureAt: the exact quarter circle gives κ = 1 along s ∈ [0, π/2].
CurvatureProfile curvatureProfile(const std::vector<std::vector<Point>>& segments,
                                  const std::vector<std::vector<double>>& weights, int samplesPerSegment);

} // namespace granota
