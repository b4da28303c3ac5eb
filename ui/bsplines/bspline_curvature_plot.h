#pragma once
/// \file bspline_curvature_plot.h
/// The other face of the plot under the B-spline canvas: the signed curvature κ of the curve
/// against its arc length s (the κ(s) plot of the Catmull-Rom tab, curvature_plot.h), from the
/// scene's profile of the Bézier pieces, each interior knot marked and labelled with the
/// continuity Cᵖ⁻ᵐ its multiplicity m allows: at a simple knot of a cubic κ is continuous (C²),
/// at a double one it may jump (C¹), at a triple one the curve may turn a corner (C⁰). Its texts
/// keep the tab's translation context (granota::ui::BSplineTab).

#include "ui/bsplines/bspline_scene.h"

class QCustomPlot;
class QFont;
class QLabel;

namespace granota::ui {

/// The title above the plot and the tooltips for κ(s).
void setBSplineCurvaturePlotTexts(QLabel* title, QCustomPlot* plot);
/// Plots `scene`'s κ(s) (computed when the model asks for it) in `font`, lines `scale` times the
/// normal width, and queues a replot.
void updateBSplineCurvaturePlot(QCustomPlot* plot, const QFont& font, const BSplineScene& scene, double scale);

/// The label of a knot of multiplicity m on a curve of degree p: "Cᵖ⁻ᵐ" with the number
/// written (C², C¹, C⁰), or "broken" (translated) when m = p + 1.
QString continuityLabel(int degree, int multiplicity);

} // namespace granota::ui
