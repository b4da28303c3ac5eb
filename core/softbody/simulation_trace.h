#pragma once
/// \file simulation_trace.h
/// The trace of any running scene in the CSV layout of reference/seed_frog_trace.csv
/// (`granota-cli simulate --trace`): `step`, the vertices of every body (`v0x,v0y,…`;
/// with several bodies `b1_v0x,…`), then every chain's joints after its fixed one — for
/// the frog its four legs' elbows and wrists (`front_right_elbow_x,…`), exactly the
/// reference's columns. The seed solver runs in single precision, so its numbers are
/// written as floats ("640.0"): the frog with the thesis's constants reproduces the
/// reference file byte for byte.

#include "core/softbody/simulation.h"

#include <cstddef>
#include <string>

namespace granota {

/// The most points (body vertices and chain joints, x and y) a trace writes over all its
/// rows: rows × simulationTracePoints(). About 20 bytes a point once written, so at most
/// some 200 MB of CSV; the frog's 600-step reference trace writes 10 818.
constexpr long long kMaxTracePoints = 10000000;

/// The points of one row of the trace: every body's vertices and every chain's joints
/// after its fixed one.
std::size_t simulationTracePoints(const Simulation& sim);

std::string simulationTraceHeader(const Simulation& sim);
std::string simulationTraceRow(const Simulation& sim);

} // namespace granota
