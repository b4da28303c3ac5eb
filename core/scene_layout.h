#pragma once
/// \file scene_layout.h
/// Where a scene's bodies start and what shape they rest in — shared by both solvers, so
/// that switching solver changes the physics and nothing else.

#include "core/scene.h"

#include <optional>
#include <vector>

namespace granota {

/// One centre per body: the scene's centre; for many-bodies a staggered grid from the
/// top left; for shapes where each shape says.
std::vector<Point> bodyStarts(const SceneSpec& scene);

/// Body i's rest shape around its centre when it is not the seed's regular N-gon: the
/// shapes of §5.2.3, or the precomputed Bézier points of §4.9/4.10. nullopt otherwise.
std::optional<std::vector<Point>> customRestShape(const SceneSpec& scene, std::size_t i);

} // namespace granota
