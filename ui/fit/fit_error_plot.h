#pragma once
/// \file fit_error_plot.h
/// The Fitting tab's error-against-degree plot (docs/tabs.md): the least-squares error
/// Σ‖Q_i − α(t_i)‖² of the best curve of each degree n (core/curves/fitting/fit_error_by_degree.h)
/// on a log axis, with the current n circled — for the tab's parametrization, or for every
/// parametrization at once, one line each with a key, so that the class sees where each wins
/// (with Annex III's t_i the n = 3 fit of Ex 2.8's data is worse than with uniform ones).
///
/// The graphs: 0 is the tab's parametrization (empty while all are shown), 1 the circle at the
/// current n, 2 + i the parametrization kPlottedParametrizations[i] (empty unless all are shown).

#include "core/curves/fitting/least_squares_fit.h"

#include <QString>

#include <array>
#include <vector>

class QCPGraph;
class QCustomPlot;

namespace granota::ui {

/// Every parametrization the core knows (parametrization.h), in the order of their lines.
constexpr std::array<Parametrization, 4> kPlottedParametrizations = {Parametrization::Uniform, Parametrization::ChordLength,
                                                                     Parametrization::Centripetal, Parametrization::AnnexIII};

/// Makes the graphs, the log axis and the integer ticks.
void setUpFitErrorPlot(QCustomPlot* plot);
/// Pens and markers at the presentation scale `scale` (1 on a desk).
void styleFitErrorPlot(QCustomPlot* plot, double scale);

struct FitErrorPlotInput {
    const std::vector<Point>* points = nullptr;                 ///< Q_0…Q_k
    Parametrization parametrization = Parametrization::Uniform; ///< the tab's (its line, and the circle's)
    LeastSquaresSolver solver = LeastSquaresSolver::Qr;
    int currentDegree = 0; ///< circled
    int lastDegree = 0;    ///< plotted from n = 1 up to this
    bool allParametrizations = false;
    /// The lines' names in the key, in the order of kPlottedParametrizations (translated by the tab).
    std::array<QString, 4> names;
};

/// What the plot shows, for the note beside it: one place for the degree where the axis ends.
struct FitErrorPlotRange {
    int lastDegree = 0;    ///< the highest degree tried (0 when none), where the x axis ends
    int failedDegrees = 0; ///< degrees whose fit failed on some line: gaps in it, no line across
};

/// Fits and plots: a degree whose fit failed is a gap in its line; the x axis ends at the
/// highest degree tried, failed or not.
FitErrorPlotRange fillFitErrorPlot(QCustomPlot* plot, const FitErrorPlotInput& in);

/// The graph that shows `p` now, or nullptr.
QCPGraph* fitErrorGraph(QCustomPlot* plot, Parametrization p, Parametrization current, bool allParametrizations);

} // namespace granota::ui
