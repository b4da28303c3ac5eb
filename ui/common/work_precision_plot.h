#pragma once
/// \file work_precision_plot.h
/// Work-precision plots (docs/work-precision.md): error against run time (or against the knob, e.g. the
/// number of points) on log–log axes, one series per method, with the knob's values written
/// beside the markers when the x axis is the run time. The same code draws the tab's
/// plot and the CLI's SVG and PNG files.

#include "core/reports/work_precision.h"

#include <QString>

#include <optional>

class QCustomPlot;

namespace granota::ui {

/// The translated title, method names and lesson of a report (the core speaks English).
QString reportTitle(const WorkPrecisionReport& report);
QString reportLesson(const WorkPrecisionReport& report);
QString reportMethod(const std::string& method);
QString reportKnob(const WorkPrecisionReport& report);
QString reportError(const WorkPrecisionReport& report);
/// The x axis title: "run time per call (s)", or the knob as a quantity ("points of the polyline …").
QString reportAxisTitle(const WorkPrecisionReport& report, WorkPrecisionAxis axis);

/// Replaces the plot's content by the report: log–log axes (x: run time in seconds or the
/// knob, `axis`, by default the report's own; y: error), a graph with markers per method, a
/// legend and, against run time, the knob values as labels.
void plotWorkPrecision(QCustomPlot* plot, const WorkPrecisionReport& report, double styleScale = 1.0,
                       std::optional<WorkPrecisionAxis> axis = std::nullopt);
/// Empties the plot: no graph, no label, no axis title, no legend (no report to show yet).
void clearWorkPrecisionPlot(QCustomPlot* plot);

} // namespace granota::ui
