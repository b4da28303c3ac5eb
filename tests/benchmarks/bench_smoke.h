#pragma once
// CI runs every benchmark once, only to see that it runs (.ci/setup: GRANOTA_BENCH_SMOKE=1
// and a tiny --benchmark_min_time). The benchmarks that set their own amount of work (a
// fixed iteration count, hundreds of steps to settle or to time) then do a token amount of
// it. The figures of such a run mean nothing; tests/benchmarks/targets.sh never sets it.
#include <cstdlib>

/// Whether this run is CI's smoke run.
inline bool benchSmokeRun()
{
    static const bool smoke = std::getenv("GRANOTA_BENCH_SMOKE") != nullptr;
    return smoke;
}

/// `full` in a real run, `smoke` in CI's smoke run.
inline int fullOrSmoke(int full, int smoke) { return benchSmokeRun() ? smoke : full; }
