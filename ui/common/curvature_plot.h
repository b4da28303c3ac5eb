#pragma once
/// \file curvature_plot.h
/// The κ(s) plot that makes §2.3 visible, shared by the curve tabs: the signed curvature κ of
/// one or more curves (each a CurvatureProfile of the core, curvature_profile.h) against arc
/// length s, with a gap at each knot (both sides of a knot are samples at the same s, so a jump
/// of κ shows as a break, never as a steep slope), a gap where κ is undefined (a cusp), the knots
/// marked by light vertical lines, optionally labelled (the B-spline tab writes the continuity
/// Cᵖ⁻ᵐ there), and the y range of most values (the 1st to 99th percentile) so that the spike of
/// a near-cusp or a corner does not flatten every other curve. The values come from the core;
/// this only plots them.

#include "core/curves/splines/curvature_profile.h"

#include <QPen>
#include <QString>

#include <vector>

class QCustomPlot;

namespace granota::ui {

/// One curve of the plot: its profile, its pen (colour and line style, as on the canvas) and its
/// legend name.
struct CurvaturePlotCurve {
    const CurvatureProfile* profile = nullptr; ///< not owned; must outlive the call
    QPen pen;
    QString name;
};

/// A knot marked on the plot: a light dashed vertical line at s, with `label` (may be empty)
/// written at its top.
struct CurvaturePlotKnot {
    double s = 0;
    QString label;
};

/// The plot's axes and pixels.
struct CurvaturePlotFrame {
    QString xLabel;        ///< "arc length s", translated by the caller
    QString yLabel;        ///< "curvature κ"
    int minimumHeight = 0; ///< plot height that keeps the axis titles whole (keepAxisTitlesWhole)
    double scale = 1;      ///< line widths times this (presentation mode)
};

/// Adds the curves and the knot marks to `plot` (whose graphs and items the caller cleared) and
/// sets its ranges: s over [0, the longest length], κ over most values with a margin. Does not
/// replot.
void plotCurvatureProfiles(QCustomPlot* plot, const std::vector<CurvaturePlotCurve>& curves,
                           const std::vector<CurvaturePlotKnot>& knots, const CurvaturePlotFrame& frame);

} // namespace granota::ui
