#include "core/reports/work_precision.h"
#include "core/base/display_text.h"

#include "core/base/number_format.h"
#include "core/reports/work_precision_reports.h"

#include <cmath>

namespace granota {

const WorkPrecisionSeries* WorkPrecisionReport::find(std::string_view method) const
{
    for (const auto& s : series)
        if (s.method == method)
            return &s;
    return nullptr;
}

const char* toString(WorkPrecisionAxis axis) { return axis == WorkPrecisionAxis::Knob ? "knob" : "seconds"; }

std::vector<std::string> workPrecisionReportNames()
{
    return {"curve-sampling", "catmull-rom-sampling", "bezier-evaluation", "least-squares", "integrators", "energy-drift",
            "soft-body",      "arc-length",           "bspline-evaluation"};
}

Expected<WorkPrecisionReport> runWorkPrecisionReport(std::string_view name, const WorkPrecisionOptions& options)
{
    if (name == "curve-sampling")
        return reports::curveSampling(options);
    if (name == "catmull-rom-sampling")
        return reports::catmullRomSampling(options);
    if (name == "bezier-evaluation")
        return reports::bezierEvaluation(options);
    if (name == "least-squares")
        return reports::leastSquares(options);
    if (name == "integrators")
        return reports::integrators(options);
    if (name == "energy-drift")
        return reports::energyDrift(options);
    if (name == "soft-body")
        return reports::softBody(options);
    if (name == "arc-length")
        return reports::arcLength(options);
    if (name == "bspline-evaluation")
        return reports::bsplineEvaluation(options);
    std::string known;
    for (const auto& n : workPrecisionReportNames())
        known += (known.empty() ? "" : ", ") + n;
    return makeError(ErrorCode::InvalidInput, "unknown report " + quotedForDisplay(name) + " (" + known + ", all)");
}

namespace {
/// CSV fields never hold commas or quotes of their own in our reports, but be safe.
std::string csvField(const std::string& s)
{
    if (s.find_first_of(",\"\n") == std::string::npos)
        return s;
    std::string out = "\"";
    for (char c : s)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string full(double v) { return formatSignificant(v, 9); }
} // namespace

std::string workPrecisionCsv(const WorkPrecisionReport& report, const std::vector<std::string>& context)
{
    std::string out;
    out += "# report: " + report.name + "\n";
    out += "# title: " + report.title + "\n";
    out += "# knob: " + report.knob + "\n";
    out += "# error: " + report.error + "\n";
    out += "# reference: " + report.reference + "\n";
    out += "# lesson: " + report.lesson + "\n";
    // The x axis names its column: "seconds", or the knob's ("knob"; "step" in energy-drift).
    const bool againstSeconds = report.timed && report.xAxis == WorkPrecisionAxis::Seconds;
    out += "# x axis: " + (againstSeconds ? std::string(toString(WorkPrecisionAxis::Seconds)) : report.knobColumn) + "\n";
    for (const auto& line : context)
        out += "# " + line + "\n";
    out += "method," + report.knobColumn + "," + report.errorColumn + (report.timed ? ",seconds\n" : "\n");
    for (const auto& s : report.series)
        for (const auto& p : s.samples)
            out += csvField(s.method) + "," + full(p.knob) + "," + full(p.error) +
                   (report.timed ? "," + full(p.seconds) + "\n" : "\n");
    return out;
}

double observedOrder(const WorkPrecisionSeries& series, double knobMin, double knobMax)
{
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& p : series.samples) {
        if (p.knob < knobMin || p.knob > knobMax || !(p.error > 0) || !(p.knob > 0))
            continue;
        const double x = std::log(p.knob), y = std::log(p.error);
        n += 1;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double d = n * sxx - sx * sx;
    return n >= 2 && d != 0 ? (n * sxy - sx * sy) / d : std::nan("");
}

namespace reports {
Error cancelled() { return makeError(ErrorCode::Cancelled, "cancelled"); }

WorkPrecisionReport samplingReport(std::string name, std::string title, std::string reference, std::string lesson)
{
    WorkPrecisionReport r;
    r.name = std::move(name);
    r.title = std::move(title);
    r.knob = "points";
    r.error = "max distance between curve and polyline";
    r.reference = std::move(reference);
    r.lesson = std::move(lesson);
    r.xAxis = WorkPrecisionAxis::Knob;
    return r;
}

Expected<WorkPrecisionReport> withSamplingSeries(
    WorkPrecisionReport report, const WorkPrecisionOptions& options, const std::string& uniformName, int maxLevel,
    const std::function<WorkPrecisionSample(int, const std::vector<double>&)>& uniformAt, int maxTolerance,
    const std::function<WorkPrecisionSample(double)>& adaptiveAt)
{
    const Progress progress(options);
    WorkPrecisionSeries uniform{uniformName, {}}, adaptive{"adaptive", {}};
    const double total = maxLevel + maxTolerance;
    for (int level = 1; level <= maxLevel; ++level) {
        const int samples = (1 << level) + 1;
        std::vector<double> t(static_cast<std::size_t>(samples));
        for (int j = 0; j < samples; ++j)
            t[static_cast<std::size_t>(j)] = j == samples - 1 ? 1.0 : j / double(samples - 1);
        uniform.samples.push_back(uniformAt(samples, t));
        if (!progress.tick(level, total))
            return cancelled();
    }
    for (int k = 1; k <= maxTolerance; ++k) {
        adaptive.samples.push_back(adaptiveAt(std::pow(10.0, -k)));
        if (!progress.tick(maxLevel + k, total))
            return cancelled();
    }
    report.series = {std::move(uniform), std::move(adaptive)};
    return report;
}
} // namespace reports

} // namespace granota
