#pragma once
/// \file simulation.h
/// One running scene: the scene's components built on the chosen solver, stepped at a
/// fixed step, driven by the mouse and the space bar as in Annex II — headless, so that
/// the GUI canvas stays thin and tests can drive grabs. Both solvers sit behind this one
/// interface so a student can switch and compare:
///  - `seed`: the thesis's own schemes (§4.1–4.5 explicit velocities, Annex II's Verlet
///    body, legs and pendulums), reproduced faithfully;
///  - `stable`: beyond the thesis, position-based constraints with compliance (XPBD).

#include "core/base/expected.h"
#include "core/softbody/scenes/scene.h"

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace granota {

enum class SolverKind { Seed, Stable };
/// "seed", "stable", exactly (case and blanks count); nullopt for anything else.
std::optional<SolverKind> parseSolverKind(std::string_view name);
std::string solverName(SolverKind s);

/// Teaching readouts (docs/scenes.md overlays, issue: "readouts from both solvers").
struct Readouts {
    double areaErrorPercent = 0; ///< mean over bodies of 100·(A − A₀)/A₀ (0 when A₀ = 0)
    double maxStretch = 0;       ///< largest |edge length / rest length − 1|
    double constraintForce = 0;  ///< largest constraint force (stable: |λ|/h²; seed: largest correction, px/step²)
    double kineticEnergy = 0;    ///< Σ ½ m |v|², px²/step² (the seed: unit masses)
    double potentialEnergy = 0;  ///< Σ m g·(height above the frame edge gravity points to), px²/step²
    /// Σ ½ α F² over the compliant constraints (springs, area, bending; F = λ/h²), stable
    /// solver only: the seed's springs and area are position corrections, not forces, so
    /// they store no energy one could name (nullopt).
    std::optional<double> elasticEnergy;
    /// What damping (the seed's fregament, friction per axis) has taken from the kinetic
    /// energy since the start, stable solver only (XpbdWorld::dampingLoss).
    std::optional<double> dampingLoss;
    /// Contacts now: the stable solver's (XpbdWorld::contactCount); for the seed, the
    /// points lying on the frame's edge, where its walls hold them.
    int contacts = 0;
};

/// The readouts' total energy: kinetic + gravitational + elastic (where the solver knows it).
inline double totalEnergy(const Readouts& r) { return r.kineticEnergy + r.potentialEnergy + r.elasticEnergy.value_or(0); }

/// §4.15's limit of one link of a chain: its angle (seed_angle.h) kept in [min, max], rad,
/// measured from straight down the screen or, `fromParent`, from the link before it.
struct LinkLimit {
    double min = 0;
    double max = 0;
    bool fromParent = false;
    bool operator==(const LinkLimit& o) const { return min == o.min && max == o.max && fromParent == o.fromParent; }
};

/// Steps per second: one step is one frame of Processing's default 60 frames per second.
inline constexpr int kStepsPerSecond = 60;

class Simulation {
public:
    virtual ~Simulation() = default;

    /// Builds `scene` on `solver`. Errors: parameters that make no sense for it.
    static Expected<std::unique_ptr<Simulation>> create(const SceneSpec& scene, SolverKind solver);
    /// An independent copy of the whole state, step count and grab included: stepped with the
    /// same input it goes through the same bits (the snapshots of a recorded run).
    virtual std::unique_ptr<Simulation> clone() const = 0;

    const SceneSpec& scene() const { return m_scene; }
    SolverKind solver() const { return m_solver; }
    long stepCount() const { return m_steps; }

    /// One fixed step (one `actualitza()` of the seed).
    void step()
    {
        doStep();
        ++m_steps;
    }

    /// Substeps per step: the stable solver's n (XpbdParams::substeps), 1 for the seed.
    virtual int substeps() const { return 1; }
    /// The stable solver's knobs in force: the scene's (SceneSpec::stable) until
    /// setStableSettings changes them.
    const StableSettings& stableSettings() const { return m_stable; }
    /// Turns the knobs live (docs/solvers.md#knobs): the run goes on from its state with them
    /// from the next step. The seed keeps them, to hand on, and steps as Annex II does.
    /// Values out of range (StableSettings::valid): false, and nothing changes.
    bool setStableSettings(const StableSettings& settings)
    {
        if (!settings.valid())
            return false;
        m_stable = settings;
        applyStableSettings(settings);
        return true;
    }
    /// The stable solver's spring of body i's first edge: its rest length, px, and the mass of
    /// a vertex on it (what edgeRingPeriodSteps and edgeRingHertz take); nullopt on the seed
    /// and without springs.
    struct EdgeSpring {
        double restLength = 0;
        double vertexMass = 0;
    };
    virtual std::optional<EdgeSpring> edgeSpring(int) const { return std::nullopt; }
    /// Every body's vertices and every chain's joints.
    std::size_t pointCount() const;
    /// The counted work of one step, pointCount() × substeps(): what the frog's run budgets
    /// its frames by (ui/frog/frog_run.cpp). The stable solver costs 45 ns to 480 ns per unit
    /// (a body of 100 sides to one of 10000: 37 µs to 39 ms a step), the seed less.
    long workPerStep() const { return static_cast<long>(pointCount()) * substeps(); }

    /// Soft bodies (none in the pendulum scenes).
    virtual int bodyCount() const = 0;
    /// The distinct vertices of body i, in order, written into `out`.
    virtual void bodyVertices(int i, std::vector<Point>& out) const = 0;
    virtual double bodyArea(int i) const = 0;
    virtual double bodyTargetArea(int i) const = 0;
    /// Chains of joints: the frog's legs (front right, front left, back right, back left)
    /// or the pendulum; each from its fixed end (shoulder, clau) outwards.
    virtual int chainCount() const { return 0; }
    virtual void chainJoints(int, std::vector<Point>&) const {}
    /// The limits the solver keeps chain i's links in, first link first, as it measures them
    /// (the seed's pendulum measures its second link from straight down, the stable solver's
    /// from the first); empty for a chain without limits.
    virtual void chainLimits(int, std::vector<LinkLimit>& out) const { out.clear(); }
    /// The obstacles of §5.2.1 as the scene gives them.
    const std::vector<ObstacleSpec>& obstacles() const { return m_scene.obstacles; }

    /// Mouse and keyboard (Annex II): press/move/release of the left button, and the
    /// space bar (spawn a new body at the mouse, held until released).
    virtual bool press(Point) { return false; }
    virtual void move(Point) {}
    virtual void release() {}
    virtual void spawn(Point) {}
    virtual void releaseSpawn() {}
    virtual bool grabbing() const { return false; }

    virtual Readouts readouts() const = 0;
    /// Each body's own readouts, one per body (the plots per body): the same quantities over
    /// that body's vertices and constraints and the legs that hang from it; its area error
    /// and largest stretch are its own. Summed over the bodies (mean, largest for those two)
    /// they give readouts(), but for a chain that hangs from no body (the pendulums).
    virtual void bodyReadouts(std::vector<Readouts>& out) const { out.clear(); }
    /// readouts() and bodyReadouts(bodies) at once, for less than the two cost apart (a
    /// sample of the plots per body, every step).
    virtual Readouts readoutsAndBodies(std::vector<Readouts>& bodies) const
    {
        bodyReadouts(bodies);
        return readouts();
    }
    /// §5.2.2's broad phase: the pairs of bodies (first < second) whose boxes, grown by the
    /// step's motion, overlapped in the last step — the candidates the contacts were tested
    /// on. None on the seed, which has no collisions.
    virtual void broadPhasePairs(std::vector<std::pair<int, int>>& out) const { out.clear(); }
    /// §4.1's polygon (the `polygon` stage, no components): the radius the mouse has set,
    /// r = |mouseY − h/2|, or the scene's radius before the mouse has moved; nullopt in every
    /// other scene. The Frog tab's radius field shows it.
    virtual std::optional<double> mouseRadius() const { return std::nullopt; }

    /// Every coordinate finite, every body vertex, and every joint where jointsKeptInFrame(),
    /// inside [0, W−1] × [0, H−1] (within `slack` px).
    bool finite() const;
    bool inBounds(double slack = 1e-6) const;
    /// False for the seed's frog, whose legs may reach past the frame as in Annex II
    /// (only the wrists are kept above the floor) unless the scene names `legs-in-frame`.
    virtual bool jointsKeptInFrame() const { return true; }

protected:
    Simulation(SceneSpec scene, SolverKind solver) : m_scene(std::move(scene)), m_solver(solver), m_stable(m_scene.stable) {}
    Simulation(const Simulation&) = default;
    Simulation& operator=(const Simulation&) = delete;
    virtual void doStep() = 0;
    /// The solver's part of setStableSettings (already checked): none for the seed.
    virtual void applyStableSettings(const StableSettings&) {}

private:
    SceneSpec m_scene;
    SolverKind m_solver;
    StableSettings m_stable;
    long m_steps = 0;
};

/// An area error past ±100 % (Readouts::areaErrorPercent) that is also 100 points away from
/// the error the scene started with: the body has blown up, as the seed's explicit schemes
/// can on extreme settings (a +9096 % was seen). The Frog tab then says to press Reset or to
/// switch to the stable solver. (§4.5's `area` stage starts at +112 %, a polygon twice its
/// target area, and shrinks: that is no explosion.) Not finite: blown up.
inline constexpr double kBlownUpAreaErrorPercent = 100;
inline bool blownUp(double areaErrorPercent, double startAreaErrorPercent)
{
    const double k = kBlownUpAreaErrorPercent;
    return !(std::abs(areaErrorPercent) <= k || std::abs(areaErrorPercent - startAreaErrorPercent) <= k);
}

/// Whether the seed solver cannot keep the form of `scene`'s bodies: it has no angle
/// constraints, so the `shapes` of §5.2.3 (a star, a rectangle, an L) round into blobs under
/// its springs and area (docs/solvers.md). The Frog tab says so.
bool seedRoundsShapes(const SceneSpec& scene);

/// Potential energy of unit masses at `points` under gravity g, measured from the frame
/// edge that gravity points to (so it is ≥ 0 inside the frame).
double potentialEnergy(const std::vector<Point>& points, Point gravity, double width, double height);
/// The point of the frame edge gravity points to, from which potentialEnergy measures.
Point potentialOrigin(Point gravity, double width, double height);
/// How many of `points` lie on the frame [0, W−1] × [0, H−1]'s edge (or past it).
int pointsOnFrameEdge(const std::vector<Point>& points, double width, double height);

} // namespace granota
