#include "core/curves/splines/curvature_profile.h"

#include "core/curves/bezier/arc_length.h"
#include "core/curves/bezier/curvature.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace granota {

CurvatureProfile curvatureProfile(const std::vector<std::vector<Point>>& segments, int samplesPerSegment)
{
    assert(samplesPerSegment >= 2);
    samplesPerSegment = std::max(samplesPerSegment, 2);
    CurvatureProfile out;
    out.samples.reserve(segments.size());
    out.knots.reserve(segments.size() + 1);
    double start = 0;
    for (const auto& P : segments) {
        out.knots.push_back(start);
        std::vector<CurvatureSample> row;
        if (P.empty()) {
            out.samples.push_back(std::move(row));
            continue;
        }
        const ArcLengthParametrization arc(P);
        const double L = std::isfinite(arc.total()) ? arc.total() : 0.0;
        row.reserve(static_cast<std::size_t>(samplesPerSegment));
        for (int j = 0; j < samplesPerSegment; ++j) {
            // Equal steps of arc length, ends exactly at t = 0 and t = 1.
            const double local = j == samplesPerSegment - 1 ? L : L * j / (samplesPerSegment - 1);
            const double t = j == 0 ? 0.0 : j == samplesPerSegment - 1 ? 1.0 : arc.parameterAt(local);
            CurvatureSample sample;
            sample.s = start + local;
            sample.kappa = curvatureAt(P, t).curvature;
            if (sample.kappa && !std::isfinite(*sample.kappa))
                sample.kappa.reset();
            row.push_back(sample);
        }
        out.samples.push_back(std::move(row));
        start += L;
    }
    out.knots.push_back(start);
    return out;
}

} // namespace granota
