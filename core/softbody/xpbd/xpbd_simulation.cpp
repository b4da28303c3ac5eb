// The stable (XPBD) solver behind Simulation: every scene, with the scene's components
// mapped onto constraints. A component the scene lacks is a constraint left out (or, for
// the springs and area of §4.1–4.3, one so compliant that it does nothing).
#include "core/softbody/scenes/scene_layout.h"
#include "core/base/math_constants.h"
#include "core/softbody/polygon_geometry.h"
#include "core/softbody/regular_polygon.h"
#include "core/softbody/simulation_backends.h"
#include "core/softbody/xpbd/xpbd_world.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace granota {

namespace {

constexpr double kNoConstraint = 1e12; // compliance of a constraint a scene does not have

XpbdParams paramsOf(const SceneSpec& s)
{
    XpbdParams p;
    p.gravity = s.has(SceneComponent::Gravity) ? s.params.gravity : Point(0, 0);
    p.damping = s.hasParam("friction") && !s.has(SceneComponent::Bounce) ? s.params.friction : Point(1, 1);
    // f > 1 would add energy every step (the seed lets it, its velmax clamp bounds it); the
    // constraint solver keeps at most all of the velocity.
    p.damping = Point(std::clamp(p.damping.x, 0.0, 1.0), std::clamp(p.damping.y, 0.0, 1.0));
    // The friction f of §4.3 is the share of speed kept at a bounce: a restitution.
    p.restitution = s.has(SceneComponent::Bounce) ? std::clamp(0.5 * (s.params.friction.x + s.params.friction.y), 0.0, 1.0) : 0.0;
    p.width = s.params.width;
    p.height = s.params.height;
    if (s.hasParam("velmax"))
        p.velmax = std::max(s.params.velmax, 1e-9);
    p.substeps = s.stable.substeps;
    p.edgeCompliance = s.has(SceneComponent::Springs) ? s.stable.edgeCompliance : kNoConstraint;
    p.edgeDampingRatio = s.has(SceneComponent::Springs) ? s.stable.edgeDampingRatio : 0.0;
    if (!s.has(SceneComponent::Area))
        p.areaCompliance = kNoConstraint;
    p.grabMode = s.grab;
    return p;
}

std::vector<Point> shapeAt(const SceneSpec& s, std::size_t i, Point centre)
{
    std::vector<Point> shape = customRestShape(s, i).value_or(regularPolygon(Point(0, 0), s.params.radius, s.params.sides));
    if (polygonArea(shape) <= 0) {
        // A body of radius 0 has no rest shape to keep; the stable solver needs one, so it
        // takes the regular polygon of the target area (or of 1 px² when that is 0 too).
        const double n = std::max<std::size_t>(3, shape.size());
        const double area = std::max(1.0, s.has(SceneComponent::Area) ? s.params.targetArea : 1.0);
        shape = regularPolygon(Point(0, 0), std::sqrt(2 * area / (n * std::sin(2 * kPi / n))), static_cast<int>(n));
    }
    for (Point& p : shape)
        p += centre;
    return shape;
}

class StableSimulation final : public Simulation {
public:
    StableSimulation(const SceneSpec& scene, XpbdWorld world) : Simulation(scene, SolverKind::Stable), m_world(std::move(world))
    {
    }
    std::unique_ptr<Simulation> clone() const override { return std::make_unique<StableSimulation>(*this); }

    Expected<void> build()
    {
        const SceneSpec& s = scene();
        if (s.model == SceneModel::Pendulum) {
            if (s.chain.empty())
                return makeError(ErrorCode::InvalidInput, "scene '" + s.name + "' needs a chain of link lengths");
            ChainDef chain;
            chain.anchor.point = s.params.center;
            chain.joints.push_back(s.params.center);
            for (double l : s.chain) // hanging straight down; a zero link is nudged to 1e-6 px
                chain.joints.emplace_back(s.params.center.x, chain.joints.back().y + std::max(l, 1e-6));
            if (s.has(SceneComponent::AngleLimits)) {
                chain.limits.push_back(AngleLimit{s.chainShoulderMin, s.chainShoulderMax, AngleReference::World});
                for (std::size_t k = 1; k < s.chain.size(); ++k)
                    chain.limits.push_back(AngleLimit{s.chainElbowMin, s.chainElbowMax, AngleReference::Parent});
            }
            auto c = addChain(chain);
            if (!c)
                return c.error();
            return {};
        }
        const auto starts = bodyStarts(s);
        BodyOptions options;
        options.bending = !s.shapes.empty() && s.has(SceneComponent::AngleLimits);
        options.collides = s.has(SceneComponent::Collisions);
        for (std::size_t i = 0; i < starts.size(); ++i) {
            const auto shape = shapeAt(s, i, starts[i]);
            // Without the area component the rest shape keeps its own area.
            const double target = s.has(SceneComponent::Area) ? s.params.targetArea : polygonArea(shape);
            auto b = m_world.addBody(shape, target, s.hasParam("v0") ? s.params.v0 : Point(0, 0), options);
            if (!b)
                return b.error();
        }
        if (s.model == SceneModel::Frog && s.has(SceneComponent::Legs))
            for (int leg = 0; leg < 4; ++leg) {
                const ChainAnchor anchor = frogLegAnchor(0, leg, s.params.sides);
                auto c = addChain(frogLegChain(s.params.legs[std::size_t(leg)], anchor, m_world.anchorPoint(anchor)));
                if (!c)
                    return c.error();
            }
        if (s.has(SceneComponent::Obstacles))
            for (const auto& o : s.obstacles) {
                auto ok = o.closed ? m_world.addPolygonObstacle(o.points) : m_world.addSegmentObstacle(o.points[0], o.points[1]);
                if (!ok)
                    return ok.error();
            }
        return {};
    }

