#pragma once
/// \file bspline_drawing.h
/// The B-spline on the canvas, under the point editor's handles: the Bézier segments of the
/// extraction (when shown), the polygon before a knot insertion (dashed, under the new one),
/// the curve, the p + 1 control points of u's span ringed (local support: only they move the
/// curve there), and de Boor's net at u level by level, one colour per level as the De
/// Casteljau tab draws its construction (CanvasStyle::series), the point c(u) last. The same
/// drawing serves the screen and every image export; tikz() writes the same layers.

#include "core/base/vec2.h"
#include "ui/bsplines/bspline_model.h"
#include "ui/bsplines/bspline_scene.h"
#include "ui/common/canvas_style.h"
#include "ui/common/view_transform.h"

#include <QColor>

#include <vector>

class QPainter;

namespace granota::ui {

class TikzWriter;

/// The span's points and the span on the knot ruler.
inline const QColor kBSplineSpanColour(0xf2, 0xb7, 0x05);
/// The cubic Bézier quarter circle beside the exact one.
inline const QColor kBSplineCubicCircleColour(0xc0, 0x39, 0x2b);
/// The polygon before a knot insertion.
inline const QColor kBSplineOldPolygonColour(0x6a, 0x6a, 0x6a);
/// The Bézier segments' control polygons, alternately.
inline QColor bsplineSegmentColour(int i) { return i % 2 ? QColor(0x8e, 0x44, 0xad) : QColor(0x16, 0xa0, 0x85); }

void drawBSpline(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const BSplineModel& model,
                 const BSplineScene& scene, const std::vector<Point>& previousPolygon);

/// The weights of a rational curve (none drawn for a polynomial one): a thin ring round each
/// point Pᵢ whose radius grows with log₂ wᵢ (w = 1 just outside the handle, each doubling a
/// little wider), and "w = …" (exact) beside the selected point (−1: none).
inline const QColor kBSplineWeightColour(0x8e, 0x44, 0xad);
void drawBSplineWeights(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const std::vector<Point>& points,
                        const std::vector<Rational>& weights, int selected);

/// The same in TikZ: the curve as cubic `.. controls ..` segments when its Bézier segments are
/// cubic or less (raised to degree 3 exactly), else as a polyline of its samples; the polygon, the
/// points P_i, the net at u.
void writeBSplineTikz(TikzWriter& w, const std::vector<Point>& points, const BSplineModel& model, const BSplineScene& scene);

} // namespace granota::ui
