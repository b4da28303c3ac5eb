// docs/work-precision.md, curve sampling: the polyline drawn for a curve (the Matlab `part` samples) against
// the curve itself, uniform against adaptive subdivision.
#include "core/curves/bezier/adaptive_sampling.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/base/stopwatch.h"
#include "core/reports/work_precision_reports.h"

namespace granota::reports {

Expected<WorkPrecisionReport> curveSampling(const WorkPrecisionOptions& options)
{
    const WorkPrecisionReport r = samplingReport(
        "curve-sampling", "Curve sampling: polyline against curve", "the curve evaluated in long double between the samples",
        "Against the number of points, both errors fall like 1/N^2 (twice the points, a quarter of the "
        "error), and adaptive subdivision, which puts its points where the curve bends, needs fewer for "
        "the same error. Its run time per point is higher: each point costs a flatness test.");
    // Ex 2.2's control points: a quartic with a tight bend and a long flat stretch.
    const std::vector<Point> control = {{2, 3}, {-1, 8}, {-5, -3}, {3, 0}, {-7, -2}};
    double sink = 0;
    return withSamplingSeries(
        r, options, "uniform", options.quick ? 8 : 12,
        [&](int samples, const std::vector<double>& t) {
            const double seconds = secondsPerCall([&] { return sampleBezier(control, samples).back().x; },
                                                  options.minSecondsPerPoint, &sink);
            return WorkPrecisionSample{double(samples), polylineDeviation(control, t), seconds};
        },
        options.quick ? 5 : 8,
        [&](double tolerance) {
            const AdaptiveSample s = sampleBezierAdaptive(control, tolerance);
            const double seconds = secondsPerCall([&] { return sampleBezierAdaptive(control, tolerance).points.back().x; },
                                                  options.minSecondsPerPoint, &sink);
            return WorkPrecisionSample{double(s.t.size()), polylineDeviation(control, s.t), seconds};
        });
}

} // namespace granota::reports
