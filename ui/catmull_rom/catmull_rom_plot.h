#pragma once
/// \file catmull_rom_plot.h
/// The plot under the Catmull-Rom canvas (docs/tabs.md): the blending functions wⱼ(t, τ) of
/// Cor 2.1 (Def 2.9) for the selected τ or, as Ex 2.12, for every τ in one line style each; or,
/// for §2.3, the signed curvature κ of every curve drawn against its arc length s, with a gap
/// at each knot (a jump of κ shows as a break) and the selected τ's knots marked. The values
/// come from the core (blendingFunctions, the scene's curvature profiles); this only plots
/// them. Its texts keep the tab's translation context (granota::ui::CatmullRomTab).

#include "ui/catmull_rom/catmull_rom_curves.h"
#include "ui/catmull_rom/catmull_rom_settings.h"

class QCustomPlot;
class QFont;
class QLabel;

namespace granota::ui {

/// The plot's lasting set-up: the legend in the top right corner, t ∈ [0, 1], tick labels kept
/// inside the widget.
void setUpCatmullRomPlot(QCustomPlot* plot);

/// The title above the plot and the tooltips, for the blending functions or for κ(s).
void setCatmullRomPlotTexts(QLabel* title, QCustomPlot* plot, bool curvature);

/// Plots what `settings` asks (settings.curvaturePlot: κ(s) of `scene`'s curves; else the
/// blending functions), in `font` and with lines `scale` times the normal width (presentation
/// mode), and queues a replot.
void updateCatmullRomPlot(QCustomPlot* plot, const QFont& font, const CatmullRomSettings& settings, const CatmullRomScene& scene,
                          double scale);

} // namespace granota::ui