    int substeps() const override { return m_world.params().substeps; }
    void applyStableSettings(const StableSettings& s) override
    {
        XpbdParams p = m_world.params();
        p.substeps = s.substeps;
        if (scene().has(SceneComponent::Springs)) { // without springs the edges stay unconstrained (paramsOf)
            p.edgeCompliance = s.edgeCompliance;
            p.edgeDampingRatio = s.edgeDampingRatio;
        }
        const auto ok = m_world.setParams(p);
        assert(ok);
        (void)ok;
    }
    int bodyCount() const override { return m_world.bodyCount(); }
    std::optional<EdgeSpring> edgeSpring(int i) const override
    {
        if (!scene().has(SceneComponent::Springs) || i < 0 || i >= bodyCount() || m_world.bodyRange(i).count < 2)
            return std::nullopt;
        const XpbdWorld::EdgeRest e = m_world.edgeRest(i, 0);
        return EdgeSpring{e.length, e.vertexMass};
    }
    // Copied into the caller's vector (its capacity reused): no allocation per frame.
    void bodyVertices(int i, std::vector<Point>& out) const override { copyRange(m_world.bodyRange(i), out); }
    double bodyArea(int i) const override { return std::abs(m_world.area(i)); }
    double bodyTargetArea(int i) const override { return m_world.targetArea(i); }
    int chainCount() const override { return m_world.chainCount(); }
    void chainJoints(int i, std::vector<Point>& out) const override { copyRange(m_world.chainRange(i), out); }
    void chainLimits(int i, std::vector<LinkLimit>& out) const override { out = m_limits[std::size_t(i)]; }

    bool press(Point p) override
    {
        if (scene().model == SceneModel::Pendulum) {
            move(p);
            return true;
        }
        if (scene().has(SceneComponent::Bounce) && !scene().has(SceneComponent::Grab)) { // §4.3: a click respawns
            respawnAt(p);
            return true;
        }
        return scene().has(SceneComponent::Grab) && m_world.press(p);
    }
    void move(Point p) override
    {
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            return;
        if (scene().model == SceneModel::Pendulum) {
            m_world.moveChainAnchor(0, p);
            return;
        }
        if (scene().components.empty() && bodyCount() == 1) { // §4.1: r = |mouseY − h/2|
            const double r = std::min(std::fabs(p.y - scene().params.height / 2), 10 * scene().params.height);
            const auto shape = regularPolygon(scene().params.center, r, scene().params.sides);
            m_world.setTargetArea(0, polygonArea(shape));
            m_world.setBodyVertices(0, shape);
            m_mouseRadius = r;
            return;
        }
        m_world.move(p);
    }
    void release() override { m_world.release(); }
    void spawn(Point p) override
    {
        if (m_world.grabbedBody() >= 0 || bodyCount() == 0)
            return;
        respawnAt(p);
        if (scene().has(SceneComponent::Grab) && scene().grab == GrabMode::Anchors) {
            // Annex II keeps vertex 0 10 px above the mouse and the body hanging below it
            // (seed_body_step.inc): spawn it there, so that the short ropes hold it hanging,
            // not balanced upside down on ropes as long as its height.
            const double y = std::clamp(p.y, 0.0, scene().params.height - 1);
            const double below = (y - 10) - m_world.bodyVertices(0).front().y;
            if (below > 0 && y + below <= scene().params.height - 1)
                respawnAt(Point(p.x, y + below));
        }
        if (scene().has(SceneComponent::Grab)) {
            m_world.press(p);
            m_spawned = true;
        }
    }
    void releaseSpawn() override
    {
        if (m_spawned)
            m_world.release();
        m_spawned = false;
    }
    bool grabbing() const override { return m_world.grabbedBody() >= 0; }
    std::optional<double> mouseRadius() const override
    {
        if (!(scene().components.empty() && bodyCount() == 1))
            return std::nullopt;
        return m_mouseRadius.value_or(scene().params.radius);
    }

    void broadPhasePairs(std::vector<std::pair<int, int>>& out) const override
    {
        out.clear();
        for (const BodyPair& p : m_world.contactPairs())
            out.emplace_back(p.first, p.second);
    }

