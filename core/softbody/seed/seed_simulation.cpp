// The seed solver behind Simulation: Annex II's Verlet bodies and frog (§4.6–4.12,
// §4.16, and §5.2 without collisions, which the seed never had), and its pendulums
// (§4.13–4.15). Single precision, as Processing computes: with the thesis's constants the
// frog reproduces the reference trace bit for bit.
#include "core/softbody/seed/follow_chain.h"
#include "core/softbody/polygon_geometry.h"
#include "core/softbody/regular_polygon.h"
#include "core/softbody/seed/seed_frog.h"
#include "core/softbody/scenes/scene_layout.h"
#include "core/softbody/simulation_backends.h"

#include <algorithm>
#include <cmath>

namespace granota {

namespace {

using Real = float;

SeedComponents componentsOf(const SceneSpec& s)
{
    SeedComponents c;
    setSharedComponents(c, s);
    c.legs = s.has(SceneComponent::Legs);
    c.grab = s.has(SceneComponent::Grab);
    c.angleLimits = s.has(SceneComponent::AngleLimits);
    c.clampLegs = s.has(SceneComponent::LegsInFrame); // Annex II keeps only the wrists above the floor
    c.grabMode = s.grab;
    return c;
}

double edgeStretch(const std::vector<Point>& x, const std::vector<double>& rest)
{
    double worst = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
        if (rest[i] > 0)
            worst = std::max(worst, std::abs(distance(x[i], x[(i + 1) % x.size()]) / rest[i] - 1));
    return worst;
}

std::vector<double> edgeLengths(const std::vector<Point>& x)
{
    std::vector<double> l;
    for (std::size_t i = 0; i < x.size(); ++i)
        l.push_back(distance(x[i], x[(i + 1) % x.size()]));
    return l;
}

class SeedBodySimulation final : public Simulation {
public:
    SeedBodySimulation(const SceneSpec& scene) : Simulation(scene, SolverKind::Seed) {}
    SeedBodySimulation(const SeedBodySimulation& o)
        : Simulation(o), m_frog(o.m_frog ? std::make_unique<SeedFrog<Real>>(*o.m_frog) : nullptr), m_bodies(o.m_bodies),
          m_rest(o.m_rest), m_held(o.m_held), m_heldBody(o.m_heldBody)
    {
    }
    std::unique_ptr<Simulation> clone() const override { return std::make_unique<SeedBodySimulation>(*this); }

    Expected<void> build()
    {
        const SceneSpec& s = scene();
        const SeedComponents c = componentsOf(s);
        if (s.model == SceneModel::Frog) {
            auto frog = SeedFrog<Real>::create(s.params, c);
            if (!frog)
                return frog.error();
            m_frog = std::make_unique<SeedFrog<Real>>(std::move(frog).value());
            m_rest.push_back(edgeLengths(m_frog->body().vertices()));
            return {};
        }
        const auto at = bodyStarts(s);
        for (std::size_t i = 0; i < at.size(); ++i) {
            FrogParams p = s.params;
            p.center = at[i];
            const auto shape = customRestShape(s, i);
            auto body = shape ? SeedBody<Real>::createFromShape(p, *shape, c) : SeedBody<Real>::create(p, c);
            if (!body)
                return body.error();
            m_rest.push_back(edgeLengths(body->vertices()));
            m_bodies.push_back(std::move(body).value());
        }
        return {};
    }

    int bodyCount() const override { return m_frog ? 1 : static_cast<int>(m_bodies.size()); }
    bool jointsKeptInFrame() const override { return !m_frog || componentsOf(scene()).clampLegs; }
    // Written into the caller's vector (its capacity reused): no allocation per frame.
    void bodyVertices(int i, std::vector<Point>& out) const override
    {
        const SeedBody<Real>& b = body(i);
        const auto& v = b.seedVertices();
        out.resize(std::size_t(b.sides()));
        for (std::size_t k = 0; k < out.size(); ++k)
            out[k] = Point(double(v[k].pos.x), double(v[k].pos.y));
    }
    double bodyArea(int i) const override { return std::abs(double(body(i).area())); }
    double bodyTargetArea(int i) const override { return double(body(i).targetArea()); }
    int chainCount() const override { return m_frog ? static_cast<int>(m_frog->legs().size()) : 0; }
    void chainJoints(int i, std::vector<Point>& out) const override
    {
        const SeedLeg<Real>& l = m_frog->legs()[std::size_t(i)];
        out.resize(3);
        out[0] = Point(double(l.shoulder().x), double(l.shoulder().y));
        out[1] = Point(double(l.elbow().x), double(l.elbow().y));
        out[2] = Point(double(l.wrist().x), double(l.wrist().y));
    }
    // §4.15, Annex II l. 411–423: both angles from straight down the screen.
    void chainLimits(int i, std::vector<LinkLimit>& out) const override
    {
        out.clear();
        if (!m_frog || !componentsOf(scene()).angleLimits)
            return;
        const LegParams& l = scene().params.legs[std::size_t(i)];
        out = {{l.shoulderMin, l.shoulderMax, false}, {l.elbowMin, l.elbowMax, false}};
    }

