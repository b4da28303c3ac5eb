// Google Benchmark: the curve hot paths (issue: speed). How cost grows with the size of the
// work — degree, samples, data points — is printed by the Complexity() fits.
//   build/bin/granota-bench --benchmark_filter='Fit|Outline|DeCasteljau'
#include "core/curves/bezier/arc_length.h"
#include "core/curves/bezier/bernstein.h"
#include "core/curves/bezier/closest_point.h"
#include "core/curves/bezier/curve_features.h"
#include "core/curves/bezier/degree_elevation.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/fitting/least_squares_fit.h"
#include "core/softbody/outline.h"
#include "core/curves/bezier/power_basis.h"
#include "core/softbody/regular_polygon.h"

#include <benchmark/benchmark.h>

#include <cmath>

using namespace granota;

namespace {

std::vector<Point> wavyPoints(int count)
{
    std::vector<Point> p;
    p.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const double t = i / double(std::max(count - 1, 1));
        p.emplace_back(10 * t, std::sin(6 * t) + 0.3 * std::cos(17 * t));
    }
    return p;
}

void BM_DeCasteljauPoint(benchmark::State& state)
{
    const auto control = wavyPoints(static_cast<int>(state.range(0)) + 1);
    std::vector<Point> work(control.size());
    double t = 0.37;
    for (auto _ : state) {
        std::copy(control.begin(), control.end(), work.begin());
        benchmark::DoNotOptimize(deCasteljauInPlace(work, t));
    }
    state.SetComplexityN(state.range(0));
}

void BM_BernsteinPoint(benchmark::State& state)
{
    const auto control = wavyPoints(static_cast<int>(state.range(0)) + 1);
    for (auto _ : state)
        benchmark::DoNotOptimize(bezierBernstein(control, 0.37));
    state.SetComplexityN(state.range(0));
}

void BM_HornerPoint(benchmark::State& state)
{
    const auto power = bezierToPowerBasis(wavyPoints(static_cast<int>(state.range(0)) + 1));
    for (auto _ : state)
        benchmark::DoNotOptimize(evaluateHorner(power, 0.37));
    state.SetComplexityN(state.range(0));
}

/// The De Casteljau tab's curve at degree 30, sampled for the screen: what a drag recomputes.
void BM_SampleBezier(benchmark::State& state)
{
    const auto control = wavyPoints(31);
    const int samples = static_cast<int>(state.range(0));
    for (auto _ : state)
        benchmark::DoNotOptimize(sampleBezier(control, samples));
    state.SetComplexityN(samples);
}

void BM_CatmullRomSample(benchmark::State& state)
{
    const auto points = wavyPoints(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        auto segments = catmullRomSegments(points, 0.5, CatmullRomMode::Open);
        benchmark::DoNotOptimize(sampleSegments(*segments, 32));
    }
    state.SetComplexityN(state.range(0));
}

