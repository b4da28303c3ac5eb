#include "core/softbody/simulation.h"

#include "core/base/enum_names.h"

#include "core/softbody/simulation_backends.h"

#include <cmath>

namespace granota {

namespace {

constexpr std::array<EnumName<SolverKind>, 2> kSolverNames{{{SolverKind::Seed, "seed"}, {SolverKind::Stable, "stable"}}};

} // namespace

std::optional<SolverKind> parseSolverKind(std::string_view name) { return parseName(kSolverNames, name); }

std::string solverName(SolverKind s) { return std::string(nameOf(kSolverNames, s, "stable")); }

Expected<std::unique_ptr<Simulation>> Simulation::create(const SceneSpec& scene, SolverKind solver)
{
    if (solver == SolverKind::Stable)
        return makeStableSimulation(scene);
    switch (scene.model) {
    case SceneModel::Stage: return makeStageSimulation(scene);
    case SceneModel::Pendulum: return makeSeedPendulumSimulation(scene);
    case SceneModel::Body:
    case SceneModel::Frog: return makeSeedBodySimulation(scene);
    }
    return makeError(ErrorCode::InvalidInput, "unknown scene model");
}

namespace {
template <class F> bool allPoints(const Simulation& s, F pred, bool joints = true)
{
    std::vector<Point> pts;
    for (int i = 0; i < s.bodyCount(); ++i) {
        s.bodyVertices(i, pts);
        for (const Point& p : pts)
            if (!pred(p))
                return false;
    }
    for (int i = 0; joints && i < s.chainCount(); ++i) {
        s.chainJoints(i, pts);
        for (const Point& p : pts)
            if (!pred(p))
                return false;
    }
    return true;
}
} // namespace

std::size_t Simulation::pointCount() const
{
    std::size_t n = 0;
    std::vector<Point> pts;
    for (int i = 0; i < bodyCount(); ++i) {
        bodyVertices(i, pts);
        n += pts.size();
    }
    for (int c = 0; c < chainCount(); ++c) {
        chainJoints(c, pts);
        n += pts.size();
    }
    return n;
}

bool Simulation::finite() const
{
    for (int i = 0; i < bodyCount(); ++i)
        if (!std::isfinite(bodyArea(i)))
            return false;
    return allPoints(*this, [](const Point& p) { return std::isfinite(p.x) && std::isfinite(p.y); });
}

bool Simulation::inBounds(double slack) const
{
    const double w = m_scene.params.width - 1, h = m_scene.params.height - 1;
    return allPoints(
        *this, [&](const Point& p) { return p.x >= -slack && p.x <= w + slack && p.y >= -slack && p.y <= h + slack; },
        jointsKeptInFrame());
}

bool seedRoundsShapes(const SceneSpec& scene) { return !scene.shapes.empty(); }

Point potentialOrigin(Point g, double width, double height)
{
    // The edge gravity pulls towards: x = W−1 when g.x > 0, x = 0 when g.x < 0.
    return Point(g.x > 0 ? width - 1 : 0, g.y > 0 ? height - 1 : 0);
}

double potentialEnergy(const std::vector<Point>& points, Point g, double width, double height)
{
    const Point e = potentialOrigin(g, width, height);
    double u = 0;
    for (const Point& p : points)
        u += g.x * (e.x - p.x) + g.y * (e.y - p.y);
    return u;
}

int pointsOnFrameEdge(const std::vector<Point>& points, double width, double height)
{
    int n = 0;
    for (const Point& p : points)
        if (!(p.x > 0 && p.x < width - 1 && p.y > 0 && p.y < height - 1))
            ++n;
    return n;
}

} // namespace granota
