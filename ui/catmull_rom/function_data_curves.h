#pragma once
/// \file function_data_curves.h
/// What the Catmull-Rom tab draws in its "function data" family: the points read as data
/// y(x), x strictly increasing, and four curves through them — the natural spline of
/// Def 2.3 (cubic_spline.h), Catmull-Rom with τ = 1/2 (Def 2.10, open, uniform: the tab's
/// curve), Fritsch–Carlson and Steffen (monotone_spline.h). Each curve is one parametric
/// segment per data interval [x_i, x_{i+1}] (a function spline's graph through
/// function_spline_segments.h), as cubic Bézier segments for the canvas, the exports and κ(s).
///
/// The overshoot: on each interval the part of a curve outside [min(y_i, y_{i+1}),
/// max(y_i, y_{i+1})], measured exactly per segment (interval_overshoot.h: at the roots of
/// the derivative, no sampling) and, for the shading only, outlined from samples. On
/// d3-shape #38's data the natural spline dips about 98 below 180 between x = 107 and 502;
/// Fritsch–Carlson and Steffen measure 0. No mathematics here: calls to the core.

#include "core/base/vec2.h"
#include "core/curves/splines/bezier_segments.h"
#include "core/curves/splines/curvature_profile.h"
#include "core/curves/splines/interval_overshoot.h"
#include "core/exact/polynomial.h"
#include "ui/catmull_rom/function_data_settings.h"

#include <QColor>
#include <QCoreApplication>
#include <QString>

#include <vector>

namespace granota::ui {

/// One of the four curves on the data.
struct FunctionDataCurveShape {
    FunctionDataCurve curve = FunctionDataCurve::Natural;
    std::vector<Vec2<Polynomial<double>>> segments; ///< one per interval, local u ∈ [0, 1]
    std::vector<BezierSegment<double>> bezier;      ///< the segments as cubic Bézier curves
    std::vector<Point> samples;                     ///< kSamplesPerSegment per segment, ends included
    std::vector<IntervalOvershoot> overshoot;       ///< one per interval
    double largestOvershoot = 0;                    ///< the largest overshoot.amount (0: never leaves the data's bands)
    int largestInterval = -1;                       ///< the interval i (from x_i to x_{i+1}) where it is, −1 for none
    /// Each overshooting interval's shaded region in model coordinates: the curve's samples
    /// there, then the same samples clamped into the band, backwards (a closed outline).
    std::vector<std::vector<Point>> overshootRegions;
    CurvatureProfile curvature; ///< κ(s), when asked for
};

struct FunctionDataScene {
    static constexpr int kSamplesPerSegment = 41; ///< as the Catmull-Rom curves (CatmullRomScene)
    /// An overshoot below this fraction of the data's y range is rounding (the value at u = 1
    /// of a piece computed in doubles), and measures 0.
    static constexpr double kOvershootRoundingFraction = 1e-9;
    std::vector<FunctionDataCurveShape> curves; ///< the shown ones, in kFunctionDataCurves order
    QString error;                              ///< translated: why the points are no function data
};

/// The four curves' colours (canvas, key, κ(s) plot, exports, overshoot table).
QColor functionDataCurveColour(FunctionDataCurve curve);
/// "natural spline", "Catmull-Rom τ = 1/2", "Fritsch–Carlson", "Steffen", translated.
QString functionDataCurveLabel(FunctionDataCurve curve);

/// The shown curves through `points` read as data y(x); κ(s) profiles when `curvature`.
FunctionDataScene computeFunctionDataScene(const std::vector<Point>& points, const FunctionDataSettings& settings,
                                           bool curvature);

class FunctionDataCurves {
    Q_DECLARE_TR_FUNCTIONS(granota::ui::FunctionDataCurves)
};

} // namespace granota::ui
