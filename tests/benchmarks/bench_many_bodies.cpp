// Google Benchmark: the many-bodies scene of §5.2.2 on the `stable` solver at 10, 100 and
// 1000 bodies (issue 5: 1000 colliding frogs in at most 16 ms per step on one core), in
// two layouts, so that the growth with the number of bodies is visible in the counter
// `ns_per_body_step` (flat = linear cost, the point of the broad phase):
//  - spread: the scene's own density (withBodies grows the frame with the bodies), just
//    after the start — the bodies fall, few touch;
//  - pile: the worst case of the narrow phase. The same B bodies (10-gons, radius 40 px,
//    target area 5000 px²) start in a grid ⌈√B⌉ bodies wide in a frame just wide enough for
//    that grid and just tall enough for its rows; they fall for kPileSettleSteps steps and
//    come to rest on the floor and on each other, a pile about as deep as it is wide (at
//    1000 bodies: a 2936 × 2936 px frame, the pile's top near y = 1250, squeezed ~2.6 %
//    below the target area). Each body then presses on about six others: ~2900 pairs from
//    the broad phase and ~10 000 vertex contacts per substep, about one per vertex. Timed
//    steps continue from that state (the pile stays a pile: nothing leaves it).
//   build/bin/granota-bench --benchmark_filter=ManyBodies
#include "core/softbody/recorded_run.h"
#include "core/softbody/simulation.h"
#include "core/softbody/simulation_series.h"

#include "bench_smoke.h"

#include <benchmark/benchmark.h>

#include <chrono>

#include <algorithm>
#include <cmath>

using namespace granota;

namespace {

/// Steps before timing the spread layout: the bodies are under way, still apart.
constexpr int kSpreadSettleSteps = 50;
/// Steps before timing the pile: enough for the top row to fall onto the others and the
/// pile to come (nearly) to rest.
const int kPileSettleSteps = fullOrSmoke(300, 10);
/// The scene's layout (scene_layout.cpp) puts bodies 2.2 radii apart…
constexpr double kLayoutPitchRadii = 2.2;
/// …and keeps about 2.1 radii from the frame's top-left corner; one more radius of room.
constexpr double kLayoutMarginRadii = 3.0;

SceneSpec spreadScene(int bodies) { return *withBodies(*loadScene("many-bodies"), bodies); }

/// The same bodies in a frame about √B bodies wide and just tall enough to hold the
/// starting grid: after a short fall they form a pile as deep as it is wide.
SceneSpec pileScene(int bodies)
{
    SceneSpec s = spreadScene(bodies);
    const double r = s.params.radius, pitch = kLayoutPitchRadii * r;
    const int perRow = std::max(1, static_cast<int>(std::ceil(std::sqrt(double(bodies)))));
    const int rows = (bodies + perRow - 1) / perRow;
    s.params.width = std::round(kLayoutMarginRadii * r + perRow * pitch);
    s.params.height = std::round(kLayoutMarginRadii * r + rows * pitch);
    return s;
}

void run(benchmark::State& state, const SceneSpec& spec, int settle)
{
    const int bodies = static_cast<int>(state.range(0));
    auto sim = std::move(Simulation::create(spec, SolverKind::Stable)).value();
    for (int i = 0; i < settle; ++i)
        sim->step();
    for (auto _ : state)
        sim->step();
    state.SetComplexityN(bodies);
    state.counters["bodies"] = bodies;
    state.counters["ns_per_body_step"] = benchmark::Counter(static_cast<double>(state.iterations()) * bodies,
                                                            benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["in_bounds"] = sim->inBounds() ? 1 : 0;
}

void BM_ManyBodiesSpread(benchmark::State& state)
{
    run(state, spreadScene(static_cast<int>(state.range(0))), kSpreadSettleSteps);
}

void BM_ManyBodiesPile(benchmark::State& state) { run(state, pileScene(static_cast<int>(state.range(0))), kPileSettleSteps); }

} // namespace

BENCHMARK(BM_ManyBodiesSpread)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_ManyBodiesPile)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond)->Complexity();

// Issue 16: what recording a run (RecordedRun: its snapshots, spaced as the Frog tab spaces
// them) and the plots' series (SeriesRecorder, one sample a step) add to a step of 1000
// bodies. The same steps from the same state with and without them: the ratio of the two is
// the overhead (target: at most 5 %, tests/benchmarks/targets.sh).

