#include "app/cli/run_budget.h"

#include "core/base/input_limits.h"
#include "core/base/number_format.h"
#include "core/softbody/step_cost.h"

#include <cmath>

namespace granota::cli {

std::string roughDuration(double nanoseconds)
{
    const double s = nanoseconds / 1e9;
    // Two significant digits: an estimate, not a measurement.
    const auto rough = [](double v, const char* unit) {
        return (v < 10 ? formatSignificant(v, 2) : formatDouble(std::round(v))) + " " + unit;
    };
    if (!(s < 1e300))
        return "forever";
    if (s < 1e-3)
        return rough(s * 1e6, "µs");
    if (s < 1)
        return rough(s * 1e3, "ms");
    if (s < 120)
        return rough(s, "s");
    if (s < 7200)
        return rough(s / 60, "min");
    if (s < 48 * 3600)
        return rough(s / 3600, "h");
    return rough(s / 86400, "days");
}

Expected<void> checkRunWork(const Simulation& s, long long steps, int copies)
{
    const double perStep = estimatedStepNanoseconds(s) * copies;
    const double total = perStep * static_cast<double>(steps);
    if (total <= kMaxRunNanoseconds)
        return {};
    const long long vertices = static_cast<long long>(s.pointCount()) * copies;
    std::string what = std::to_string(steps) + " steps of " + std::to_string(vertices) + " vertices on the " +
                       solverName(s.solver()) + " solver";
    if (s.solver() == SolverKind::Stable)
        what += " (" + std::to_string(s.substeps()) + " substeps; a body of n sides also checks its n²/2 pairs of edges)";
    return makeError(ErrorCode::OutOfRange, what + " would take about " + roughDuration(total) + " (" + roughDuration(perStep) +
                                                " a step, estimated), more than the " + roughDuration(kMaxRunNanoseconds) +
                                                " a run may take: lower --steps, or bodies or sides");
}

} // namespace granota::cli
