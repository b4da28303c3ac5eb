#pragma once
/// \file work_precision_plot.h
/// Work-precision plots (docs/work-precision.md): error against run time on log–log axes, one series per
/// method, with the knob's values written beside the markers. The same code draws the tab's
/// plot and the CLI's SVG and PNG files.

#include "core/reports/work_precision.h"

#include <QString>

class QCustomPlot;

namespace granota::ui {

/// The translated title, method names and lesson of a report (the core speaks English).
QString reportTitle(const WorkPrecisionReport& report);
QString reportLesson(const WorkPrecisionReport& report);
QString reportMethod(const std::string& method);
QString reportKnob(const WorkPrecisionReport& report);
QString reportError(const WorkPrecisionReport& report);

/// Replaces the plot's content by the report: log–log axes (run time in seconds, error),
/// a graph with markers per method, a legend and the knob values as labels.
void plotWorkPrecision(QCustomPlot* plot, const WorkPrecisionReport& report, double styleScale = 1.0);
/// Empties the plot: no graph, no label, no axis title, no legend (no report to show yet).
void clearWorkPrecisionPlot(QCustomPlot* plot);

} // namespace granota::ui