    Readouts readouts() const override { return collectReadouts(nullptr); }
    void bodyReadouts(std::vector<Readouts>& out) const override { collectReadouts(&out); }
    Readouts readoutsAndBodies(std::vector<Readouts>& bodies) const override { return collectReadouts(&bodies); }

protected:
    void doStep() override { m_world.step(); }

private:
    /// The scene's readouts and, given `bodies`, each body's: a body's area, edges and area
    /// pressure are looked at once for both.
    Readouts collectReadouts(std::vector<Readouts>* bodies) const
    {
        const Point g = m_world.params().gravity;
        const double height = dot(g, potentialOrigin(g, scene().params.width, scene().params.height));
        // The energies per body in the world's own passes (motionEnergies, elasticEnergy).
        std::vector<XpbdWorld::BodyEnergies>* energies = bodies ? &m_energies : nullptr;
        if (bodies) {
            m_energies.assign(std::size_t(bodyCount()), XpbdWorld::BodyEnergies());
            m_world.bodyLosses(m_energies);
            bodies->resize(m_energies.size());
        }
        const XpbdWorld::MotionEnergies motion = m_world.motionEnergies(energies);
        Readouts r;
        r.elasticEnergy = m_world.elasticEnergy(energies);
        // The largest stretch of the scene from the largest and smallest L²/L₀² of all its
        // bodies: two square roots in all, not two a body.
        XpbdWorld::BodyShape all;
        for (int i = 0; i < bodyCount(); ++i) {
            const XpbdWorld::BodyShape shape = m_world.bodyShape(i);
            const double area = XpbdWorld::areaErrorPercent(shape.area, m_world.targetArea(i));
            const double force = std::max(std::abs(m_world.areaPressure(i)), shape.tension);
            r.areaErrorPercent += area / bodyCount();
            all.largestRatio2 = std::max(all.largestRatio2, shape.largestRatio2);
            all.smallestRatio2 = std::min(all.smallestRatio2, shape.smallestRatio2);
            all.tiny = std::max(all.tiny, shape.tiny);
            r.constraintForce = std::max(r.constraintForce, force);
            if (!bodies)
                continue;
            const XpbdWorld::BodyEnergies& e = m_energies[std::size_t(i)];
            Readouts& b = (*bodies)[std::size_t(i)];
            b.areaErrorPercent = area;
            b.maxStretch = shape.stretch();
            b.constraintForce = force;
            b.kineticEnergy = e.kinetic;
            b.potentialEnergy = e.gravity + e.movingMass * height; // as the scene's, below
            b.elasticEnergy = e.elastic;
            b.dampingLoss = e.dampingLoss;
            b.contacts = e.contacts;
        }
        r.maxStretch = all.stretch();
        for (int c = 0; c < chainCount(); ++c)
            r.constraintForce = std::max(r.constraintForce, m_world.angleLimitTorque(c));
        r.kineticEnergy = motion.kinetic;
        // Σ m g·(e − x) = Σ m g·e − Σ m g·x, with the masses the kinetic energy counts.
        r.potentialEnergy = motion.gravity + motion.movingMass * height;
        r.dampingLoss = m_world.dampingLoss();
        r.contacts = m_world.contactCount();
        return r;
    }

    /// Adds a chain to the world and keeps its limits as chainLimits gives them.
    Expected<int> addChain(const ChainDef& chain)
    {
        auto c = m_world.addChain(chain);
        if (c) {
            std::vector<LinkLimit> limits;
            for (const AngleLimit& l : chain.limits)
                limits.push_back({l.min, l.max, l.reference == AngleReference::Parent});
            m_limits.push_back(std::move(limits));
        }
        return c;
    }

    void copyRange(ParticleRange r, std::vector<Point>& out) const
    {
        const auto first = m_world.positions().begin() + r.first;
        out.assign(first, first + r.count);
    }

    void respawnAt(Point p)
    {
        p.x = std::clamp(p.x, 0.0, scene().params.width - 1);
        p.y = std::clamp(p.y, 0.0, scene().params.height - 1);
        m_world.setBodyVertices(0, shapeAt(scene(), 0, p));
        m_world.setBodyVelocity(0, Point(0, 0));
    }

    XpbdWorld m_world;
    mutable std::vector<XpbdWorld::BodyEnergies> m_energies; // scratch of bodyReadouts
    std::vector<std::vector<LinkLimit>> m_limits;            // per chain, as added
    bool m_spawned = false;
    std::optional<double> m_mouseRadius; // §4.1, once the mouse has moved
};

} // namespace

Expected<std::unique_ptr<Simulation>> makeStableSimulation(const SceneSpec& scene)
{
    auto world = XpbdWorld::create(paramsOf(scene));
    if (!world)
        return makeError(world.error().code, "scene '" + scene.name + "': " + world.error().message);
    auto sim = std::make_unique<StableSimulation>(scene, std::move(world).value());
    auto ok = sim->build();
    if (!ok)
        return ok.error();
    return std::unique_ptr<Simulation>(std::move(sim));
}

} // namespace granota
