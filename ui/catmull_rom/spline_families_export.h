#pragma once
/// \file spline_families_export.h
/// The TikZ picture of the families "C² spline in the plane" and "function data": each
/// curve as cubic Bézier segments (TikzWriter::bezierSegments, as on the canvas), the function
/// data's overshoot filled in the curve's colour, and the canvas's key. The SVG export paints
/// the canvas, so it draws them with spline_families_drawing.h as cubic paths.

#include "ui/catmull_rom/function_data_curves.h"
#include "ui/catmull_rom/plane_spline_curves.h"
#include "ui/common/canvas_legend.h"

namespace granota::ui {

class TikzWriter;

void writePlaneSplineTikz(TikzWriter& w, const PlaneSplineSettings& settings, const PlaneSplineScene& scene);
/// The canvas's key (planeSplineLegend, functionDataLegend) in TeX, after the points.
void writeSplineFamilyTikzKey(TikzWriter& w, const CanvasLegend& key);
void writeFunctionDataTikz(TikzWriter& w, const FunctionDataSettings& settings, const FunctionDataScene& scene);

} // namespace granota::ui