    bool press(Point p) override
    {
        if (m_frog)
            return m_held = m_frog->press(p), m_held;
        for (std::size_t i = 0; i < m_bodies.size(); ++i)
            if (m_bodies[i].press(p)) {
                m_heldBody = static_cast<int>(i);
                return m_held = true;
            }
        return false;
    }
    void move(Point p) override
    {
        if (m_frog)
            m_frog->move(p);
        else
            for (auto& b : m_bodies)
                b.move(p);
    }
    void release() override
    {
        if (m_frog)
            m_frog->release();
        else if (m_heldBody >= 0)
            m_bodies[std::size_t(m_heldBody)].release();
        m_held = false;
        m_heldBody = -1;
    }
    void spawn(Point p) override
    {
        if (m_held)
            return;
        if (m_frog ? m_frog->respawn(p) : m_bodies.front().respawn(p)) {
            m_held = scene().has(SceneComponent::Grab);
            m_heldBody = 0;
        }
    }
    void releaseSpawn() override
    {
        if (m_frog)
            m_frog->releaseSpawn();
        else
            m_bodies.front().releaseSpawn();
        m_held = false;
        m_heldBody = -1;
    }
    bool grabbing() const override { return m_held; }

    Readouts readouts() const override { return readoutsAndBodies(m_bodyReadouts); }
    /// The scene's readouts: its bodies' (bodyReadout) summed.
    Readouts readoutsAndBodies(std::vector<Readouts>& bodies) const override
    {
        bodyReadouts(bodies);
        Readouts r;
        for (const Readouts& b : bodies) {
            r.areaErrorPercent += b.areaErrorPercent / bodyCount();
            r.maxStretch = std::max(r.maxStretch, b.maxStretch);
            r.constraintForce = std::max(r.constraintForce, b.constraintForce);
            r.kineticEnergy += b.kineticEnergy;
            r.potentialEnergy += b.potentialEnergy;
            r.contacts += b.contacts;
        }
        return r;
    }
    void bodyReadouts(std::vector<Readouts>& out) const override
    {
        out.resize(std::size_t(bodyCount()));
        for (int i = 0; i < bodyCount(); ++i)
            out[std::size_t(i)] = bodyReadout(i);
    }

    /// Body i's readouts: unit masses, velocities x − x_prev (Annex II's Verlet).
    Readouts bodyReadout(int i) const
    {
        Readouts r;
        const SeedBody<Real>& b = body(i);
        const auto x = b.vertices(), prev = b.previousVertices();
        if (b.targetArea() > 0)
            r.areaErrorPercent = 100 * (bodyArea(i) - double(b.targetArea())) / double(b.targetArea());
        r.maxStretch = edgeStretch(x, m_rest[std::size_t(i)]);
        for (const auto& c : b.corrections())
            r.constraintForce = std::max(r.constraintForce, std::hypot(double(c.x), double(c.y)));
        for (std::size_t k = 0; k < x.size(); ++k) {
            const Point v = x[k] - prev[k];
            r.kineticEnergy += 0.5 * dot(v, v);
        }
        const FrogParams& p = scene().params;
        if (scene().has(SceneComponent::Gravity))
            r.potentialEnergy = potentialEnergy(x, p.gravity, p.width, p.height);
        if (scene().has(SceneComponent::Bounds))
            r.contacts = pointsOnFrameEdge(x, p.width, p.height);
        return r;
    }

protected:
    void doStep() override
    {
        if (m_frog)
            m_frog->step();
        else
            for (auto& b : m_bodies)
                b.step();
    }

private:
    const SeedBody<Real>& body(int i) const { return m_frog ? m_frog->body() : m_bodies[std::size_t(i)]; }

    std::unique_ptr<SeedFrog<Real>> m_frog;
    std::vector<SeedBody<Real>> m_bodies;
    std::vector<std::vector<double>> m_rest;      // edge lengths at the start, per body
    mutable std::vector<Readouts> m_bodyReadouts; // scratch of readouts()
    bool m_held = false;
    int m_heldBody = -1;
};

/// §4.13 and §4.15 (a two-link `Pota` hanging from the mouse) and §4.14 (the chain that
/// follows its first joint).
class SeedPendulumSimulation final : public Simulation {
public:
    SeedPendulumSimulation(const SceneSpec& scene) : Simulation(scene, SolverKind::Seed), m_clau(scene.params.center) {}
    SeedPendulumSimulation(const SeedPendulumSimulation& o)
        : Simulation(o), m_clau(o.m_clau), m_leg(o.m_leg ? std::make_unique<SeedLeg<Real>>(*o.m_leg) : nullptr),
          m_chain(o.m_chain ? std::make_unique<FollowChain>(*o.m_chain) : nullptr)
    {
    }
    std::unique_ptr<Simulation> clone() const override { return std::make_unique<SeedPendulumSimulation>(*this); }

