#pragma once
/// \file work_precision.h
/// Error against run time for every numerical method (docs/work-precision.md): a report measures, for
/// each method, the error against an independent reference (exact rationals, long double
/// or a known analytic solution) and the run time, over a range of the method's knob
/// (samples, degree, step size, substeps). The GUI plots it in the tab it belongs to; the
/// CLI writes it as CSV, SVG and PNG (`granota-cli report NAME --out DIR`).

#include "core/base/expected.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace granota {

struct WorkPrecisionSample {
    double knob = 0;    ///< the method's setting: samples, degree, step size h, substeps
    double error = 0;   ///< against the reference, in the report's unit; signed in energy-drift (E/E0 - 1)
    double seconds = 0; ///< run time of one call at this setting (0 in an untimed report)
};

struct WorkPrecisionSeries {
    std::string method; ///< e.g. "De Casteljau", "normal equations", "Verlet"
    std::vector<WorkPrecisionSample> samples;
};

/// What a report's plot puts on its x axis (the y axis is always the error).
enum class WorkPrecisionAxis {
    Seconds, ///< the run time per call: the work-precision plot proper
    Knob,    ///< the knob itself, e.g. the number of points: what the cost is counted in
};

/// "seconds" or "knob": the CSV column the x axis is drawn from (the `# x axis:` line).
const char* toString(WorkPrecisionAxis axis);

struct WorkPrecisionReport {
    std::string name;      ///< curve-sampling, …, integrators, energy-drift, soft-body, arc-length
    std::string title;     ///< English; the GUI translates it
    std::string knob;      ///< what the knob is: "samples", "degree", "step h", "substeps"
    std::string error;     ///< what the error is: "max distance to the curve", …
    std::string reference; ///< what the error is measured against
    std::string lesson;    ///< the one sentence the plot teaches
    /// The x axis the lesson reads from. The sampling reports count their cost in points
    /// (evaluations of the curve): their run time also pays for choosing the points.
    WorkPrecisionAxis xAxis = WorkPrecisionAxis::Seconds;
    /// false: nothing is timed (energy-drift follows one run step by step, the knob is the step
    /// number): the CSV has no seconds column and the plot is against the knob only.
    bool timed = true;
    /// The CSV's names of the knob and error columns (energy-drift: "step" and "energy_error").
    std::string knobColumn = "knob";
    std::string errorColumn = "error";
    /// > 0: the plot's error axis ends here, so that a series growing without bound (explicit
    /// Euler's energy) leaves the frame instead of squeezing the others into its bottom.
    double plotErrorCeiling = 0;
    std::vector<WorkPrecisionSeries> series;

    const WorkPrecisionSeries* find(std::string_view method) const;
};

struct WorkPrecisionOptions {
    /// Each measurement repeats its work for at least this long (s). Tests use a tiny value:
    /// they check the errors, never the times.
    double minSecondsPerPoint = 2e-3;
    /// Fewer and cheaper settings (tests, quick previews).
    bool quick = false;
    /// Called with the fraction done (0..1); returning false cancels the report.
    std::function<bool(double)> progress;
};

/// curve-sampling, catmull-rom-sampling, bezier-evaluation, least-squares, integrators,
/// energy-drift, soft-body, arc-length, bspline-evaluation.
std::vector<std::string> workPrecisionReportNames();

/// Runs a report. Errors: an unknown name, or "cancelled" when `progress` returned false.
Expected<WorkPrecisionReport> runWorkPrecisionReport(std::string_view name, const WorkPrecisionOptions& options = {});

/// The report as CSV: `# key: value` header lines (title, knob, error, reference, lesson,
/// x axis and each line of `context`, e.g. machine and build type), then `method,knob,error,seconds`
/// (an untimed report: `method,<knobColumn>,<errorColumn>`, e.g. `method,step,energy_error`).
std::string workPrecisionCsv(const WorkPrecisionReport& report, const std::vector<std::string>& context);

/// Least-squares slope of log(error) against log(knob) over the samples with knob in
/// [knobMin, knobMax] and error > 0: the observed order of convergence (integrators:
/// error ~ h^p gives slope p).
double observedOrder(const WorkPrecisionSeries& series, double knobMin, double knobMax);

} // namespace granota
