#pragma once
/// \file stopwatch.h
/// Run time of a piece of work for the work-precision reports (docs/work-precision.md): the work is
/// repeated until at least `minSeconds` have passed, so that short calls are measured over
/// many repetitions and the clock's resolution does not matter. Reports compare methods
/// measured in the same run; nothing here is a test.

#include <algorithm>
#include <chrono>
#include <functional>

namespace granota {

/// Seconds per call of `work` (a callable returning a double that is accumulated, so the
/// compiler cannot drop the work). The number of calls is first raised until a batch takes
/// `minSeconds`; then the batch is timed three times and the fastest kept — on a shared
/// machine other programs only ever add time, so the minimum is the least disturbed.
template <class Work> double secondsPerCall(Work&& work, double minSeconds, double* sink)
{
    using Clock = std::chrono::steady_clock;
    // Called through a pointer read from volatile memory: the compiler cannot see which
    // function runs, so it can neither hoist a pure computation out of the loop nor drop it.
    std::function<double()> call(std::ref(work));
    std::function<double()>* volatile opaque = &call;
    double acc = 0;
    auto timeBatch = [&](long calls) {
        const auto start = Clock::now();
        for (long i = 0; i < calls; ++i)
            acc += (*opaque)();
        return std::chrono::duration<double>(Clock::now() - start).count();
    };
    long batch = 1;
    double elapsed = timeBatch(batch);
    while (elapsed < minSeconds && batch < (1L << 40)) {
        batch *= 2;
        elapsed = timeBatch(batch);
    }
    constexpr int kRepeats = 3;
    for (int r = 1; r < kRepeats && minSeconds > 1e-5; ++r)
        elapsed = std::min(elapsed, timeBatch(batch));
    if (sink)
        *sink += acc;
    return elapsed / static_cast<double>(batch);
}

} // namespace granota
