#include "app/cli/scene_options.h"

#include "core/base/display_text.h"
#include "core/exact/rational.h"

#include <cmath>

namespace granota::cli {

Expected<SceneSpec> sceneFromArguments(const Arguments& args)
{
    auto name = args.value("scene");
    if (!name)
        return makeError(ErrorCode::InvalidInput, "--scene NAME is required");
    auto scene = loadScene(*name);
    if (!scene)
        return scene.error();
    for (const std::string& setting : args.values("set")) {
        // bodies=N lays the N bodies out as `bench --bodies N` does: in a frame grown for them.
        const std::string prefix = "bodies=";
        if (setting.compare(0, prefix.size(), prefix) == 0 && scene->hasParam("bodies")) {
            const auto q = parseRational(setting.substr(prefix.size()));
            const double n = q ? toDouble(*q) : 0;
            if (q && n >= 1 && n <= 1e9 && n == std::trunc(n)) { // else applySetting says what is wrong
                auto grown = withBodies(*scene, static_cast<int>(n));
                if (!grown)
                    return grown.error();
                scene = std::move(grown);
                continue;
            }
        }
        auto ok = applySetting(*scene, setting);
        if (!ok)
            return ok.error();
    }
    return scene;
}

Expected<SolverKind> solverFromArguments(const Arguments& args, const SceneSpec& scene)
{
    if (auto name = args.value("solver")) {
        auto kind = parseSolverKind(*name);
        if (!kind)
            return makeError(ErrorCode::InvalidInput, "--solver " + quotedForDisplay(*name) + " is not one of: seed, stable");
        return *kind;
    }
    return scene.has(SceneComponent::Collisions) || scene.has(SceneComponent::Obstacles) ? SolverKind::Stable : SolverKind::Seed;
}

Expected<std::pair<SceneSpec, SolverKind>> sceneAndSolverFromArguments(const Arguments& args)
{
    auto scene = sceneFromArguments(args);
    if (!scene)
        return scene.error();
    auto solver = solverFromArguments(args, *scene);
    if (!solver)
        return solver.error();
    return std::make_pair(std::move(scene).value(), *solver);
}

Expected<std::unique_ptr<Simulation>> buildSimulation(const Arguments& args)
{
    auto chosen = sceneAndSolverFromArguments(args);
    if (!chosen)
        return chosen.error();
    return Simulation::create(chosen->first, chosen->second);
}

} // namespace granota::cli
