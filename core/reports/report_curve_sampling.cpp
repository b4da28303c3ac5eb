// docs/work-precision.md, curve sampling: the polyline drawn for a curve (the Matlab `part` samples) against
// the curve itself, uniform against adaptive subdivision.
#include "core/curves/bezier/adaptive_sampling.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/base/stopwatch.h"
#include "core/reports/work_precision_reports.h"

namespace granota::reports {

Expected<WorkPrecisionReport> curveSampling(const WorkPrecisionOptions& options)
{
    WorkPrecisionReport r;
    r.name = "curve-sampling";
    r.title = "Curve sampling: polyline against curve";
    r.knob = "points";
    r.error = "max distance between curve and polyline";
    r.reference = "the curve evaluated in long double between the samples";
    r.lesson = "Against the number of points, both errors fall like 1/N^2 (twice the points, a quarter of the "
               "error), and adaptive subdivision, which puts its points where the curve bends, needs fewer for "
               "the same error. Its run time per point is higher: each point costs a flatness test.";
    r.xAxis = WorkPrecisionAxis::Knob; // the lesson is about points, not seconds
    // Ex 2.2's control points: a quartic with a tight bend and a long flat stretch.
    const std::vector<Point> control = {{2, 3}, {-1, 8}, {-5, -3}, {3, 0}, {-7, -2}};
    const Progress progress(options);
    double sink = 0;

    WorkPrecisionSeries uniform{"uniform", {}};
    const int maxLevel = options.quick ? 8 : 12;
    WorkPrecisionSeries adaptive{"adaptive", {}};
    const int maxTolerance = options.quick ? 5 : 8;
    const double total = maxLevel + maxTolerance;
    for (int level = 1; level <= maxLevel; ++level) {
        const int samples = (1 << level) + 1;
        std::vector<double> t(static_cast<std::size_t>(samples));
        for (int j = 0; j < samples; ++j)
            t[static_cast<std::size_t>(j)] = j == samples - 1 ? 1.0 : j / double(samples - 1);
        const double seconds = secondsPerCall(
            [&] { return sampleBezier(control, samples).back().x; }, options.minSecondsPerPoint, &sink);
        uniform.samples.push_back({double(samples), polylineDeviation(control, t), seconds});
        if (!progress.tick(level, total))
            return cancelled();
    }
    for (int k = 1; k <= maxTolerance; ++k) {
        const double tolerance = std::pow(10.0, -k);
        const AdaptiveSample s = sampleBezierAdaptive(control, tolerance);
        const double seconds = secondsPerCall(
            [&] { return sampleBezierAdaptive(control, tolerance).points.back().x; }, options.minSecondsPerPoint,
            &sink);
        adaptive.samples.push_back({double(s.t.size()), polylineDeviation(control, s.t), seconds});
        if (!progress.tick(maxLevel + k, total))
            return cancelled();
    }
    r.series = {std::move(uniform), std::move(adaptive)};
    (void)sink;
    return r;
}

} // namespace granota::reports
