#pragma once
/// \file scene_options.h
/// --scene, --solver and --set, shared by `simulate` and `bench`.

#include "app/cli/arguments.h"

#include "core/softbody/simulation.h"

#include <memory>
#include <utility>

namespace granota::cli {

/// The scene with every --set applied, in order.
Expected<SceneSpec> sceneFromArguments(const Arguments& args);
/// --solver, or the scene's natural one: stable where the scene needs collisions (the
/// seed never had them), seed otherwise.
Expected<SolverKind> solverFromArguments(const Arguments& args, const SceneSpec& scene);
/// Both of the above.
Expected<std::pair<SceneSpec, SolverKind>> sceneAndSolverFromArguments(const Arguments& args);
Expected<std::unique_ptr<Simulation>> buildSimulation(const Arguments& args);

} // namespace granota::cli
