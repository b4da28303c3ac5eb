// granota-cli bench: nanoseconds per step of a scene (docs/cli.md). With --bodies B, a scene
// that has bodies of its own (many-bodies) gets B of them; any other scene is run as B
// independent copies, like the seed's `java SeedFrog STEPS FROGS`.
#include "app/cli/command.h"
#include "app/cli/run_budget.h"
#include "app/cli/scene_options.h"

#include "core/base/input_limits.h"
#include "core/base/number_format.h"

#include <chrono>
#include <cmath>
#include <sstream>

namespace granota::cli {

namespace {

constexpr int kMaxBenchSteps = 100000000;
constexpr int kMaxBenchBodies = 5000;

Expected<CommandOutput> run(const Arguments& args)
{
    auto scene = sceneFromArguments(args);
    if (!scene)
        return scene.error();
    auto bodies = args.integer("bodies", 1, kMaxBenchBodies, 1);
    if (!bodies)
        return bodies.error();
    auto steps = args.integer("steps", 1, kMaxBenchSteps, 1000);
    if (!steps)
        return steps.error();
    int copies = *bodies;
    if (scene->hasParam("bodies")) {
        auto scaled = withBodies(*scene, *bodies);
        if (!scaled)
            return scaled.error();
        scene = std::move(scaled);
        copies = 1;
    }
    // The copies together hold at most what one scene may (kMaxVertices): 5000 copies of a
    // body of 10 000 sides were 50 million vertices, 4.5 GB before the first step.
    if (copies * sceneVertexCount(*scene) > kMaxVertices)
        return makeError(ErrorCode::OutOfRange, std::to_string(copies) + " copies of " +
                                                    std::to_string(sceneVertexCount(*scene)) + " vertices are " +
                                                    std::to_string(copies * sceneVertexCount(*scene)) + ", more than " +
                                                    std::to_string(kMaxVertices) + " vertices in all: lower --bodies, or sides");
    auto solver = solverFromArguments(args, *scene);
    if (!solver)
        return solver.error();
    std::vector<std::unique_ptr<Simulation>> sims;
    for (int i = 0; i < copies; ++i) {
        auto sim = Simulation::create(*scene, *solver);
        if (!sim)
            return sim.error();
        sims.push_back(std::move(sim).value());
        // The copies are alike: the first says what all of them will cost (run_budget.h).
        if (i == 0)
            if (auto affordable = checkRunWork(*sims.front(), *steps, copies); !affordable)
                return affordable.error();
    }
    const auto t0 = std::chrono::steady_clock::now();
    for (int s = 0; s < *steps; ++s)
        for (auto& sim : sims)
            sim->step();
    const auto t1 = std::chrono::steady_clock::now();
    const double ns = std::chrono::duration<double, std::nano>(t1 - t0).count();
    const double nsPerStep = ns / *steps;
    const double nsPerBodyStep = nsPerStep / *bodies;
    bool finite = true;
    for (const auto& sim : sims)
        finite = finite && sim->finite();

    CommandOutput out;
    std::ostringstream txt;
    txt << "scene " << scene->name << ", solver " << solverName(*solver) << ", " << *bodies << " bodies, " << *steps
        << " steps: " << formatDouble(std::round(nsPerStep)) << " ns per step, "
        << formatDouble(std::round(nsPerBodyStep * 10) / 10) << " ns per body step (frame " << formatDouble(scene->params.width)
        << " × " << formatDouble(scene->params.height) << " px)\n";
    out.json.set("ns_per_step", nsPerStep)
        .set("ns_per_body_step", nsPerBodyStep)
        .set("scene", scene->name)
        .set("solver", solverName(*solver))
        .set("bodies", *bodies)
        .set("steps", *steps)
        .set("finite", finite);
    out.text = txt.str();
    return out;
}

} // namespace

Command benchCommand()
{
    return {"bench",
            "--scene NAME [--solver seed|stable] [--bodies B] [--steps N] [--set key=value …] [--json]",
            "time the steps of a scene: ns per step and per body step",
            {{"scene", "solver", "bodies", "steps", "set"}, {"json"}, {"set"}},
            &run};
}

} // namespace granota::cli
