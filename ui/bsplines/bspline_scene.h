#pragma once
/// \file bspline_scene.h
/// What the B-spline tab draws, computed once per change and without a widget: the curve
/// checked (checkBSpline), sampled span by span, de Boor's net at u level by level (de_boor.h),
/// exactly too when the points are exact (the knots, the weights and u always are), and the
/// Bézier segments of the curve when they are shown. The canvas, the ruler, the basis plot,
/// the exact panel and the exports all read this one scene.

#include "core/base/vec2.h"
#include "core/curves/bsplines/bspline_curve.h"
#include "core/curves/bsplines/de_boor.h"
#include "core/curves/splines/curvature_profile.h"
#include "core/exact/rational.h"
#include "ui/bsplines/bspline_model.h"
#include "ui/bsplines/homogeneous_view.h"

#include <QString>

#include <array>
#include <optional>
#include <vector>

namespace granota::ui {

struct BSplineScene {
    static constexpr int kSamplesPerSpan = 32;     ///< samples of each non-empty knot span, both ends included
    static constexpr int kCurvatureSamples = 48;   ///< κ(s) samples of each Bézier piece, both ends included
    static constexpr int kHomogeneousSamples = 17; ///< samples of each span in (wx, wy, w) (its middle among them)

    BSplineCurve<double> curve; ///< the curve drawn: the points, the knots and weights in force
    /// The same exactly: each point's exact form, or the value of its double where it has none
    /// (every double is a fraction). Insertion, removal and elevation work on it.
    BSplineCurve<Rational> exact;
    /// Why the curve cannot be drawn (checkBSpline's words, in English: the tab says it in its own),
    /// empty when it can.
    QString error;
    Rational u;                                    ///< de Boor's parameter, inside the domain
    DeBoorTable<double> net;                       ///< de Boor's net at u
    std::optional<DeBoorTable<Rational>> exactNet; ///< the same exactly, when every point has an exact form
    std::vector<Point> samples;                    ///< the curve over its domain, span after span
    /// The control points of each Bézier segment (the extraction, one per non-empty span), and
    /// their weights for a rational curve (empty otherwise).
    std::vector<std::vector<Point>> bezier;
    std::vector<std::vector<double>> bezierWeights;
    /// The curve as cubic Bézier segments when it is polynomial of degree ≤ 3 (each segment
    /// raised to degree 3 exactly): the canvas draws them as cubic paths, so that SVG and PDF
    /// hold the curve itself, and TikZ writes them as `.. controls ..`. Empty otherwise.
    std::vector<std::array<Point, 4>> cubics;
    /// The cubic Bézier quarter circle (1,0), (1,k), (k,1), (0,1), k = 4(√2 − 1)/3, drawn beside
    /// the exact one when the model asks (circle_arcs.h), and its largest radial error.
    std::vector<Point> cubicCircle;
    double cubicCircleError = 0;
    /// κ(s) along the curve when the plot shows it (model.curvaturePlot): the profile of its
    /// Bézier segments (curvature_profile.h), one piece per non-empty span, so a jump of κ at a
    /// knot is a break; and each interior knot of the domain with its multiplicity m (the
    /// curve is Cᵖ⁻ᵐ there), at the s where its piece starts.
    CurvatureProfile curvature;
    struct KnotContinuity {
        double s = 0;         ///< arc length from the curve's start to the knot
        int multiplicity = 1; ///< m; the curve is Cᵖ⁻ᵐ there (broken when m = p + 1)
    };
    std::vector<KnotContinuity> curvatureKnots;
    /// The curve in (wx, wy, w) when the model shows it (homogeneous_view.h).
    HomogeneousView homogeneous;

    bool valid() const { return error.isEmpty(); }
    int span() const { return net.span; }
    int degree() const { return curve.degree; }
};

/// The scene of `points` under `model`; `exactValues` are the points exactly (their exact forms,
/// or their doubles' values), `allExact` whether every one is an exact form (the net is then shown exactly).
BSplineScene computeBSplineScene(const std::vector<Point>& points, const std::vector<RPoint>& exactValues, bool allExact,
                                 const BSplineModel& model);

/// The box the view frames: the points, the curve and the Bézier points drawn.
QRectF bsplineContentBounds(const std::vector<Point>& points, const BSplineScene& scene);

} // namespace granota::ui
