#pragma once
/// \file step_cost.h
/// What one step of a running scene costs, estimated before it is run, so that
/// `granota-cli simulate` and `bench` refuse a run of hours rather than start it
/// (kMaxRunNanoseconds, core/base/input_limits.h). The estimate is in nanoseconds on the
/// reference machine (2 cores, 2026; docs/extreme-cases.md has the measurements), from
/// what each solver does in a step:
///
/// - the seed (Annex II's actualitza()) visits each vertex and joint a fixed number of
///   times: kSeedNsPerPoint each;
/// - the stable solver (XPBD) solves every constraint once a substep: kStableNsPerVertex
///   per body vertex and kStableNsPerJoint per chain joint (its angle limits and four
///   passes), times the substeps; and once a step it checks every body for crossing edges
///   (xpbd_recovery.h, polygonSelfIntersects), every pair of edges: kStableNsPerEdgePair
///   × n(n − 1)/2 for a body of n sides. That term is the one that grows with the square
///   of a body's size: 10 000 sides is 5·10⁷ pairs, about a tenth of a second a step.
///
/// Contacts between bodies are not counted: the broad phase keeps them close to linear
/// in the bodies laid out side by side, and a scene that starts piled up is bounded by the
/// scene's own validation (scene.cpp, kMaxPiledVertices).

#include "core/softbody/simulation.h"

namespace granota {

/// The seed: nanoseconds per vertex or joint and step (10 000 sides: 75 µs a step).
inline constexpr double kSeedNsPerPoint = 10;
/// The stable solver: nanoseconds per body vertex and substep (5000 bodies of 10 sides,
/// 8 substeps: 17.5 ms a step, 44 ns; one body of 3000 sides, 17 ns).
inline constexpr double kStableNsPerVertex = 50;
/// The stable solver: nanoseconds per chain joint and substep (the pendulum chain's 6
/// joints: 7.5 µs a step, 157 ns).
inline constexpr double kStableNsPerJoint = 200;
/// The stable solver: nanoseconds per pair of a body's edges, once a step (one body of
/// 3000 sides, 1.8 ns; of 10 000, 1.6 to 2.6 ns).
inline constexpr double kStableNsPerEdgePair = 2.5;

/// The estimated nanoseconds of one step of `s` on the reference machine.
double estimatedStepNanoseconds(const Simulation& s);

} // namespace granota
