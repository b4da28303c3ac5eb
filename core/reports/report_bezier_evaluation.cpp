// docs/work-precision.md, Bézier evaluation at degree n: De Casteljau (Def 2.4) against the Bernstein sum
// (Def 2.6) and Horner's rule on the power basis, against exact rational arithmetic.
#include "core/curves/bezier/bernstein.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bezier/power_basis.h"
#include "core/exact/rational.h"
#include "core/base/stopwatch.h"
#include "core/reports/work_precision_reports.h"

#include <algorithm>
#include <cmath>

namespace granota::reports {

namespace {

/// Reproducible control points: small integers from a linear congruential generator.
std::vector<Point> integerControlPoints(int count, unsigned seed)
{
    std::vector<Point> p;
    unsigned s = seed;
    auto next = [&s] {
        s = s * 1664525u + 1013904223u;
        return static_cast<int>((s >> 16) % 21) - 10;
    };
    for (int i = 0; i < count; ++i) {
        const double x = next();
        p.emplace_back(x, next());
    }
    return p;
}

} // namespace

std::vector<Point> reportControlPoints(int count, unsigned seed) { return integerControlPoints(count, seed); }

Expected<WorkPrecisionReport> bezierEvaluation(const WorkPrecisionOptions& options)
{
    WorkPrecisionReport r;
    r.name = "bezier-evaluation";
    r.title = "Evaluating a Bézier curve of degree n";
    r.knob = "degree";
    r.error = "max |c(t) - exact| / max |P_i| over 33 values of t";
    r.reference = "exact rational De Casteljau (GMP)";
    r.lesson = "De Casteljau and the Bernstein sum stay at rounding level at every degree; Horner on "
               "the power basis loses digits as the degree grows, because its coefficients are huge "
               "alternating sums that cancel.";
    const Progress progress(options);
    const int maxDegree = options.quick ? 30 : 60;
    const int step = options.quick ? 4 : 2;
    constexpr int kValues = 33; // t = j/32: exact in binary, so the reference sees the same t
    WorkPrecisionSeries casteljau{"De Casteljau", {}}, bernsteinSum{"Bernstein sum", {}}, horner{"Horner (power basis)", {}};
    double sink = 0;
    for (int n = 2; n <= maxDegree; n += step) {
        const std::vector<Point> control = integerControlPoints(n + 1, 12345u + static_cast<unsigned>(n));
        const std::vector<RPoint> exactControl = toRational(control);
        double scale = 0;
        for (const Point& p : control)
            scale = std::max(scale, norm(p));
        const auto power = bezierToPowerBasis(control);
        std::vector<Point> work(control.size());
        double eCasteljau = 0, eBernstein = 0, eHorner = 0;
        for (int j = 0; j < kValues; ++j) {
            const double t = j / double(kValues - 1);
            const RPoint exact = deCasteljauPoint(exactControl, exactRational(t));
            const Point ref(exact.x.get_d(), exact.y.get_d());
            std::copy(control.begin(), control.end(), work.begin());
            eCasteljau = std::max(eCasteljau, distance(deCasteljauInPlace(work, t), ref));
            eBernstein = std::max(eBernstein, distance(bezierBernstein(control, t), ref));
            eHorner = std::max(eHorner, distance(evaluateHorner(power, t), ref));
        }
        auto timeOf = [&](auto&& evaluate) {
            return secondsPerCall(
                       [&] {
                           double acc = 0;
                           for (int j = 0; j < kValues; ++j)
                               acc += evaluate(j / double(kValues - 1)).x;
                           return acc;
                       },
                       options.minSecondsPerPoint, &sink) /
                   kValues;
        };
        const double tCasteljau = timeOf([&](double t) {
            std::copy(control.begin(), control.end(), work.begin());
            return deCasteljauInPlace(work, t);
        });
        const double tBernstein = timeOf([&](double t) { return bezierBernstein(control, t); });
        const double tHorner = timeOf([&](double t) { return evaluateHorner(power, t); });
        casteljau.samples.push_back({double(n), std::max(eCasteljau / scale, kErrorFloor), tCasteljau});
        bernsteinSum.samples.push_back({double(n), std::max(eBernstein / scale, kErrorFloor), tBernstein});
        horner.samples.push_back({double(n), std::max(eHorner / scale, kErrorFloor), tHorner});
        if (!progress.tick(n, maxDegree))
            return cancelled();
    }
    r.series = {std::move(casteljau), std::move(bernsteinSum), std::move(horner)};
    return r;
}

} // namespace granota::reports