/// A least-squares fit of k points at degree n (QR, the default): k = 10² … 10⁶, n = 3 … 30.
void BM_FitBezier(benchmark::State& state)
{
    const auto data = wavyPoints(static_cast<int>(state.range(0)));
    FitOptions options;
    options.degree = static_cast<int>(state.range(1));
    for (auto _ : state)
        benchmark::DoNotOptimize(fitBezier(data, options));
    state.SetComplexityN(state.range(0));
    state.counters["ns_per_point"] = benchmark::Counter(
        static_cast<double>(state.range(0)), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

/// §4.9/4.10: the per-frame least-squares Bézier fit of the frog's outline that the thesis
/// abandoned as too costly — with M⁺ computed once, one frame's fit is a small product.
void BM_OutlineFit(benchmark::State& state)
{
    const int sides = 10;
    OutlineFitter fitter(sides, static_cast<int>(state.range(0)));
    std::vector<Point> vertices = regularPolygon(Point(640, 360), 120, sides), control;
    for (auto _ : state) {
        vertices[3].x += 1e-9; // a new frame's outline
        fitter.fit(vertices, control);
        benchmark::DoNotOptimize(control.data());
    }
}

/// Extrema of x and y, the tight box, inflections and cusps of a wavy degree-n curve: the
/// roots of three Bernstein polynomials (degrees n − 1, n − 1, 2n − 4) and of the cusp test.
void BM_CurveFeatures(benchmark::State& state)
{
    auto control = wavyPoints(static_cast<int>(state.range(0)) + 1);
    for (auto _ : state) {
        control[2].y += 1e-12; // a new drag position
        benchmark::DoNotOptimize(curveFeatures(control));
    }
    state.SetComplexityN(state.range(0));
}

/// The global closest point on a wavy degree-n curve to a point that moves over its box.
void BM_ClosestPoint(benchmark::State& state)
{
    const auto control = wavyPoints(static_cast<int>(state.range(0)) + 1);
    int k = 0;
    for (auto _ : state) {
        const Point p(0.37 * (k % 29), -1.5 + 0.11 * (k % 31));
        ++k;
        benchmark::DoNotOptimize(closestPoint(control, p));
    }
    state.SetComplexityN(state.range(0));
}

/// The length of a degree-n curve (wavy control points) to the default 1e-13 relative
/// tolerance. Targets: cubic < 1 µs, degree 10 < 5 µs.
void BM_ArcLength(benchmark::State& state)
{
    const auto p = wavyPoints(static_cast<int>(state.range(0)) + 1);
    for (auto _ : state)
        benchmark::DoNotOptimize(arcLength(p));
}

/// Harder degree-10 curves than the wavy one, for the same kernels: 0 a curve that winds
/// round a tight turn (|c′| small and curvature large there: many panels for the length),
/// 1 the cusp cubic (0,0) (1,1) (0,1) (1,0) raised to degree 10 (c′ = 0 at t = 1/2: the
/// length is split there, and x′, y′ and the curvature numerator have multiple roots).
std::vector<Point> hardCurve(int which)
{
    if (which == 0)
        return {{0, 0}, {4, 3}, {6, 5}, {5, 7}, {3, 6}, {2, 4}, {3, 2}, {5, 1}, {7, 2}, {9, 3}, {10, 0}};
    std::vector<Point> p{{0, 0}, {1, 1}, {0, 1}, {1, 0}};
    while (p.size() < 11)
        p = elevateDegree(p);
    return p;
}

void BM_ArcLengthHard(benchmark::State& state)
{
    const auto p = hardCurve(static_cast<int>(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(arcLength(p));
}

void BM_CurveFeaturesHard(benchmark::State& state)
{
    auto control = hardCurve(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        control[2].y += 1e-12; // a new drag position
        benchmark::DoNotOptimize(curveFeatures(control));
    }
}

/// t(s) on a built parametrization: constant-speed playback asks for one per frame.
void BM_ArcLengthInverse(benchmark::State& state)
{
    const ArcLengthParametrization a(wavyPoints(static_cast<int>(state.range(0)) + 1));
    double s = 0;
    for (auto _ : state) {
        s += 0.618 * a.total();
        if (s > a.total())
            s -= a.total();
        benchmark::DoNotOptimize(a.parameterAt(s));
    }
}

} // namespace

BENCHMARK(BM_CurveFeatures)->Arg(3)->Arg(10)->Arg(30)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ClosestPoint)->Arg(3)->Arg(10)->Arg(30)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ArcLength)->Arg(3)->Arg(10)->Arg(30)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_ArcLengthHard)->Arg(0)->Arg(1)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_CurveFeaturesHard)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ArcLengthInverse)->Arg(3)->Arg(10)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_DeCasteljauPoint)->DenseRange(3, 30, 9)->Arg(60)->Complexity(benchmark::oNSquared);
BENCHMARK(BM_BernsteinPoint)->DenseRange(3, 30, 9)->Arg(60)->Complexity(benchmark::oN);
BENCHMARK(BM_HornerPoint)->DenseRange(3, 30, 9)->Arg(60)->Complexity(benchmark::oN);
BENCHMARK(BM_SampleBezier)->Arg(100)->Arg(400)->Arg(1600)->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oN);
BENCHMARK(BM_CatmullRomSample)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oN);
BENCHMARK(BM_FitBezier)->ArgsProduct({{100, 1000, 10000, 100000, 1000000}, {3, 10, 30}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OutlineFit)->Arg(3)->Arg(5)->Unit(benchmark::kNanosecond);
