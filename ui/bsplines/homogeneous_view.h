#pragma once
/// \file homogeneous_view.h
/// A rational curve as the central projection of a polynomial one (Piegl & Tiller §4.2;
/// Farin ch. 13): the control points Pᵢ = (xᵢ, yᵢ) with weights wᵢ are the points
/// Hᵢ = (wᵢxᵢ, wᵢyᵢ, wᵢ) of space, the B-spline H(u) = Σ Nᵢ,ₚ(u) Hᵢ through them is polynomial,
/// and the ray from the origin through H(u) meets the plane w = 1 at c(u) = (X/W, Y/W): the
/// rational curve. The points of H(u) come from the core's de Boor on the homogeneous points
/// (de_boor.h: its last level's point times its weight). The inset draws it in an oblique view
/// (x to the right, y up, w into the depth): the plane w = 1 with the curve and its polygon,
/// the homogeneous polygon and curve, and the rays from the origin through each Hᵢ.

#include "core/base/vec2.h"
#include "core/curves/bsplines/bspline_curve.h"
#include "ui/common/canvas_style.h"

#include <QRectF>

#include <vector>

class QPainter;

namespace granota::ui {

struct HomogeneousPoint {
    double x = 0; ///< w·x
    double y = 0; ///< w·y
    double w = 1;
};

struct HomogeneousView {
    std::vector<HomogeneousPoint> controlPoints; ///< Hᵢ = (wᵢxᵢ, wᵢyᵢ, wᵢ); wᵢ = 1 for a polynomial curve
    std::vector<double> u;                       ///< the sample parameters, over the domain
    std::vector<HomogeneousPoint> curve;         ///< H(u) at those u
    std::vector<Point> planeCurve;               ///< c(u) = (X/W, Y/W) at those u: the curve on w = 1
    bool empty() const { return controlPoints.empty(); }
};

/// The view of `c` (which passes checkBSpline), `samplesPerSpan` ≥ 2 samples of each non-empty
/// span, both ends included.
HomogeneousView homogeneousView(const BSplineCurve<double>& c, int samplesPerSpan);

/// The oblique picture of `view` fitted into `target` (widget pixels) on a light panel, with
/// `title` at its top.
void drawHomogeneousView(QPainter& p, const QRectF& target, const HomogeneousView& view, const CanvasStyle& style,
                         const QString& title);

} // namespace granota::ui