    Expected<void> build()
    {
        const SceneSpec& s = scene();
        if (s.chain.empty())
            return makeError(ErrorCode::InvalidInput, "scene '" + s.name + "' needs a chain of link lengths");
        if (!s.has(SceneComponent::Gravity)) { // §4.14: kinematic
            m_chain = std::make_unique<FollowChain>(m_clau, s.chain);
            return {};
        }
        if (s.chain.size() != 2)
            return makeError(ErrorCode::OutOfRange, "the seed's pendulum (Annex II's Pota) has exactly two links");
        LegParams leg;
        leg.upper = s.chain[0];
        leg.lower = s.chain[1];
        leg.shoulderMin = s.chainShoulderMin;
        leg.shoulderMax = s.chainShoulderMax;
        leg.elbowMin = s.chainElbowMin;
        leg.elbowMax = s.chainElbowMax;
        SeedComponents c = componentsOf(s);
        auto pendulum = SeedLeg<Real>::create(s.params, leg, m_clau, c);
        if (!pendulum)
            return pendulum.error();
        m_leg = std::make_unique<SeedLeg<Real>>(std::move(pendulum).value());
        return {};
    }

    int bodyCount() const override { return 0; }
    void bodyVertices(int, std::vector<Point>& out) const override { out.clear(); }
    double bodyArea(int) const override { return 0; }
    double bodyTargetArea(int) const override { return 0; }
    int chainCount() const override { return 1; }
    void chainJoints(int, std::vector<Point>& out) const override { out = m_leg ? m_leg->joints() : m_chain->joints(); }
    // Annex II's Pota is a leg: its elbow too is measured from straight down.
    void chainLimits(int, std::vector<LinkLimit>& out) const override
    {
        out.clear();
        const SceneSpec& s = scene();
        if (m_leg && componentsOf(s).angleLimits)
            out = {{s.chainShoulderMin, s.chainShoulderMax, false}, {s.chainElbowMin, s.chainElbowMax, false}};
    }

    // The pendulum hangs from the mouse (its "clau"), kept inside the frame.
    bool press(Point p) override
    {
        move(p);
        return true;
    }
    void move(Point p) override
    {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            return;
        m_clau = Point(std::clamp(p.x, 0.0, scene().params.width - 1), std::clamp(p.y, 0.0, scene().params.height - 1));
    }

    Readouts readouts() const override
    {
        Readouts r;
        std::vector<Point> joints;
        chainJoints(0, joints);
        for (std::size_t i = 1; i < joints.size(); ++i) {
            const double rest = scene().chain[i - 1];
            if (rest > 0)
                r.maxStretch = std::max(r.maxStretch, std::abs(distance(joints[i], joints[i - 1]) / rest - 1));
        }
        if (m_leg) {
            for (const auto* v : {&m_leg->elbowVertex(), &m_leg->wristVertex()}) {
                const Point d(double(v->pos.x - v->prev.x), double(v->pos.y - v->prev.y));
                r.kineticEnergy += 0.5 * dot(d, d);
            }
            joints.erase(joints.begin()); // the clau does not fall
            r.potentialEnergy = potentialEnergy(joints, scene().params.gravity, scene().params.width, scene().params.height);
        }
        if (scene().has(SceneComponent::Bounds))
            r.contacts = pointsOnFrameEdge(joints, scene().params.width, scene().params.height);
        return r;
    }

protected:
    void doStep() override
    {
        if (m_leg)
            m_leg->step(m_clau);
        else
            m_chain->follow(m_clau);
    }

private:
    Point m_clau;
    std::unique_ptr<SeedLeg<Real>> m_leg;
    std::unique_ptr<FollowChain> m_chain;
};

} // namespace

Expected<std::unique_ptr<Simulation>> makeSeedBodySimulation(const SceneSpec& scene)
{
    auto sim = std::make_unique<SeedBodySimulation>(scene);
    auto ok = sim->build();
    if (!ok)
        return ok.error();
    return std::unique_ptr<Simulation>(std::move(sim));
}

Expected<std::unique_ptr<Simulation>> makeSeedPendulumSimulation(const SceneSpec& scene)
{
    auto sim = std::make_unique<SeedPendulumSimulation>(scene);
    auto ok = sim->build();
    if (!ok)
        return ok.error();
    return std::unique_ptr<Simulation>(std::move(sim));
}

} // namespace granota
