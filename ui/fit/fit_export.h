#pragma once
/// \file fit_export.h
/// The Fitting tab's exports, all of the finished fit (never a half state of one running in
/// the background): File ▸ Export ▸ CSV (docs/file-formats.md), the TikZ figure (the same
/// picture as the screen, fit_display.h), and File ▸ Export's image through the canvas.

#include "core/curves/fitting/least_squares_fit.h"
#include "core/exact/exact_point.h"
#include "ui/common/drawable.h"
#include "ui/fit/fit_display.h"

#include <QString>

#include <functional>
#include <vector>

namespace granota::ui {

class TikzWriter;
struct CurvatureComb;

/// What the CSV is written from.
struct FitCsvInput {
    const std::vector<Point>& data;       ///< Q_0…Q_k
    const std::vector<ExactPoint>& exact; ///< their exact forms, index by index (exact_point.h)
    const FitResult* fit;                 ///< nullptr: no fit (its columns are left empty)
    /// The error plot's lines for every parametrization (fitErrorByDegree, n = 1 … lastDegree)
    /// are appended when `allParametrizations`.
    bool allParametrizations = false;
    LeastSquaresSolver solver = LeastSquaresSolver::Qr;
    int lastDegree = 0;
};

/// `i,x,y,t,alpha_x,alpha_y,residual_x,residual_y` per data point, then `j,P_x,P_y` per
/// control point, then `parametrization,degree,sse` per line of the error plot (empty where
/// that fit failed). The data as their exact values' decimals (readableExact: as typed), the
/// rest at most 15 significant digits, the fit without binary noise.
QString fitCsv(const FitCsvInput& in);

/// The TikZ figure: a comment naming the fit, then writeFitTikz()'s picture.
void writeFitFigureTikz(TikzWriter& tikz, int degree, Parametrization parametrization, const FitPicture& picture,
                        const CurvatureComb* comb);

/// File ▸ Export of the tab: its canvas, once `finish` has waited for a fit in the background.
class FinishedFitView : public Drawable {
public:
    FinishedFitView(std::function<void()> finish, Drawable* canvas) : m_finish(std::move(finish)), m_canvas(canvas) {}
    QSizeF exportSize() const override { return m_canvas->exportSize(); }
    void render(QPainter& painter, const QRectF& target) override
    {
        m_finish();
        m_canvas->render(painter, target);
    }

private:
    std::function<void()> m_finish;
    Drawable* m_canvas;
};

} // namespace granota::ui
