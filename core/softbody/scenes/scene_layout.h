#pragma once
/// \file scene_layout.h
/// Where a scene's bodies start and what shape they rest in — shared by both solvers, so
/// that switching solver changes the physics and nothing else.

#include "core/softbody/scenes/scene.h"

#include <optional>
#include <vector>

namespace granota {

/// How many of the scene's bodies start in one row of its frame (at least 1; all of them
/// when the frame is wide enough).
int bodiesPerRow(const SceneSpec& scene);

/// Whether the scene's bodies start inside its frame without overlapping: the staggered
/// grid of bodyStarts() has room for every row above the floor. A scene whose bodies
/// start piled up makes the broad phase pair every body with every other (5000 bodies in
/// 1280 × 720 px cost seconds a step). Always true for a single body or given shapes.
bool bodiesFitFrame(const SceneSpec& scene);

struct FrameSize {
    double width = 0, height = 0;
};

/// The frame for `bodies` of the scene's bodies at the scene's density: its width and
/// height grow by √(bodies / scene.bodies) (never shrink), then the height grows further
/// if the rows still do not fit (bodiesFitFrame). The one place `bench --bodies` and
/// `--set bodies=N` get their frame from.
FrameSize frameForBodies(const SceneSpec& scene, int bodies);

/// One centre per body: the scene's centre; for many-bodies a staggered grid from the
/// top left; for shapes where each shape says.
std::vector<Point> bodyStarts(const SceneSpec& scene);

/// Body i's rest shape around its centre when it is not the seed's regular N-gon: the
/// shapes of §5.2.3, or the precomputed Bézier points of §4.9/4.10. nullopt otherwise.
std::optional<std::vector<Point>> customRestShape(const SceneSpec& scene, std::size_t i);

} // namespace granota
