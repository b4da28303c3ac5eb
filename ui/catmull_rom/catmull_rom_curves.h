#pragma once
/// \file catmull_rom_curves.h
/// What the Catmull-Rom tab draws, computed by the core from the points and the settings:
/// one curve per τ (Def 2.10 in the chosen mode and spacing), the other end mode for Ex 2.13's
/// comparison, the Bézier curve of the same points (§2.3) and the cubic spline with its chosen ends
/// (Def 2.3), each also as cubic Bézier segments (bezier_segments.h: drawn and exported as
/// cubic paths) and, for the κ(s) plot, as a curvature profile (curvature_profile.h). No
/// mathematics here: only calls to core/curves/splines/catmull_rom.h, de_casteljau.h,
/// cubic_spline.h, function_spline_segments.h and curvature_profile.h, and the translation of
/// their errors.

#include "core/base/expected.h"
#include "core/exact/polynomial.h"
#include "core/exact/rational.h"
#include "core/base/vec2.h"
#include "core/curves/splines/bezier_segments.h"
#include "core/curves/splines/catmull_rom_analysis.h"
#include "core/curves/splines/curvature_profile.h"
#include "core/curves/splines/piecewise_polynomial.h"
#include "ui/catmull_rom/catmull_rom_settings.h"
#include "ui/catmull_rom/family_curves.h"
#include "ui/catmull_rom/function_data_curves.h"
#include "ui/catmull_rom/plane_spline_curves.h"

#include <QCoreApplication>
#include <QString>

#include <optional>
#include <vector>

namespace granota::ui {

/// One Catmull-Rom curve: its segments in the local s ∈ [0, 1] and its samples.
struct CatmullRomCurve {
    Rational tau;
    CatmullRomEnds ends = CatmullRomEnds::Open;
    std::vector<Vec2<Polynomial<double>>> segments;
    std::vector<Point> samples;                ///< kSamplesPerSegment per segment, ends included, in order
    std::vector<BezierSegment<double>> bezier; ///< the segments as cubic Bézier curves
    /// h_i per segment (catmullRomIntervals): 1 for uniform spacing, |q_{i+1} − q_i|^α else,
    /// with 1 instead of 0 for a segment between coincident points (it is a point).
    std::vector<double> intervals;
    CurvatureProfile curvature; ///< κ(s), when the plot shows it
    QString error;              ///< translated; empty when the curve exists
};

struct CatmullRomScene {
    static constexpr int kSamplesPerSegment = 41; ///< `part` = 40 in the Matlab SegmentCatmullRom
    static constexpr int kBezierSamples = 301;
    /// κ(s) samples of all Catmull-Rom curves together: with many points and tensions each
    /// segment gets fewer (at least 5, at most kSamplesPerSegment), so that the plot follows
    /// a drag (a plot a few hundred pixels wide shows no more anyway).
    static constexpr int kCurvatureSampleBudget = 8000;
    static constexpr int kMinCurvatureSamples = 5;
    std::vector<CatmullRomCurve> curves;    ///< one per τ, in the order of the list
    std::vector<CatmullRomCurve> otherEnds; ///< compareEnds: one per τ in the other end mode
    std::vector<Point> bezier;              ///< the Bézier curve of the points (when shown)
    CurvatureProfile bezierCurvature;       ///< its κ(s): one segment of degree n (when plotted)
    std::vector<Point> spline;              ///< the cubic spline with its chosen ends (when shown and defined), sampled
    std::optional<PiecewisePolynomial<double>> splinePieces; ///< and its pieces, solved once (the side panel formats them)
    /// The spline's graph (x, s(x)) as parametric pieces (function_spline_segments.h), with
    /// their lengths h_i = x_{i+1} − x_i, as cubic Bézier segments and as κ(s) (when plotted).
    std::vector<Vec2<Polynomial<double>>> splineSegments;
    std::vector<double> splineIntervals;
    std::vector<BezierSegment<double>> splineBezier;
    CurvatureProfile splineCurvature;
    QString splineError;            ///< translated: why there is no spline
    FamilyCurve family;             ///< the chosen family's curve when it is not Catmull-Rom (family_curves.h)
    PlaneSplineScene planeSpline;   ///< the C² spline in the plane, in that family (plane_spline_curves.h)
    FunctionDataScene functionData; ///< the four curves on function data, in that family (function_data_curves.h)
};

/// The control polygons of cubic Bézier segments, as curvatureProfile() takes them.
std::vector<std::vector<Point>> controlPolygons(const std::vector<BezierSegment<double>>& segments);

/// A core error in the user's language.
QString translatedError(const Error& error, CatmullRomEnds ends);

CatmullRomScene computeScene(const std::vector<Point>& points, const CatmullRomSettings& settings);

/// The exact side of the same settings (catmull_rom_analysis.h) for the points exactly as the
/// point editor keeps them (PointEditor::allExactPoints), empty when some coordinate has no
/// exact form. Computed once per change, for the side panel.
CatmullRomAnalysis computeAnalysis(const std::optional<std::vector<RPoint>>& exactPoints, const CatmullRomSettings& settings);

class CatmullRomCurves {
    Q_DECLARE_TR_FUNCTIONS(CatmullRomCurves)
};

} // namespace granota::ui
