#pragma once
/// \file spline_families_drawing.h
/// What the Catmull-Rom canvas shows in the families "C² spline in the plane" and "function
/// data" besides the point editor's handles (catmull_rom_drawing.h does the Catmull-Rom
/// family): the curves as cubic paths (each segment one Bézier segment, so the exports write
/// them as such), the function data's overshoot shaded, their keys, what a key should not
/// cover and the box the view fits to.

#include "ui/catmull_rom/function_data_curves.h"
#include "ui/catmull_rom/plane_spline_curves.h"
#include "ui/common/canvas_legend.h"

#include <QColor>
#include <QRectF>

#include <vector>

class QPainter;

namespace granota::ui {

class ViewTransform;
struct CanvasStyle;

/// Opacity of the overshoot's fill, 0–255: the curve shows through.
inline constexpr int kOvershootFillAlpha = 70;

/// The Catmull-Rom comparison dashed under the C² spline.
void drawPlaneSpline(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const PlaneSplineScene& scene);
CanvasLegend planeSplineLegend(const PlaneSplineSettings& settings, const PlaneSplineScene& scene);

/// Each shown curve in its colour, its overshoot filled translucent underneath (when shaded).
void drawFunctionData(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const FunctionDataSettings& settings,
                      const FunctionDataScene& scene);
CanvasLegend functionDataLegend(const FunctionDataScene& scene);

/// The samples of every curve drawn, in `view`'s pixels: the key covers as few as it can.
CanvasLegendObstacles splineFamilyLegendObstacles(const ViewTransform& view, const std::vector<std::vector<Point>>& samples);
/// The samples of the curves drawn, one list per curve (for the key and the view's box).
std::vector<std::vector<Point>> planeSplineSamples(const PlaneSplineScene& scene);
std::vector<std::vector<Point>> functionDataSamples(const FunctionDataScene& scene);

/// The points' box and the curves' samples inside one box size around it.
QRectF splineFamilyContentBounds(const std::vector<Point>& points, const std::vector<std::vector<Point>>& samples);

} // namespace granota::ui
