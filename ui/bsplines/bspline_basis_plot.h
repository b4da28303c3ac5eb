#pragma once
/// \file bspline_basis_plot.h
/// The plot under the B-spline canvas: the basis functions N_{i,p}(u) (Cox–de Boor,
/// bspline_basis.h) over the whole knot vector, each in its point's colour (the colour that
/// rings P_i in the canvas's key: CanvasStyle::series(i)), their sum (1 on the domain
/// [u_p, u_{n+1}]: the partition of unity) dashed, the domain shaded and u marked. The values
/// come from the core; this only plots them. Its texts keep the tab's translation context
/// (granota::ui::BSplineTab).

#include "ui/bsplines/bspline_scene.h"

class QCustomPlot;
class QFont;
class QLabel;

namespace granota::ui {

/// The plot's lasting set-up (the legend in the top right corner, tick labels inside).
void setUpBSplineBasisPlot(QCustomPlot* plot);
/// The title above the plot and the tooltips.
void setBSplineBasisPlotTexts(QLabel* title, QCustomPlot* plot);
/// Plots `scene`'s basis functions in `font`, lines `scale` times the normal width, and queues a
/// replot. The legend (N₀…, Σ) only while the plot is high enough for it: call again on a resize.
void updateBSplineBasisPlot(QCustomPlot* plot, const QFont& font, const BSplineScene& scene, double scale);
/// Makes the next updateBSplineBasisPlot draw again, after another plot (κ(s)) drew over it:
/// the basis plot redraws only when the knots, the degree, u or the style change.
void invalidateBSplineBasisPlot(QCustomPlot* plot);

/// The samples of N_{i,p}(u) the plot draws: u over [u_0, u_{n+p+1}], and each function over its
/// support only (it is zero elsewhere): p + 1 spans' worth of samples each, so that 200 points
/// cost 200 short lines, not 200 lines across the whole vector.
struct BasisSamples {
    std::vector<double> u;   ///< every sample, increasing
    std::vector<double> sum; ///< Σ_i N_{i,p}(u_j)
    struct Support {
        int first = 0;              ///< the index in `u` of its first sample
        std::vector<double> values; ///< N_{i,p} at u[first], u[first + 1], …
    };
    std::vector<Support> functions; ///< i = 0..n
};
BasisSamples sampleBasis(const BSplineCurve<double>& curve, int samplesPerSpan);

} // namespace granota::ui