namespace {

/// Steps timed each way: enough for two or more snapshots at the spacing the cost floor
/// reaches on 1000 bodies (~300 steps), so their share is in the figure.
const int kOverheadSteps = fullOrSmoke(900, 20);

// What recording a run and its series cost on 1000 bodies (issue 16: at most 5 % of the
// step): a plain simulation and a recorded run with its series, built alike and settled,
// step in turns of 10 steps, each turn timed, for kOverheadSteps steps each — so that the
// machine's drift (other work, clock changes) falls on both alike. Counters: plain_ms and
// recorded_ms (each iteration's kOverheadSteps steps), overhead_percent, snapshot_every (the
// spacing the cost floor reached).
void BM_RecordingOverhead(benchmark::State& state)
{
    const SceneSpec spec = spreadScene(static_cast<int>(state.range(0)));
    double plainNs = 0, recordedNs = 0;
    int snapshotEvery = 0;
    for (auto _ : state) {
        auto sim = std::move(Simulation::create(spec, SolverKind::Stable)).value();
        // As the Frog tab's canvas records it: a snapshot every step asked (its seek budget,
        // FrogRun::kScrubWork, holds one step of 1000 bodies), spaced out by the cost floor.
        auto run = std::move(RecordedRun::start(spec, SolverKind::Stable, 1)).value();
        run.limitSnapshotCost(RecordedRun::kSnapshotCostShare);
        SeriesRecorder series(36000);
        for (int i = 0; i < kSpreadSettleSteps; ++i) {
            sim->step();
            run.step();
        }
        double plain = 0, recorded = 0;
        for (int turn = 0; turn < kOverheadSteps / 10; ++turn) {
            auto t0 = std::chrono::steady_clock::now();
            for (int i = 0; i < 10; ++i)
                sim->step();
            auto t1 = std::chrono::steady_clock::now();
            for (int i = 0; i < 10; ++i) {
                run.step();
                series.record(run.simulation());
            }
            auto t2 = std::chrono::steady_clock::now();
            plain += std::chrono::duration<double, std::nano>(t1 - t0).count();
            recorded += std::chrono::duration<double, std::nano>(t2 - t1).count();
        }
        state.SetIterationTime(recorded * 1e-9);
        snapshotEvery = run.snapshotEvery();
        plainNs += plain;
        recordedNs += recorded;
    }
    const double n = double(state.iterations());
    state.counters["plain_ms"] = plainNs / n * 1e-6;
    state.counters["recorded_ms"] = recordedNs / n * 1e-6;
    state.counters["overhead_percent"] = 100 * (recordedNs / plainNs - 1);
    state.counters["snapshot_every"] = snapshotEvery;
}

// The parts of that overhead, each alone on the same settled 1000 bodies: a readout (what
// the series samples every step), a sample of the series, and a snapshot (a clone into new
// memory, as a recording keeps it: on this machine a new page costs ~10 µs, so a snapshot of
// 1000 bodies costs a few steps; RecordedRun::limitSnapshotCost spaces them out).
std::unique_ptr<Simulation> settledSpread(int bodies)
{
    auto sim = std::move(Simulation::create(spreadScene(bodies), SolverKind::Stable)).value();
    for (int i = 0; i < kSpreadSettleSteps; ++i)
        sim->step();
    return sim;
}

void BM_Readouts(benchmark::State& state)
{
    const auto sim = settledSpread(static_cast<int>(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(sim->readouts());
}

void BM_SeriesSample(benchmark::State& state)
{
    const auto sim = settledSpread(static_cast<int>(state.range(0)));
    SeriesRecorder series(36000);
    for (auto _ : state) {
        state.PauseTiming();
        sim->step();
        state.ResumeTiming();
        benchmark::DoNotOptimize(series.record(*sim));
    }
}

void BM_Snapshot(benchmark::State& state)
{
    const auto sim = settledSpread(static_cast<int>(state.range(0)));
    std::vector<std::unique_ptr<Simulation>> kept; // as a recording keeps them: new memory each
    for (auto _ : state)
        kept.push_back(sim->clone());
}

// A scrub 10 000 steps back: from step 10 000 of the frog on the stable solver (grabbed
// and thrown on the way) to step 99, the worst case of snapshots every 100 steps (99 steps
// re-simulated after restoring the one at step 0). Target: within 100 ms.
void BM_ScrubBack10000(benchmark::State& state)
{
    auto run = std::move(RecordedRun::start(*loadScene("frog"), SolverKind::Stable)).value();
    for (int i = 0; i < 10000; ++i) {
        if (i % 1000 == 100)
            run.press(Point(640, 500));
        if (i % 1000 == 160)
            run.release();
        run.step();
    }
    for (auto _ : state) {
        state.PauseTiming();
        (void)run.seek(10000);
        state.ResumeTiming();
        (void)run.seek(99);
    }
    state.counters["snapshots"] = static_cast<double>(run.snapshotCount());
}

} // namespace

BENCHMARK(BM_RecordingOverhead)->Arg(1000)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(fullOrSmoke(3, 1));
BENCHMARK(BM_Readouts)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SeriesSample)->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Snapshot)->Arg(1000)->Unit(benchmark::kMicrosecond)->Iterations(fullOrSmoke(100, 2));
BENCHMARK(BM_ScrubBack10000)->Unit(benchmark::kMillisecond);
