#include "core/curves/bezier/de_casteljau.h"

#include <algorithm>

namespace granota {

std::vector<Point> sampleBezier(const std::vector<Point>& controlPoints, int samples)
{
    assert(!controlPoints.empty() && samples >= 2);
    std::vector<Point> out;
    out.reserve(static_cast<std::size_t>(samples));
    std::vector<Point> work(controlPoints.size());
    const double u0 = 1.0 / (samples - 1);
    for (int j = 0; j < samples; ++j) {
        // Exact ends: t = 1 must give P_n, not P_n + rounding.
        const double t = j == samples - 1 ? 1.0 : j * u0;
        std::copy(controlPoints.begin(), controlPoints.end(), work.begin());
        out.push_back(deCasteljauInPlace(work, t));
    }
    return out;
}

} // namespace granota
