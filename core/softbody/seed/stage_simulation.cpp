// §4.1–4.5 on the seed's explicit scheme.
#include "core/softbody/polygon_geometry.h"
#include "core/base/math_constants.h"
#include "core/softbody/simulation_backends.h"
#include "core/softbody/seed/stage_body.h"

#include <algorithm>
#include <cmath>

namespace granota {

namespace {

class StageSimulation final : public Simulation {
public:
    StageSimulation(const SceneSpec& scene, StageBody body) : Simulation(scene, SolverKind::Seed), m_body(std::move(body)) {}
    std::unique_ptr<Simulation> clone() const override { return std::unique_ptr<Simulation>(new StageSimulation(*this)); }

    int bodyCount() const override { return 1; }
    void bodyVertices(int, std::vector<Point>& out) const override { out = m_body.vertices(); }
    double bodyArea(int) const override { return polygonArea(m_body.vertices()); }
    double bodyTargetArea(int) const override
    {
        return scene().has(SceneComponent::Area) ? scene().params.targetArea : restArea();
    }

    // §4.1: the radius follows the mouse; §4.3 on: a click respawns at the mouse.
    bool press(Point p) override
    {
        if (scene().has(SceneComponent::Bounce)) {
            m_body.respawn(p);
            return true;
        }
        return false;
    }
    void move(Point p) override
    {
        if (scene().components.empty())
            m_body.followMouse(p);
    }
    std::optional<double> mouseRadius() const override
    {
        return scene().components.empty() ? std::optional<double>(m_body.radius()) : std::nullopt;
    }

    Readouts readouts() const override
    {
        Readouts r;
        const auto& x = m_body.vertices();
        const double target = bodyTargetArea(0);
        if (target > 0)
            r.areaErrorPercent = 100 * (polygonArea(x) - target) / target;
        const double rest = scene().has(SceneComponent::Springs) ? scene().params.springLength
                                                                 : 2 * m_body.radius() * std::sin(kPi / x.size());
        for (std::size_t i = 0; i < x.size(); ++i)
            if (rest > 0)
                r.maxStretch = std::max(r.maxStretch, std::abs(distance(x[i], x[(i + 1) % x.size()]) / rest - 1));
        for (const Point& v : m_body.velocities())
            r.kineticEnergy += 0.5 * dot(v, v);
        if (scene().has(SceneComponent::Gravity))
            r.potentialEnergy = potentialEnergy(x, scene().params.gravity, scene().params.width, scene().params.height);
        if (scene().has(SceneComponent::Bounds))
            r.contacts = pointsOnFrameEdge(x, scene().params.width, scene().params.height);
        return r;
    }
    /// One body: its readouts are the scene's.
    void bodyReadouts(std::vector<Readouts>& out) const override { out.assign(1, readouts()); }

protected:
    void doStep() override { m_body.step(); }

private:
    double restArea() const
    {
        const double n = scene().params.sides, r = m_body.radius();
        return 0.5 * n * r * r * std::sin(2 * kPi / n);
    }
    StageBody m_body;
};

} // namespace

Expected<std::unique_ptr<Simulation>> makeStageSimulation(const SceneSpec& scene)
{
    StageComponents c;
    setSharedComponents(c, scene);
    c.bounce = scene.has(SceneComponent::Bounce);
    FrogParams params = scene.params;
    if (!scene.hasParam("v0"))
        params.v0 = Point(0, 0); // §4.1's polygon does not move
    auto body = StageBody::create(params, c);
    if (!body)
        return body.error();
    return std::unique_ptr<Simulation>(new StageSimulation(scene, std::move(body).value()));
}

} // namespace granota
