#pragma once
/// \file catmull_rom_export.h
/// The Catmull-Rom tab's own exports (docs/file-formats.md): the CSV of its points, of every
/// curve's samples per τ, segment and t and, while the plot shows κ(s), of the curvature as
/// plotted; and the TikZ picture of the canvas, each Catmull-Rom segment and spline piece as a
/// cubic Bézier segment, with the canvas's key (catmull_rom_drawing.h).

#include "core/exact/exact_point.h"
#include "ui/catmull_rom/catmull_rom_curves.h"
#include "ui/catmull_rom/catmull_rom_settings.h"

#include <QString>

#include <vector>

namespace granota::ui {

class TikzWriter;

/// The points q_i (their exact values' decimals, readableExact, with `exact` index by index),
/// then "tau,segment,t,x,y" for every curve, then (settings.curvaturePlot)
/// "curve,tau,ends,segment,s,kappa": numbers as formatReadable writes them.
QString catmullRomCsv(const std::vector<Point>& points, const std::vector<ExactPoint>& exact, const CatmullRomSettings& settings,
                      const CatmullRomScene& scene);

/// The canvas in TikZ: the points' polygon (when `polygonVisible`, as the point editor draws
/// it), the comparisons, the curves of every τ, the points and the key.
void writeCatmullRomTikz(TikzWriter& w, const std::vector<Point>& points, bool polygonVisible, const CatmullRomSettings& settings,
                         const CatmullRomScene& scene);

} // namespace granota::ui
