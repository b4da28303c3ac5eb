#pragma once
/// \file work_precision_reports.h
/// The reports of docs/work-precision.md, one file each (report_*.cpp); run through
/// runWorkPrecisionReport(), which checks the name and handles cancelling.

#include "core/base/vec2.h"
#include "core/reports/work_precision.h"

#include <functional>
#include <string>
#include <vector>

namespace granota::reports {

/// The smallest error a report plots: an exact result (error 0) drawn on a log axis.
inline constexpr double kErrorFloor = 1e-18;

/// Progress and cancelling shared by the reports: `tick(done, total)` returns false when
/// the user cancelled.
class Progress {
public:
    explicit Progress(const WorkPrecisionOptions& options) : m_options(options) {}
    bool tick(double done, double total) const
    {
        return !m_options.progress || m_options.progress(total > 0 ? done / total : 1.0);
    }

private:
    const WorkPrecisionOptions& m_options;
};

Expected<WorkPrecisionReport> curveSampling(const WorkPrecisionOptions& options);
Expected<WorkPrecisionReport> catmullRomSampling(const WorkPrecisionOptions& options);
Expected<WorkPrecisionReport> bezierEvaluation(const WorkPrecisionOptions& options);
Expected<WorkPrecisionReport> leastSquares(const WorkPrecisionOptions& options);
Expected<WorkPrecisionReport> integrators(const WorkPrecisionOptions& options);
Expected<WorkPrecisionReport> energyDrift(const WorkPrecisionOptions& options);
Expected<WorkPrecisionReport> softBody(const WorkPrecisionOptions& options);
Expected<WorkPrecisionReport> arcLength(const WorkPrecisionOptions& options);
Expected<WorkPrecisionReport> bsplineEvaluation(const WorkPrecisionOptions& options);

/// The arc-length report's curves with their reference lengths (exact where known).
struct ArcLengthCurve {
    std::string name;
    std::vector<Point> points;
    double length = 0;
};
std::vector<ArcLengthCurve> arcLengthReportCurves();
/// One 24-point Gauss–Legendre rule on each of `pieces` equal pieces of [0, 1] (1 piece: what
/// bezier-js computes).
double gaussLegendre24Length(const std::vector<Point>& p, int pieces);

/// Reproducible control points with small integer coordinates in [−10, 10].
std::vector<Point> reportControlPoints(int count, unsigned seed);

/// The error every report returns when cancelled.
Error cancelled();

/// A sampling report's description: knob "points", error "max distance between curve and
/// polyline", plotted against the points (its lesson is about points, not seconds).
WorkPrecisionReport samplingReport(std::string name, std::string title, std::string reference, std::string lesson);

/// `report` with the two series of a sampling report: `uniformAt(N, t)` measures uniform
/// sampling with N = 2^L + 1 equally spaced parameters t (t.back() exactly 1), L = 1 … maxLevel;
/// `adaptiveAt(tolerance)` adaptive subdivision to tolerance 10^-1 … 10^-maxTolerance. Ticks
/// the progress after each; cancelled() when it says stop.
Expected<WorkPrecisionReport> withSamplingSeries(
    WorkPrecisionReport report, const WorkPrecisionOptions& options, const std::string& uniformName, int maxLevel,
    const std::function<WorkPrecisionSample(int, const std::vector<double>&)>& uniformAt, int maxTolerance,
    const std::function<WorkPrecisionSample(double)>& adaptiveAt);

} // namespace granota::reports
