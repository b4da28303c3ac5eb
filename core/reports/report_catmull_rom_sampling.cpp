// docs/work-precision.md, Catmull-Rom sampling: the polyline drawn for a Catmull-Rom curve (§2.2, Def 2.10)
// against the curve itself, the same number of points on every segment (the Matlab
// `SegmentCatmullRom`, uniform in each segment's t) against adaptive subdivision of each segment.
#include "core/base/stopwatch.h"
#include "core/curves/bezier/adaptive_sampling.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/reports/work_precision_reports.h"

#include <algorithm>
#include <cmath>

namespace granota::reports {

namespace {

/// Each segment of the open curve through `q` as a cubic Bézier curve: Def 2.8 gives
/// p(0) = p_1, p(1) = p_2, p′(0) = τ(p_2 − p_0), p′(1) = τ(p_3 − p_1), and a cubic's
/// inner control points are its ends moved by a third of the end tangents.
std::vector<std::vector<Point>> bezierSegments(const std::vector<Point>& q, double tau)
{
    std::vector<std::vector<Point>> out;
    const auto quadruples = catmullRomQuadruples(q.size(), CatmullRomMode::Open);
    if (!quadruples)
        return out;
    for (const auto& k : *quadruples) {
        const auto at = [&q](int i) { return q[static_cast<std::size_t>(i)]; };
        const Point p1 = at(k[1]), p2 = at(k[2]);
        out.push_back({p1, p1 + (tau / 3) * (p2 - at(k[0])), p2 - (tau / 3) * (at(k[3]) - p1), p2});
    }
    return out;
}

/// Every segment at the parameters `t` of its own (all in [0, 1]).
double deviation(const std::vector<std::vector<Point>>& beziers, const std::vector<std::vector<double>>& t)
{
    double worst = 0;
    for (std::size_t i = 0; i < beziers.size(); ++i)
        worst = std::max(worst, polylineDeviation(beziers[i], t[i]));
    return worst;
}

} // namespace

Expected<WorkPrecisionReport> catmullRomSampling(const WorkPrecisionOptions& options)
{
    const WorkPrecisionReport r = samplingReport(
        "catmull-rom-sampling", "Catmull-Rom sampling: polyline against curve",
        "each segment as a cubic Bézier curve, evaluated in long double between the samples",
        "The same number of points on every segment wastes them on the short, gentle ones; adaptive "
        "subdivision of each segment puts them where the curve bends and needs fewer for the same "
        "error. Both errors fall like 1/N^2.");
    // Ex 2.13's points with one far point: segments of very different length and bend.
    const std::vector<Point> q = {{3, 5}, {2, 2}, {6, 0}, {8, 3}, {7, 5}, {30, 6}};
    const double tau = 0.5;
    const auto segments = catmullRomSegments(q, tau, CatmullRomMode::Open); // Lemma 2.3
    if (!segments)
        return segments.error();
    const std::vector<std::vector<Point>> beziers = bezierSegments(q, tau);
    const std::size_t count = beziers.size();
    double sink = 0;
    return withSamplingSeries(
        r, options, "uniform t per segment", options.quick ? 7 : 11,
        [&](int perSegment, const std::vector<double>& t) {
            const double seconds = secondsPerCall([&] { return sampleSegments(*segments, perSegment).back().x; },
                                                  options.minSecondsPerPoint, &sink);
            const double points = double(count) * (perSegment - 1) + 1; // the joins are shared
            return WorkPrecisionSample{points, deviation(beziers, std::vector<std::vector<double>>(count, t)), seconds};
        },
        options.quick ? 5 : 8,
        [&](double tolerance) {
            std::vector<std::vector<double>> t;
            double points = 1;
            for (const auto& b : beziers) {
                t.push_back(sampleBezierAdaptive(b, tolerance).t);
                points += double(t.back().size()) - 1;
            }
            const double seconds = secondsPerCall(
                [&] {
                    double last = 0;
                    for (const auto& b : beziers)
                        last += sampleBezierAdaptive(b, tolerance).points.back().x;
                    return last;
                },
                options.minSecondsPerPoint, &sink);
            return WorkPrecisionSample{points, deviation(beziers, t), seconds};
        });
}

} // namespace granota::reports
