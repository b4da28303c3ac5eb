#pragma once
/// \file simulation_backends.h
/// The concrete simulations behind Simulation::create (internal to the core).

#include "core/softbody/simulation.h"

namespace granota {

/// §4.1–4.5 on the seed's explicit scheme (StageBody).
Expected<std::unique_ptr<Simulation>> makeStageSimulation(const SceneSpec& scene);
/// §4.6–4.12, §4.16 and §5.2 on Annex II's Verlet body and legs.
Expected<std::unique_ptr<Simulation>> makeSeedBodySimulation(const SceneSpec& scene);
/// §4.13–4.15 on the seed's pendulums (Annex II's Pota; §4.14's follow chain).
Expected<std::unique_ptr<Simulation>> makeSeedPendulumSimulation(const SceneSpec& scene);
/// Every scene on the constraint-based solver.
Expected<std::unique_ptr<Simulation>> makeStableSimulation(const SceneSpec& scene);

} // namespace granota
