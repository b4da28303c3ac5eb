// Google Benchmark: the closed C² spline (parametric_spline.h) through many points — a
// cyclic tridiagonal solve, O(n) — against scipy's CubicSpline(bc_type='periodic') on the
// same data (tests/benchmarks/peer/scipy_periodic_spline.py; targets.sh prints the ratio).
//   build/bin/granota-bench --benchmark_filter='ClosedSpline'
#include "core/curves/splines/parametric_spline.h"

#include <benchmark/benchmark.h>

#include <cmath>

using namespace granota;

namespace {

/// n points on the closed curve r(θ) = 1 + 0.3 sin 5θ, θ = 2πi/n (the same in the scipy script).
std::vector<Point> flowerPoints(int n)
{
    std::vector<Point> p;
    p.reserve(static_cast<std::size_t>(n));
    const double twoPi = 2 * std::acos(-1.0);
    for (int i = 0; i < n; ++i) {
        const double theta = twoPi * i / n, r = 1 + 0.3 * std::sin(5 * theta);
        p.emplace_back(r * std::cos(theta), r * std::sin(theta));
    }
    return p;
}

/// The closed spline with chord-length parameters (knots included in the time).
void BM_ClosedSpline(benchmark::State& state)
{
    const auto points = flowerPoints(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        auto spline = parametricSpline(points, ParametricEnds::Periodic, SplineParameters::Chord);
        benchmark::DoNotOptimize(spline);
    }
    state.SetComplexityN(state.range(0));
}

} // namespace

BENCHMARK(BM_ClosedSpline)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);
