#pragma once
/// \file spline_families_export.h
/// The CSV samples of the families "C² spline in the plane" and "function data" (after the
/// tab's points and τ curves, catmull_rom_export.h), and the TikZ picture of the families "C² spline in the plane" and "function data": each
/// curve as cubic Bézier segments (TikzWriter::bezierSegments, as on the canvas), the function
/// data's overshoot filled in the curve's colour, and the canvas's key. The SVG export paints
/// the canvas, so it draws them with spline_families_drawing.h as cubic paths.

#include "ui/catmull_rom/function_data_curves.h"
#include "ui/catmull_rom/plane_spline_curves.h"
#include "ui/common/canvas_legend.h"

namespace granota::ui {

class TikzWriter;

/// "curve,segment,t,x,y" and one row per sample of the spline ("c2-spline") and of its
/// Catmull-Rom comparison ("catmull-rom") when drawn; then "knot,u" with the spline's knots.
QString planeSplineCsv(const PlaneSplineScene& scene);
/// "curve,segment,t,x,y", one row per sample of each curve shown (functionDataCurveKey:
/// "natural", "fritsch-carlson"…; segment i joins x_{i−1} to x_i), then "curve,interval,overshoot",
/// each curve's overshoot on every data interval (0: it stays within the two data values).
QString functionDataCsv(const FunctionDataScene& scene);

void writePlaneSplineTikz(TikzWriter& w, const PlaneSplineSettings& settings, const PlaneSplineScene& scene);
/// The canvas's key (planeSplineLegend, functionDataLegend) in TeX, after the points.
void writeSplineFamilyTikzKey(TikzWriter& w, const CanvasLegend& key);
void writeFunctionDataTikz(TikzWriter& w, const FunctionDataSettings& settings, const FunctionDataScene& scene);

} // namespace granota::ui
