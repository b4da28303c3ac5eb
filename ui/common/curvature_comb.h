#pragma once
/// \file curvature_comb.h
/// The curvature comb of a Bézier curve (beyond the thesis; Farin, *Curves and Surfaces for
/// CAGD*, §23.1, "curvature plots"): at evenly spaced t, a tooth from c(t) along the normal,
/// of length |κ(t)| × scale, on the side away from the centre of curvature, and the outline
/// through the teeth's tips. On a straight piece the teeth have length 0; where κ is
/// undefined (c′ = 0, a cusp) there is no tooth and the outline breaks. Shared by the
/// De Casteljau tab and the Fitting tab: computed here, drawn with drawCurvatureComb(), and
/// written to TikZ by the tabs from the same teeth and outline.

#include "core/base/vec2.h"
#include "ui/common/canvas_style.h"
#include "ui/common/view_transform.h"

#include <QColor>

#include <vector>

class QPainter;

namespace granota::ui {

struct CurvatureComb {
    struct Tooth {
        Point base, tip;
    };
    std::vector<Tooth> teeth;                ///< only where κ is defined
    std::vector<std::vector<Point>> outline; ///< the tips, one polyline per stretch where κ is defined
    double scale = 0;                        ///< model length of a tooth per unit of |κ|
    int undefinedSamples = 0;                ///< samples where κ is undefined (no tooth)
    bool empty() const { return teeth.empty(); }
};

/// The comb of the curve with control points `P` at `samples` + 1 evenly spaced t. With
/// `scale` ≤ 0 it is automatic: the teeth of the 90th percentile of |κ| are 15 % of the
/// curve's size long (the diagonal of its samples' box, not of the control polygon, which a
/// fit of high degree throws far away). Whatever the scale, no tooth is longer than half the
/// curve's size (a tooth near a cusp is cut there).
CurvatureComb curvatureComb(const std::vector<Point>& P, int samples, double scale = 0);

/// The comb's colour (the legend shows it).
inline QColor curvatureCombColor() { return QColor(0x2a, 0x9d, 0x8f); }

/// Draws the teeth (thin) and the outline in `color`.
void drawCurvatureComb(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const CurvatureComb& comb,
                       const QColor& color = curvatureCombColor());

} // namespace granota::ui
