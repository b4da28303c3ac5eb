#pragma once
/// \file decasteljau_scene.h
/// Everything the De Casteljau tab draws, computed from the control points, t and the view
/// (decasteljau_view.h) in one place and without widgets: the sampled curve, the curves of the
/// first 1…n + 1 points (Matlab `desglossar`), De Casteljau's triangle at t (Def 2.4), the
/// curvature at t, and the overlays shown (features, comb, arc length, hodograph). The canvas's
/// layers, the key, the CSV and the TikZ export all read one DeCasteljauScene.

#include "core/base/vec2.h"
#include "core/curves/bezier/arc_length.h"
#include "core/curves/bezier/curvature.h"
#include "core/curves/bezier/curve_features.h"
#include "core/curves/bezier/de_casteljau.h"
#include "ui/common/curvature_comb.h"
#include "ui/decasteljau/decasteljau_view.h"

#include <optional>
#include <vector>

namespace granota::ui {

struct DeCasteljauScene {
    std::vector<Point> points; ///< P_0…P_n
    /// The same points exactly, as the point editor keeps them (exact_point.h), or nullopt when
    /// one has no exact form: the exact panel's triangle, c(t) in powers of t and κ read these.
    std::optional<std::vector<RPoint>> exactPoints;
    double t = 0.5;
    DeCasteljauView view;

    // In the order computeScene() fills them.
    std::vector<Point> curve;                   ///< view.samples + 1 points of c
    std::vector<std::vector<Point>> stepCurves; ///< while view.stepByStep
    DeCasteljauTable<double> levels;            ///< every level P_i^r(t)
    bool finite = false;                        ///< every control point is finite: the overlays exist
    CurveFeatures features;                     ///< while the box or the inflections are shown
    CurvatureComb comb;                         ///< while the comb is shown
    std::vector<Point> hodoCurve;               ///< the hodograph sampled, while it is shown
    std::optional<ArcLengthParametrization> arc;
    CurvatureAt curvature;               ///< κ, the normal and the osculating circle at t
    DeCasteljauTable<double> hodoLevels; ///< the hodograph's construction at t, while it is shown
};

/// The scene of `points` (and of `exactPoints`, PointEditor::allExactPoints) at `t` seen
/// through `view` (empty points: an empty scene).
DeCasteljauScene computeScene(const std::vector<Point>& points, const std::optional<std::vector<RPoint>>& exactPoints, double t,
                              const DeCasteljauView& view);

/// Moves a computed scene to another t: only what depends on t (the levels, the curvature and
/// the hodograph's construction) is computed again. The same as computeScene(points, exact, t, view).
void moveSceneTo(DeCasteljauScene& scene, double t);


} // namespace granota::ui
