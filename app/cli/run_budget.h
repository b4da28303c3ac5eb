#pragma once
/// \file run_budget.h
/// The work budget of `simulate` and `bench`: a run is refused, before its first step, when
/// steps × the estimated time of a step (core/softbody/step_cost.h) is beyond
/// kMaxRunNanoseconds (core/base/input_limits.h). The estimate counts what the vertex count
/// alone misses: the stable solver's substeps and its check of every pair of a body's
/// edges, which makes a body of 10 000 sides cost a tenth of a second a step.

#include "core/base/expected.h"
#include "core/softbody/simulation.h"

namespace granota::cli {

/// Refuses `steps` steps of `copies` copies of `s` when they would take longer than the
/// budget, with a one-line message naming the estimate and what to lower.
Expected<void> checkRunWork(const Simulation& s, long long steps, int copies = 1);

/// "45 s", "12 min", "3.6 h": a rough duration, for messages.
std::string roughDuration(double nanoseconds);

} // namespace granota::cli
