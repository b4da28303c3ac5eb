// Google Benchmark: the cost of one frog step on each solver (issue 5: a `seed` frog step at
// least 20× faster than the seed's own program, reference/SeedFrog.java). Timings belong
// here, never in tests. The many-bodies scene is in bench_many_bodies.cpp.
//   build/bin/granota-bench --benchmark_filter=Frog
// Compare with the seed in the same run:
//   javac -d /tmp/seedfrog SeedFrog.java && java -cp /tmp/seedfrog SeedFrog 2000000
#include "core/softbody/simulation.h"

#include <benchmark/benchmark.h>

using namespace granota;

namespace {

/// Steps run before timing, so that the frog has landed and its legs touch the floor
/// (the common state of a running scene, with every branch of the leg code in use).
constexpr int kFrogSettleSteps = 100;

void BM_FrogStep(benchmark::State& state, SolverKind solver)
{
    auto spec = loadScene("frog");
    auto sim = std::move(Simulation::create(*spec, solver)).value();
    for (int i = 0; i < kFrogSettleSteps; ++i)
        sim->step();
    for (auto _ : state)
        sim->step();
    // One frog is one body: ns per body step is the time per iteration.
    state.counters["ns_per_body_step"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                            benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

} // namespace

BENCHMARK_CAPTURE(BM_FrogStep, seed, SolverKind::Seed);
BENCHMARK_CAPTURE(BM_FrogStep, stable, SolverKind::Stable);

BENCHMARK_MAIN();
