#pragma once
/// \file fit_display.h
/// What the Fitting tab draws of a fit, and the drawing itself, one for the screen and every
/// export (File ▸ Export goes through the canvas's render(); TikZ through writeFitTikz()): the
/// residual segments α(t_i) → Q_i, the fitted curve through `samples` intervals (the thesis's
/// Matlab `part`), its control points and polygon (`puntsvis`), and the curves of the first
/// 1, 2, …, n + 1 control points (`desglossar`: Rep_BezParamEqui and Rep_BezParamProp call
/// Rep_Bezier with it, Annex III). The data points Q_i are the point editor's, drawn by it.
/// A plain value: an undo step holds it before and after, the document keeps it
/// (docs/file-formats.md).

#include "core/base/vec2.h"
#include "core/curves/fitting/least_squares_fit.h"

#include <QJsonObject>
#include <QString>

#include <optional>
#include <vector>

class QPainter;

namespace granota::ui {

class TikzWriter;
struct CurvatureComb;
class ViewTransform;
struct CanvasStyle;

struct FitDisplay {
    /// The 400 points (399 intervals) the tab drew before `part` could be chosen: old documents look the same.
    static constexpr int kDefaultSamples = 399;
    static constexpr int kMinSamples = 1;     ///< one interval: the chord P_0 P_n
    static constexpr int kMaxSamples = 10000; ///< degree 100 × 10 000 samples: about 5·10⁷ operations a refit

    bool controlPoints = true;                 ///< the fitted P_0…P_n, their labels and polygon (Matlab `puntsvis`)
    bool residuals = true;                     ///< the segments from α(t_i) to Q_i
    bool breakdown = false;                    ///< the curves of P_0…P_k, k = 0…n (Matlab `desglossar`)
    int samples = kDefaultSamples;             ///< intervals of t the drawn curve goes through (Matlab `part`)
    bool errorPlotAllParametrizations = false; ///< the error-against-degree plot for every parametrization at once

    friend bool operator==(const FitDisplay& a, const FitDisplay& b)
    {
        return a.controlPoints == b.controlPoints && a.residuals == b.residuals && a.breakdown == b.breakdown &&
               a.samples == b.samples && a.errorPlotAllParametrizations == b.errorPlotAllParametrizations;
    }
    friend bool operator!=(const FitDisplay& a, const FitDisplay& b) { return !(a == b); }
};

/// The keys `control_points`, `residuals`, `breakdown`, `samples`, `error_plot_all_parametrizations`.
void writeFitDisplay(const FitDisplay& display, QJsonObject& json);
/// Reads them (an absent key keeps the default); nullopt with the first bad key in `badKey`.
std::optional<FitDisplay> readFitDisplay(const QJsonObject& json, QString* badKey);

/// Rep_Bezier with desglossar: for k = 1 … n + 1, the Bézier curve of the first k control
/// points (k = 1: the point P_0 alone), through `samples` intervals — fewer at a high degree,
/// where the n + 1 curves would cost about n³/6 operations a sample (at least 16 intervals).
std::vector<std::vector<Point>> breakdownCurves(const std::vector<Point>& controlPoints, int samples);

/// What one picture of a fit is drawn from.
struct FitPicture {
    const std::vector<Point>& data;                   ///< Q_0…Q_k
    const FitResult* fit;                             ///< nullptr: no fit (nothing of it is drawn)
    const std::vector<Point>& curve;                  ///< α sampled
    const std::vector<std::vector<Point>>& breakdown; ///< breakdownCurves() while shown
    const FitDisplay& display;
};

/// The canvas's layers under the data handles: the residual segments, then the breakdown, the
/// control polygon, the curve and the control points (squares: computed, not dragged).
void drawFitResiduals(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const FitPicture& picture);
void drawFitCurve(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const FitPicture& picture);

/// The same picture in TikZ, in the same order: the control polygon, the comb (when `comb` is
/// given), the breakdown, the curve, the residual segments, the control points, the data points.
void writeFitTikz(TikzWriter& w, const FitPicture& picture, const CurvatureComb* comb);

/// The colour of breakdown curve k (0: the point P_0 alone), screen and TikZ alike.
QColor breakdownColor(int k);

} // namespace granota::ui
