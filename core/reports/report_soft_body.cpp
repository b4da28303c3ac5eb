// docs/work-precision.md, soft body: how far the constraints of the body are from holding, against the
// work spent on them. XPBD (the `stable` solver) with rigid edges and an exact area
// constraint (§4.4, §4.5 made hard constraints) over more and more substeps; the seed's
// soft corrections (Annex II) for comparison.
#include "core/softbody/polygon_geometry.h"
#include "core/softbody/regular_polygon.h"
#include "core/softbody/scenes/scene.h"
#include "core/softbody/simulation.h"
#include "core/base/stopwatch.h"
#include "core/reports/work_precision_reports.h"
#include "core/softbody/xpbd/xpbd_world.h"

#include <algorithm>
#include <cmath>

namespace granota::reports {

namespace {
constexpr int kSoftBodySteps = 240; ///< 4 s at 60 steps/s: a fall, an impact on the floor, rest
constexpr double kRadius = 120;     ///< the frog's body (frog.json)
constexpr int kSides = 10;

struct Run {
    double areaError = 0; ///< RMS over the steps of |A − A₀|/A₀
    double edgeError = 0; ///< RMS over the steps of max |L − L₀|/L₀
};

Expected<Run> runXpbd(int substeps)
{
    XpbdParams params;
    params.substeps = substeps;
    params.edgeCompliance = 0; // rigid edges: any violation is solver error
    params.areaCompliance = 0; // exact area
    auto world = XpbdWorld::create(params);
    if (!world)
        return world.error();
    const double target = polygonArea(regularPolygon(Point(0, 0), kRadius, kSides));
    auto body = world->addRegularBody(Point(params.width / 2, params.height / 2), kRadius, kSides, target, Point(0, -5));
    if (!body)
        return body.error();
    Run run;
    for (int s = 0; s < kSoftBodySteps; ++s) {
        world->step();
        const double a = world->areaErrorPercent(*body) / 100.0, e = world->maxEdgeStretch(*body);
        run.areaError += a * a;
        run.edgeError += e * e;
    }
    run.areaError = std::sqrt(run.areaError / kSoftBodySteps);
    run.edgeError = std::sqrt(run.edgeError / kSoftBodySteps);
    return run;
}
} // namespace

Expected<WorkPrecisionReport> softBody(const WorkPrecisionOptions& options)
{
    WorkPrecisionReport r;
    r.name = "soft-body";
    r.title = "Soft body: constraint error against substeps";
    r.knob = "substeps";
    r.error = "RMS relative violation over 240 steps (fall, impact, rest)";
    r.reference = "the constraints' own targets: rest edge lengths and target area";
    r.lesson = "XPBD's constraint error falls as the substeps grow (about 1/n^2), at a cost "
               "proportional to n; the seed's per-step corrections leave a lasting area deficit.";
    const Progress progress(options);
    const int maxLevel = options.quick ? 3 : 5; // substeps 1 … 2^maxLevel
    WorkPrecisionSeries area{"XPBD area", {}}, edges{"XPBD edge lengths", {}};
    double sink = 0;
    for (int level = 0; level <= maxLevel; ++level) {
        const int substeps = 1 << level;
        auto run = runXpbd(substeps);
        if (!run)
            return run.error();
        const double seconds = secondsPerCall([&] { return runXpbd(substeps)->areaError; }, options.minSecondsPerPoint, &sink) /
                               kSoftBodySteps;
        area.samples.push_back({double(substeps), std::max(run->areaError, 1e-18), seconds});
        edges.samples.push_back({double(substeps), std::max(run->edgeError, 1e-18), seconds});
        if (!progress.tick(level + 1, maxLevel + 2))
            return cancelled();
    }
    // The seed (Annex II) on the thesis's frog body: one setting, no substeps.
    auto scene = loadScene("frog");
    if (!scene)
        return scene.error();
    auto runSeed = [&scene]() -> Expected<double> {
        auto sim = Simulation::create(*scene, SolverKind::Seed);
        if (!sim)
            return sim.error();
        double sum = 0;
        for (int s = 0; s < kSoftBodySteps; ++s) {
            (*sim)->step();
            const double a = ((*sim)->bodyArea(0) - (*sim)->bodyTargetArea(0)) / (*sim)->bodyTargetArea(0);
            sum += a * a;
        }
        return std::sqrt(sum / kSoftBodySteps);
    };
    auto seedError = runSeed();
    if (!seedError)
        return seedError.error();
    const double seedSeconds = secondsPerCall([&] { return runSeed().value(); }, options.minSecondsPerPoint, &sink) /
                               kSoftBodySteps;
    r.series = {std::move(area), std::move(edges), {"seed area (Annex II)", {{1.0, *seedError, seedSeconds}}}};
    progress.tick(1, 1);
    return r;
}

} // namespace granota::reports
