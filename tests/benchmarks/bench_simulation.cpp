// Google Benchmark: the cost of a soft-body step (issue: ns per body step for both solvers,
// many-bodies at 10, 100 and 1000 bodies). Timings belong here, never in tests.
//   build/bin/granota-bench --benchmark_filter=Frog
#include "core/simulation.h"

#include <benchmark/benchmark.h>

using namespace granota;

namespace {

std::unique_ptr<Simulation> make(const char* scene, SolverKind solver, int bodies = 0)
{
    auto spec = loadScene(scene);
    if (bodies > 0)
        spec = withBodies(*spec, bodies); // the scene's density: the frame grows with the bodies
    return std::move(Simulation::create(*spec, solver)).value();
}

void settle(Simulation& s, int steps)
{
    for (int i = 0; i < steps; ++i)
        s.step();
}

void BM_FrogStep(benchmark::State& state, SolverKind solver)
{
    auto sim = make("frog", solver);
    settle(*sim, 100);
    for (auto _ : state)
        sim->step();
    state.counters["ns_per_body_step"] = benchmark::Counter(static_cast<double>(state.iterations()),
                                                            benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_ManyBodies(benchmark::State& state)
{
    const int bodies = static_cast<int>(state.range(0));
    auto sim = make("many-bodies", SolverKind::Stable, bodies);
    settle(*sim, 50);
    for (auto _ : state)
        sim->step();
    state.SetComplexityN(bodies);
    state.counters["bodies"] = bodies;
    state.counters["ns_per_body_step"] = benchmark::Counter(static_cast<double>(state.iterations()) * bodies,
                                                            benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

} // namespace

BENCHMARK_CAPTURE(BM_FrogStep, seed, SolverKind::Seed);
BENCHMARK_CAPTURE(BM_FrogStep, stable, SolverKind::Stable);
BENCHMARK(BM_ManyBodies)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond)->Complexity();

BENCHMARK_MAIN();
