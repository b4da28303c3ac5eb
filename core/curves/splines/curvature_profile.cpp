#include "core/curves/splines/curvature_profile.h"

#include "core/curves/bezier/arc_length.h"
#include "core/curves/bezier/curvature.h"
#include "core/curves/bezier/rational_bezier.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace granota {

namespace {

/// A polynomial segment's κ at equal steps of arc length, the ends exactly at t = 0 and t = 1,
/// its s counted from `start`; its length in `length`.
std::vector<CurvatureSample> polynomialSegmentSamples(const std::vector<Point>& P, double start, int samplesPerSegment,
                                                      double& length)
{
    std::vector<CurvatureSample> row;
    length = 0;
    if (P.empty())
        return row;
    const ArcLengthParametrization arc(P);
    const double L = std::isfinite(arc.total()) ? arc.total() : 0.0;
    row.reserve(static_cast<std::size_t>(samplesPerSegment));
    for (int j = 0; j < samplesPerSegment; ++j) {
        const double local = j == samplesPerSegment - 1 ? L : L * j / (samplesPerSegment - 1);
        const double t = j == 0 ? 0.0 : j == samplesPerSegment - 1 ? 1.0 : arc.parameterAt(local);
        CurvatureSample sample;
        sample.s = start + local;
        sample.kappa = curvatureAt(P, t).curvature;
        if (sample.kappa && !std::isfinite(*sample.kappa))
            sample.kappa.reset();
        row.push_back(sample);
    }
    length = L;
    return row;
}

} // namespace

CurvatureProfile curvatureProfile(const std::vector<std::vector<Point>>& segments, int samplesPerSegment)
{
    return curvatureProfile(segments, {}, samplesPerSegment);
}

CurvatureProfile curvatureProfile(const std::vector<std::vector<Point>>& segments,
                                  const std::vector<std::vector<double>>& weights, int samplesPerSegment)
{
    assert(samplesPerSegment >= 2);
    samplesPerSegment = std::max(samplesPerSegment, 2);
    CurvatureProfile out;
    out.samples.reserve(segments.size());
    out.knots.reserve(segments.size() + 1);
    double start = 0;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const auto& P = segments[i];
        const std::vector<double> none;
        const auto& w = i < weights.size() ? weights[i] : none;
        if (w.empty() || P.empty()) { // polynomial: equal steps of arc length
            double length = 0;
            out.knots.push_back(start);
            out.samples.push_back(polynomialSegmentSamples(P, start, samplesPerSegment, length));
            start += length;
            continue;
        }
        assert(w.size() == P.size());
        out.knots.push_back(start);
        std::vector<CurvatureSample> row;
        row.reserve(static_cast<std::size_t>(samplesPerSegment));
        double s = start, previous = 0;
        for (int j = 0; j < samplesPerSegment; ++j) {
            const double t = j == samplesPerSegment - 1 ? 1.0 : static_cast<double>(j) / (samplesPerSegment - 1);
            if (j > 0) {
                const double piece = rationalArcLength(P, w, previous, t);
                s += std::isfinite(piece) ? piece : 0.0;
            }
            previous = t;
            CurvatureSample sample;
            sample.s = s;
            sample.kappa = rationalCurvatureAt(P, w, t).curvature;
            if (sample.kappa && !std::isfinite(*sample.kappa))
                sample.kappa.reset();
            row.push_back(sample);
        }
        out.samples.push_back(std::move(row));
        start = s;
    }
    out.knots.push_back(start);
    return out;
}

} // namespace granota
