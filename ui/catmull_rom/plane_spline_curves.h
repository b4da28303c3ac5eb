#pragma once
/// \file plane_spline_curves.h
/// What the Catmull-Rom tab draws in its "C² spline in the plane" family: the parametric C²
/// spline of Def 2.1 through the points (core/curves/splines/parametric_spline.h) with the
/// family's ends and parameters, as cubic Bézier segments (bezier_segments.h: drawn and
/// exported as cubic paths, and κ(s) from them), its knots u_i, and beside it the
/// Catmull-Rom curve (τ = 1/2) of the same points in the matching mode and spacing (closed
/// for periodic ends; α = 0, 1/2, 1 for uniform, centripetal and chord parameters), which
/// §2.3 compares with it: C² against C¹. No mathematics here: calls to the core and the
/// translation of its errors.

#include "core/base/expected.h"
#include "core/base/vec2.h"
#include "core/curves/splines/bezier_segments.h"
#include "core/curves/splines/curvature_profile.h"
#include "ui/catmull_rom/plane_spline_settings.h"

#include <QCoreApplication>
#include <QString>

#include <vector>

namespace granota::ui {

/// One curve of the family: a C² spline or its Catmull-Rom comparison.
struct PlaneSplineCurve {
    std::vector<BezierSegment<double>> bezier; ///< one cubic Bézier segment per segment, in order
    std::vector<Point> samples;                ///< kSamplesPerSegment per segment, ends included
    std::vector<double> knots;                 ///< u_0 < u_1 < … (the spline only)
    CurvatureProfile curvature;                ///< κ(s), when asked for
    QString error;                             ///< translated; empty when the curve exists
};

struct PlaneSplineScene {
    static constexpr int kSamplesPerSegment = 41; ///< as the Catmull-Rom curves (CatmullRomScene)
    PlaneSplineCurve spline;
    PlaneSplineCurve catmullRom; ///< empty unless settings.catmullRomToo
};

/// The spline (and its comparison) through `points`; κ(s) profiles when `curvature`.
PlaneSplineScene computePlaneSplineScene(const std::vector<Point>& points, const PlaneSplineSettings& settings, bool curvature);

/// The core's error for the spline through `points` in the user's language: too few points
/// for the ends, coincident consecutive points with chord or centripetal parameters (which
/// names them), a point that is not finite, an overflow.
QString translatedPlaneSplineError(const Error& error, const std::vector<Point>& points, const PlaneSplineSettings& settings);

/// "natural", "clamped", "not-a-knot", "periodic (closed)" and "uniform", "chord length",
/// "centripetal", translated: the panel's choices and the key's texts.
QString planeSplineEndsLabel(ParametricEnds ends);
QString planeSplineParametersLabel(SplineParameters parameters);

class PlaneSplineCurves {
    Q_DECLARE_TR_FUNCTIONS(granota::ui::PlaneSplineCurves)
};

} // namespace granota::ui
