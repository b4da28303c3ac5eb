#include "core/curves/fitting/fit_error_by_degree.h"

#include <algorithm>

namespace granota {

std::vector<DegreeError> fitErrorByDegree(const std::vector<Point>& q, FitOptions options, int maxDegree, std::size_t entryBudget,
                                          bool* truncated)
{
    std::vector<DegreeError> out;
    if (truncated)
        *truncated = false;
    if (q.size() < 2)
        return out;
    const int last = std::min(maxDegree, static_cast<int>(q.size()) - 1);
    for (int n = 1; n <= last; ++n) {
        if (q.size() * static_cast<std::size_t>(n + 1) > entryBudget) {
            if (truncated)
                *truncated = true;
            break;
        }
        options.degree = n;
        const Expected<FitResult> fit = fitBezier(q, options);
        DegreeError e;
        e.degree = n;
        e.ok = fit.ok();
        if (fit) {
            e.sse = fit->sse;
            e.cond = fit->cond;
        }
        out.push_back(e);
    }
    return out;
}

} // namespace granota
