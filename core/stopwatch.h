#pragma once
/// \file stopwatch.h
/// Run time of a piece of work for the work-precision reports (SPEC §2): the work is
/// repeated until at least `minSeconds` have passed, so that short calls are measured over
/// many repetitions and the clock's resolution does not matter. Reports compare methods
/// measured in the same run; nothing here is a test.

#include <chrono>
#include <functional>

namespace granota {

/// Seconds per call of `work` (a callable returning a double that is accumulated, so the
/// compiler cannot drop the work).
template <class Work> double secondsPerCall(Work&& work, double minSeconds, double* sink)
{
    using Clock = std::chrono::steady_clock;
    // Called through a pointer read from volatile memory: the compiler cannot see which
    // function runs, so it can neither hoist a pure computation out of the loop nor drop it.
    std::function<double()> call(std::ref(work));
    std::function<double()>* volatile opaque = &call;
    long calls = 0;
    long batch = 1;
    double acc = 0;
    const auto start = Clock::now();
    double elapsed = 0;
    for (;;) {
        for (long i = 0; i < batch; ++i) {
            acc += (*opaque)();
        }
        calls += batch;
        elapsed = std::chrono::duration<double>(Clock::now() - start).count();
        if (elapsed >= minSeconds)
            break;
        batch *= 2;
    }
    if (sink)
        *sink += acc;
    return elapsed / static_cast<double>(calls);
}

} // namespace granota
