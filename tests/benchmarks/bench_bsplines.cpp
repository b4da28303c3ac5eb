// Google Benchmark: B-spline evaluation (issue 36, "Speed"; docs/bsplines.md#speed-and-peers).
//   build/bin/granota-bench --benchmark_filter='BSpline|DeBoor'
// A cubic B-spline with 10⁴ control points evaluated at 10⁶ parameters by Granota's
// bsplinePoint (de_boor.h) and by Eigen's Splines module on the same data in the same binary;
// scipy's BSpline on the same data is tests/benchmarks/peer/scipy_bspline.py (targets.sh prints
// the ratios). And exact de Boor (Rational) at degree 10, the net a drag redraws.
#include "bench_smoke.h"
#include "core/curves/bsplines/bspline_sampling.h"
#include "core/curves/bsplines/de_boor.h"
#include "core/curves/bsplines/knot_vector.h"
#include "core/exact/rational.h"

#include <benchmark/benchmark.h>
#include <unsupported/Eigen/Splines>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

using namespace granota;

namespace {

constexpr int kDegree = 3;
constexpr int kPoints = 10000;

/// The data scipy_bspline.py builds the same way: P_i = (i/100, sin(i/50) + 0.3 cos(i/7)) on
/// the clamped knot vector (p + 1 zeros, interior j/(n − p + 1), p + 1 ones).
BSplineCurve<double> benchCurve()
{
    BSplineCurve<double> c;
    c.degree = kDegree;
    c.points.reserve(kPoints);
    for (int i = 0; i < kPoints; ++i)
        c.points.emplace_back(i / 100.0, std::sin(i / 50.0) + 0.3 * std::cos(i / 7.0));
    c.knots = presetKnots<double>(KnotPreset::Clamped, kPoints, kDegree);
    return c;
}

/// u_k = k/(N − 1), N = 10⁶ (10³ in CI's smoke run): the whole domain [0, 1] in order, as a
/// curve is sampled for drawing.
std::vector<double> benchParameters()
{
    const int count = fullOrSmoke(1000000, 1000);
    std::vector<double> u(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k)
        u[static_cast<std::size_t>(k)] = k / double(count - 1);
    return u;
}

using EigenSpline = Eigen::Spline<double, 2, kDegree>;

EigenSpline eigenSpline(const BSplineCurve<double>& c)
{
    EigenSpline::KnotVectorType knots(static_cast<Eigen::Index>(c.knots.size()));
    for (std::size_t i = 0; i < c.knots.size(); ++i)
        knots(static_cast<Eigen::Index>(i)) = c.knots[i];
    EigenSpline::ControlPointVectorType points(2, static_cast<Eigen::Index>(c.points.size()));
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        points(0, static_cast<Eigen::Index>(i)) = c.points[i].x;
        points(1, static_cast<Eigen::Index>(i)) = c.points[i].y;
    }
    return EigenSpline(knots, points);
}

/// Before timing: both libraries must draw the same curve (largest difference ≤ 1e-12 at every
/// parameter), or the comparison means nothing.
bool sameCurve(const BSplineCurve<double>& c, const EigenSpline& e, const std::vector<double>& u)
{
    double worst = 0;
    for (double v : u) {
        const Point a = bsplinePoint(c, v);
        const auto b = e(v);
        worst = std::max({worst, std::abs(a.x - b(0)), std::abs(a.y - b(1))});
    }
    return worst <= 1e-12;
}

