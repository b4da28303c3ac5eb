#include "core/softbody/simulation_trace.h"

#include "core/softbody/seed/seed_trace.h"

namespace granota {

namespace {

std::string number(const Simulation& sim, double v)
{
    return sim.solver() == SolverKind::Seed ? seedTraceNumber(static_cast<float>(v)) : seedTraceNumber(v);
}

std::string chainName(const Simulation& sim, int chain, int joint)
{
    if (sim.scene().model == SceneModel::Frog && sim.chainCount() == 4 && joint <= 2) {
        static const char* const legs[] = {"front_right", "front_left", "back_right", "back_left"};
        return std::string(legs[chain]) + (joint == 1 ? "_elbow" : "_wrist");
    }
    return "chain" + std::to_string(chain) + "_joint" + std::to_string(joint);
}

} // namespace

std::size_t simulationTracePoints(const Simulation& sim)
{
    std::size_t n = 0;
    std::vector<Point> pts;
    for (int b = 0; b < sim.bodyCount(); ++b) {
        sim.bodyVertices(b, pts);
        n += pts.size();
    }
    for (int c = 0; c < sim.chainCount(); ++c) {
        sim.chainJoints(c, pts);
        n += pts.empty() ? 0 : pts.size() - 1;
    }
    return n;
}

std::string simulationTraceHeader(const Simulation& sim)
{
    std::string h = "step";
    std::vector<Point> pts;
    for (int b = 0; b < sim.bodyCount(); ++b) {
        sim.bodyVertices(b, pts);
        const std::string prefix = b == 0 ? "" : "b" + std::to_string(b) + "_";
        for (std::size_t i = 0; i < pts.size(); ++i)
            h += "," + prefix + "v" + std::to_string(i) + "x," + prefix + "v" + std::to_string(i) + "y";
    }
    for (int c = 0; c < sim.chainCount(); ++c) {
        sim.chainJoints(c, pts);
        for (std::size_t j = 1; j < pts.size(); ++j) {
            const std::string name = chainName(sim, c, static_cast<int>(j));
            h += "," + name + "_x," + name + "_y";
        }
    }
    return h;
}

std::string simulationTraceRow(const Simulation& sim)
{
    std::string row = std::to_string(sim.stepCount());
    std::vector<Point> pts;
    for (int b = 0; b < sim.bodyCount(); ++b) {
        sim.bodyVertices(b, pts);
        for (const Point& p : pts)
            row += "," + number(sim, p.x) + "," + number(sim, p.y);
    }
    for (int c = 0; c < sim.chainCount(); ++c) {
        sim.chainJoints(c, pts);
        for (std::size_t j = 1; j < pts.size(); ++j)
            row += "," + number(sim, pts[j].x) + "," + number(sim, pts[j].y);
    }
    return row;
}

} // namespace granota
