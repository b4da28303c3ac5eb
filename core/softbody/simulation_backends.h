#pragma once
/// \file simulation_backends.h
/// The concrete simulations behind Simulation::create (internal to the core).

#include "core/softbody/simulation.h"

namespace granota {

/// The parts of chapter 4 both of the seed's schemes (StageComponents, SeedComponents)
/// switch on from the scene's components (docs/scenes.md): gravity and the frame (§4.2),
/// the springs (§4.4), the area (§4.5).
template <class Components> void setSharedComponents(Components& c, const SceneSpec& scene)
{
    c.gravity = scene.has(SceneComponent::Gravity);
    c.bounds = scene.has(SceneComponent::Bounds);
    c.springs = scene.has(SceneComponent::Springs);
    c.area = scene.has(SceneComponent::Area);
}

/// §4.1–4.5 on the seed's explicit scheme (StageBody).
Expected<std::unique_ptr<Simulation>> makeStageSimulation(const SceneSpec& scene);
/// §4.6–4.12, §4.16 and §5.2 on Annex II's Verlet body and legs.
Expected<std::unique_ptr<Simulation>> makeSeedBodySimulation(const SceneSpec& scene);
/// §4.13–4.15 on the seed's pendulums (Annex II's Pota; §4.14's follow chain).
Expected<std::unique_ptr<Simulation>> makeSeedPendulumSimulation(const SceneSpec& scene);
/// Every scene on the constraint-based solver.
Expected<std::unique_ptr<Simulation>> makeStableSimulation(const SceneSpec& scene);

} // namespace granota
