#include "ui/fit/fit_error_plot.h"

#include "core/curves/fitting/fit_error_by_degree.h"
#include "ui/common/canvas_style.h"

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace granota::ui {

namespace {

constexpr int kCurrentGraph = 0;
constexpr int kCircleGraph = 1;
constexpr int kFirstAllGraph = 2;
/// Each parametrization's line in the key: a colour and a marker of its own (they overlap where they agree).
const QCPScatterStyle::ScatterShape kShapes[] = {QCPScatterStyle::ssCircle, QCPScatterStyle::ssSquare,
                                                 QCPScatterStyle::ssTriangle, QCPScatterStyle::ssDiamond};
constexpr int kSeries[] = {0, 1, 2, 5}; ///< CanvasStyle::series of each line (3 is the circle's)

} // namespace

void setUpFitErrorPlot(QCustomPlot* plot)
{
    plot->addGraph(); // the tab's parametrization
    plot->addGraph(); // the current n
    plot->graph(kCircleGraph)->setLineStyle(QCPGraph::lsNone);
    plot->graph(kCircleGraph)->removeFromLegend();
    for (std::size_t i = 0; i < kPlottedParametrizations.size(); ++i)
        plot->addGraph();
    plot->graph(kCurrentGraph)->removeFromLegend();
    plot->yAxis->setScaleType(QCPAxis::stLogarithmic);
    plot->yAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    plot->yAxis->setNumberFormat(QStringLiteral("eb"));
    plot->yAxis->setNumberPrecision(0);
    QSharedPointer<QCPAxisTickerFixed> integers(new QCPAxisTickerFixed);
    integers->setTickStep(1);
    integers->setScaleStrategy(QCPAxisTickerFixed::ssMultiples);
    plot->xAxis->setTicker(integers);
    plot->legend->setBrush(QColor(255, 255, 255, 200));
    plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignBottom | Qt::AlignLeft);
    styleFitErrorPlot(plot, 1.0);
}

void styleFitErrorPlot(QCustomPlot* plot, double scale)
{
    plot->graph(kCurrentGraph)->setPen(QPen(CanvasStyle::series(0), 1.5 * scale));
    plot->graph(kCurrentGraph)->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, 5 * scale));
    plot->graph(kCircleGraph)
        ->setScatterStyle(
            QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(CanvasStyle::series(3), 2 * scale), Qt::NoBrush, 12 * scale));
    for (std::size_t i = 0; i < kPlottedParametrizations.size(); ++i) {
        QCPGraph* g = plot->graph(kFirstAllGraph + static_cast<int>(i));
        const QColor c = CanvasStyle::series(kSeries[i]);
        g->setPen(QPen(c, 1.5 * scale));
        g->setScatterStyle(QCPScatterStyle(kShapes[i], c, 6 * scale));
    }
    plot->legend->setFont(QFont());
}

FitErrorPlotRange fillFitErrorPlot(QCustomPlot* plot, const FitErrorPlotInput& in)
{
    FitOptions options;
    options.solver = in.solver;
    // One list of errors per line shown.
    std::vector<std::pair<int, std::vector<DegreeError>>> lines; // graph index, errors
    if (in.allParametrizations) {
        for (std::size_t i = 0; i < kPlottedParametrizations.size(); ++i) {
            options.parametrization = kPlottedParametrizations[i];
            lines.emplace_back(kFirstAllGraph + static_cast<int>(i), fitErrorByDegree(*in.points, options, in.lastDegree));
        }
    } else {
        options.parametrization = in.parametrization;
        lines.emplace_back(kCurrentGraph, fitErrorByDegree(*in.points, options, in.lastDegree));
    }
    // Log scale: an interpolating fit has error ~0; show it at a floor far below the rest.
    double largest = 0;
    for (const auto& line : lines)
        for (const DegreeError& e : line.second)
            if (e.ok)
                largest = std::max(largest, e.sse);
    const double floor = std::max(largest * 1e-20, std::numeric_limits<double>::min());
    for (int g = 0; g < plot->graphCount(); ++g)
        if (g != kCircleGraph)
            plot->graph(g)->data()->clear();
    int tried = 0;
    std::set<int> failed; // degrees, over every line
    QVector<double> cx, cy, all;
    const int circled = in.allParametrizations
                            ? kFirstAllGraph + static_cast<int>(std::find(kPlottedParametrizations.begin(),
                                                                          kPlottedParametrizations.end(), in.parametrization) -
                                                                kPlottedParametrizations.begin())
                            : kCurrentGraph;
    for (const auto& [graph, errors] : lines) {
        QVector<double> x, y;
        for (const DegreeError& e : errors) {
            tried = std::max(tried, e.degree);
            x << e.degree;
            if (!e.ok) {
                // The normal equations broke down at this degree: a gap (QCustomPlot breaks a
                // line at NaN), never a line drawn across the degrees that have no value.
                y << std::numeric_limits<double>::quiet_NaN();
                failed.insert(e.degree);
                continue;
            }
            y << std::max(e.sse, floor);
            if (graph == circled && e.degree == in.currentDegree) {
                cx << e.degree;
                cy << std::max(e.sse, floor);
            }
        }
        plot->graph(graph)->setData(x, y, true);
        for (double v : y)
            if (!std::isnan(v))
                all << v;
    }
    plot->graph(kCircleGraph)->setData(cx, cy, true);
    for (std::size_t i = 0; i < kPlottedParametrizations.size(); ++i) {
        QCPGraph* g = plot->graph(kFirstAllGraph + static_cast<int>(i));
        g->setName(in.names[i]);
        if (in.allParametrizations)
            g->addToLegend();
        else
            g->removeFromLegend();
    }
    plot->legend->setVisible(in.allParametrizations);
    // The axis ends at the last degree tried, the one the tab's note names when the plot stops
    // short: failed degrees at the end are gaps inside the range, not beyond it.
    plot->xAxis->setRange(0.5, std::max(tried, 2) + 0.5);
    if (!all.isEmpty()) {
        const auto [lo, hi] = std::minmax_element(all.begin(), all.end());
        plot->yAxis->setRange(*lo / 3, *hi * 3);
    }
    return {tried, static_cast<int>(failed.size())};
}

QCPGraph* fitErrorGraph(QCustomPlot* plot, Parametrization p, Parametrization current, bool allParametrizations)
{
    if (!allParametrizations)
        return p == current ? plot->graph(kCurrentGraph) : nullptr;
    const auto it = std::find(kPlottedParametrizations.begin(), kPlottedParametrizations.end(), p);
    return it == kPlottedParametrizations.end()
               ? nullptr
               : plot->graph(kFirstAllGraph + static_cast<int>(it - kPlottedParametrizations.begin()));
}

} // namespace granota::ui