void BM_BSplineEvaluateGranota(benchmark::State& state)
{
    const auto curve = benchCurve();
    const auto u = benchParameters();
    if (!sameCurve(curve, eigenSpline(curve), u)) {
        state.SkipWithError("Granota and Eigen disagree on the benchmark's curve");
        return;
    }
    std::vector<Point> out(u.size());
    for (auto _ : state) {
        for (std::size_t k = 0; k < u.size(); ++k)
            out[k] = bsplinePoint(curve, u[k]);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.counters["ns_per_point"] = benchmark::Counter(
        static_cast<double>(u.size()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void BM_BSplineEvaluateEigen(benchmark::State& state)
{
    const auto curve = benchCurve();
    const auto spline = eigenSpline(curve);
    const auto u = benchParameters();
    std::vector<Point> out(u.size());
    for (auto _ : state) {
        for (std::size_t k = 0; k < u.size(); ++k) {
            const auto p = spline(u[k]);
            out[k] = Point(p(0), p(1));
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.counters["ns_per_point"] = benchmark::Counter(
        static_cast<double>(u.size()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

/// bsplinePoint and Eigen in turns, a block of 10⁴ parameters each, and bsplinePoints
/// (bspline_sampling.h: the span carried from one parameter to the next) on the same block, each
/// timed by the steady clock: on a shared machine the load then falls on all three alike, and
/// their ratios (granota_ms, eigen_ms, sampled_ms: a pass over all the parameters each) are what
/// targets.sh reports.
void BM_BSplineEvaluateInTurns(benchmark::State& state)
{
    using Clock = std::chrono::steady_clock;
    const auto curve = benchCurve();
    const auto spline = eigenSpline(curve);
    const auto u = benchParameters();
    std::vector<Point> out(u.size()), block;
    constexpr std::size_t kBlock = 10000;
    double granotaSeconds = 0, eigenSeconds = 0, sampledSeconds = 0;
    std::vector<std::vector<double>> blocks;
    for (std::size_t start = 0; start < u.size(); start += kBlock)
        blocks.emplace_back(u.begin() + static_cast<std::ptrdiff_t>(start),
                            u.begin() + static_cast<std::ptrdiff_t>(std::min(start + kBlock, u.size())));
    for (auto _ : state) {
        for (std::size_t start = 0; start < u.size(); start += kBlock) {
            const std::size_t end = std::min(start + kBlock, u.size());
            const auto t0 = Clock::now();
            for (std::size_t k = start; k < end; ++k)
                out[k] = bsplinePoint(curve, u[k]);
            benchmark::DoNotOptimize(out.data());
            benchmark::ClobberMemory();
            const auto t1 = Clock::now();
            for (std::size_t k = start; k < end; ++k) {
                const auto p = spline(u[k]);
                out[k] = Point(p(0), p(1));
            }
            benchmark::DoNotOptimize(out.data());
            benchmark::ClobberMemory();
            const auto t2 = Clock::now();
            bsplinePoints(curve, blocks[start / kBlock], block);
            benchmark::DoNotOptimize(block.data());
            benchmark::ClobberMemory();
            const auto t3 = Clock::now();
            granotaSeconds += std::chrono::duration<double>(t1 - t0).count();
            eigenSeconds += std::chrono::duration<double>(t2 - t1).count();
            sampledSeconds += std::chrono::duration<double>(t3 - t2).count();
        }
    }
    const double passes = static_cast<double>(state.iterations());
    state.counters["granota_ms"] = 1e3 * granotaSeconds / passes;
    state.counters["eigen_ms"] = 1e3 * eigenSeconds / passes;
    state.counters["sampled_ms"] = 1e3 * sampledSeconds / passes;
}

/// Degree 10, 21 control points with small integer coordinates, clamped knots i/11, u = 37/100:
/// every level of the exact net, what the B-spline tab redraws on a drag when the data are
/// rational (target < 5 ms).
BSplineCurve<Rational> exactCurve(int degree)
{
    BSplineCurve<Rational> c;
    c.degree = degree;
    const int count = 2 * degree + 1;
    for (int i = 0; i < count; ++i)
        c.points.emplace_back(Rational((i * 7) % 21 - 10), Rational((i * 13) % 21 - 10));
    c.knots = presetKnots<Rational>(KnotPreset::Clamped, count, degree);
    return c;
}

void BM_DeBoorExact(benchmark::State& state)
{
    const auto curve = exactCurve(static_cast<int>(state.range(0)));
    const Rational u = frac(37, 100);
    for (auto _ : state)
        benchmark::DoNotOptimize(deBoor(curve, u));
}

void BM_BSplinePointExact(benchmark::State& state)
{
    const auto curve = exactCurve(static_cast<int>(state.range(0)));
    const Rational u = frac(37, 100);
    for (auto _ : state)
        benchmark::DoNotOptimize(bsplinePoint(curve, u));
}

} // namespace

BENCHMARK(BM_BSplineEvaluateGranota)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BSplineEvaluateEigen)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BSplineEvaluateInTurns)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DeBoorExact)->Arg(3)->Arg(10)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BSplinePointExact)->Arg(3)->Arg(10)->Unit(benchmark::kMicrosecond);
