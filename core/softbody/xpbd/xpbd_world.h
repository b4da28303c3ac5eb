#pragma once
/// \file xpbd_world.h
/// The `stable` solver: soft bodies as particles held by constraints, solved with XPBD
/// (Macklin, Müller and Chentanez 2016, "XPBD: position-based simulation of compliant
/// constrained dynamics") in substeps (Macklin, Storey, Lu et al. 2019, "Small steps in
/// physics simulation"), with contacts after Müller, Macklin, Chentanez, Jeschke and Kim
/// 2020 ("Detailed rigid body simulation with extended position based dynamics"). Where
/// the seed (Annex II) corrects lengths and area by ad-hoc factors (C = reescala, 5 passes,
/// averaged corrections), here each constraint has a compliance — a physical stiffness —
/// and the area constraint is exact.
///
/// One step (one frame of the seed) is n substeps of length h = dt/n. Each substep:
///   1. predict: v ← f^h ⊙ v + g h (damping per axis, gravity), x_prev ← x, x ← x + v h;
///   2. one pass over the constraints, λ starting at 0: per body its ring of edges
///      (averaged Jacobi, see solveEdgeRing), its area (C = A − A₀, shoelace area) and its
///      bending — or shape matching while it is invalid; the mouse ties; the contacts with
///      obstacles and between bodies; the chains (links and angle limits, a few passes out
///      and back, after everything that moves the bodies they hang from); and last the
///      frame's walls, so that nothing ever leaves it;
///   3. v ← (x − x_prev)/h, with restitution at walls and obstacles and Coulomb friction
///      between bodies at the velocity level (Müller et al. 2020, eq. 30).
/// The broad phase of body–body contacts runs once per step on boxes grown by the motion
/// of the step. After the step each body is checked: if it has turned inside out, lost
/// most of its area or crosses itself, its elastic constraints are switched off and shape
/// matching pulls it back to its rest shape until it is valid again.
///
/// Memory: flat arrays of particles and constraints, sized when bodies are added; a step
/// allocates nothing once the contact lists have reached their working size. Same input,
/// same bits: the order of every loop is fixed.

#include "core/base/expected.h"
#include "core/base/vec2.h"
#include "core/softbody/xpbd/xpbd_broad_phase.h"
#include "core/softbody/xpbd/xpbd_chain.h"
#include "core/softbody/xpbd/xpbd_collisions.h"
#include "core/softbody/xpbd/xpbd_constraints.h"
#include "core/softbody/xpbd/xpbd_params.h"

#include <limits>
#include <vector>

namespace granota {

struct BodyOptions {
    double mass = 10;     ///< total mass, mass units, shared equally by the vertices (the seed's frog: 10 × 1)
    bool bending = false; ///< keep the angles between consecutive edges: non-regular shapes keep their form (§5.2.3)
    bool collides = true; ///< takes part in body–body contacts (§5.2.2)
};

/// The particles [first, first + count) of a body or chain in positions().
struct ParticleRange {
    int first = 0;
    int count = 0;
};

class XpbdWorld {
public:
    /// A world with no bodies, or an error naming the first bad parameter.
    static Expected<XpbdWorld> create(const XpbdParams& params = {});

    const XpbdParams& params() const { return m_params; }
    /// Changes the parameters live (stiffness, gravity, frame size, …); bad values are
    /// rejected and nothing changes.
    Expected<void> setParams(const XpbdParams& params);

    /// Adds a body: any simple polygon (regularPolygon's, or another shape). The rest shape
    /// is scaled about its centroid to `targetArea` (px², ≥ 0; the seed's Areal), which
    /// sets the rest lengths of the edges; the body starts where `restShape` lies (points
    /// outside the frame are moved in, as Annex II l. 188–192) moving at `velocity` (px/step).
    /// A clockwise-on-screen order (regularPolygon's) is kept; the other order is reversed
    /// keeping vertex 0 first. Returns the body's index.
    Expected<int> addBody(const std::vector<Point>& restShape, double targetArea, Point velocity,
                          const BodyOptions& options = {});

    /// The regular polygon of §4.1 (regularPolygon, first vertex on top) as a body; rejects
    /// sides < 3, a radius ≤ 0 and non-finite numbers with a message.
    Expected<int> addRegularBody(Point centre, double radius, int sides, double targetArea, Point velocity,
                                 const BodyOptions& options = {});

    /// Adds a chain (pendulum, leg); returns its index.
    Expected<int> addChain(const ChainDef& chain);

    /// Adds a fixed thick segment ab (radius = half thickness, px); returns its index.
    Expected<int> addSegmentObstacle(Point a, Point b, double radius = 2);
    /// Adds a fixed polygon (simple, convex or not); returns its index.
    Expected<int> addPolygonObstacle(const std::vector<Point>& polygon);

    /// Changes a body's target area live (rescales its rest shape).
    Expected<void> setTargetArea(int body, double targetArea);

    /// Moves a body's vertices (teleport: velocity 0), for tests and editors.
    Expected<void> setBodyVertices(int body, const std::vector<Point>& vertices);
    /// Sets the velocity of every vertex of a body, px/step.
    Expected<void> setBodyVelocity(int body, Point velocity);
    /// Sets each vertex's velocity (a spin, a wobble), px/step.
    Expected<void> setBodyVelocities(int body, const std::vector<Point>& velocities);

    /// Moves the fixed first joint of a chain (the seed's nail following the mouse, §4.14);
    /// the joint travels there during the next step. Ignored for body-anchored chains.
    void moveChainAnchor(int chain, Point p);

    /// Advances one step (one frame).
    void step();

    // --- Grabbing (the GUI's mouse; §4.6, §4.7, Annex II l. 34–53) ---
    /// Grabs the topmost body whose polygon contains p (§4.6's test): the anchor vertices
    /// (XpbdParams::grabMode) are tied to the mouse by compliant ropes of their present
    /// length, each pulling with at most grabMaxForce. Returns false (and grabs nothing) when
    /// no body contains p, p is not finite, or a body is already held.
    bool press(Point p);
    /// Moves the mouse; points outside the frame are brought to its edge.
    void move(Point p);
    /// Lets go; the body keeps the mouse's velocity of the last step.
    void release();
    int grabbedBody() const { return m_grabBody; }
    /// Particle indices tied to the mouse (empty when nothing is held).
    const std::vector<int>& grabAnchorParticles() const { return m_grabIdx; }
    Point mouse() const { return m_mouse; }

    // --- State ---
    int bodyCount() const { return static_cast<int>(m_bodies.size()); }
    int chainCount() const { return static_cast<int>(m_chains.size()); }
    int obstacleCount() const { return static_cast<int>(m_obstacles.size()); }
    int particleCount() const { return static_cast<int>(m_x.size()); }
    long stepCount() const { return m_steps; }
    /// Every particle's position, px: bodies' vertices and chains' joints (see the ranges).
    const std::vector<Point>& positions() const { return m_x; }
    const std::vector<Point>& velocities() const { return m_v; }
    ParticleRange bodyRange(int body) const;
    ParticleRange chainRange(int chain) const;
    std::vector<Point> bodyVertices(int body) const;
    std::vector<Point> chainJoints(int chain) const;
    const XpbdObstacle& obstacle(int index) const { return m_obstacles[static_cast<std::size_t>(index)]; }
    std::vector<Point> obstaclePoints(int index) const;
    /// The point a chain anchor designates now, px.
    Point anchorPoint(const ChainAnchor& anchor) const;
    /// Body pairs the broad phase found in the last step (for overlays and tests).
    const std::vector<BodyPair>& contactPairs() const { return m_pairs; }
    double gridCellSize() const { return m_grid.cellSize(); }

    // --- Readouts for teaching ---
    double area(int body) const;                                ///< signed area, px² (positive unless inside out)
    double targetArea(int body) const;                          ///< px²
    double areaErrorPercent(int body) const;                    ///< 100 (A − A₀)/A₀ (A₀ taken ≥ 1 px²)
    static double areaErrorPercent(double area, double target); ///< the same of an area A and a target A₀
    double maxEdgeStretch(int body) const;                      ///< max |L − L₀|/L₀ over the edges (L₀ taken ≥ 1 px)
    double areaPressure(int body) const;                        ///< λ/h² of the area constraint, mass/step² (> 0 pushes out)
    double maxEdgeTension(int body) const;    ///< max −λ/h² over the edges, mass·px/step² (> 0 = stretched)
    double angleLimitTorque(int chain) const; ///< max |λ|/h² over the chain's angle limits (0 when none is hit)
    Point centroid(int body) const;           ///< mean of the vertices, px
    /// Edge k of a body (from vertex k to k + 1): its rest length, px, and its first vertex's mass.
    struct EdgeRest {
        double length = 0, vertexMass = 0;
    };
    EdgeRest edgeRest(int body, int edge) const;
    double orientation(int body) const; ///< best-fit rotation from the rest shape, rad
    bool recovering(int body) const;    ///< shape matching is pulling the body back
    bool isValid(int body) const;       ///< positive area above 20 % of the target, no self-crossing
    double kineticEnergy() const;       ///< Σ ½ m |v|², mass·px²/step²
    double gravityEnergy() const;       ///< Σ −m g·x (zero at the origin), mass·px²/step²
    struct BodyEnergies;
    /// Σ ½ α F² (F = λ/h²) over compliant constraints, mass·px²/step²; with `bodies`
    /// (bodyCount() entries), each constraint's also added to its body's `elastic`.
    double elasticEnergy(std::vector<BodyEnergies>* bodies = nullptr) const;
    double potentialEnergy() const { return gravityEnergy() + elasticEnergy(); }
    /// Σ m over the particles that move (inverse mass > 0), mass units.
    double movingMass() const;
    /// area(body), maxEdgeStretch(body) and maxEdgeTension(body) in one pass over its
    /// vertices and edges, without a square root: the readouts of every step.
    struct BodyShape {
        double area = 0;    ///< signed, px², as area(body)
        double tension = 0; ///< as maxEdgeTension(body)
        /// Largest and smallest L²/L₀² over the edges of 1 px or more at rest (smallest >
        /// largest when there is none), and max |L − L₀| over those under 1 px.
        double largestRatio2 = 0, smallestRatio2 = std::numeric_limits<double>::infinity(), tiny = 0;
        /// maxEdgeStretch(body): max |L − L₀| / max(L₀, 1), from the two ratios' square roots.
        double stretch() const;
    };
    BodyShape bodyShape(int body) const;
    /// kineticEnergy(), gravityEnergy() and movingMass() in one pass (the masses are kept, so
    /// no division): what a readout of every step costs (the plots over time) on 10⁴ particles.
    struct MotionEnergies {
        double kinetic = 0, gravity = 0, movingMass = 0;
    };
    /// With `bodies` (bodyCount() entries), each particle's also added to its body's.
    MotionEnergies motionEnergies(std::vector<BodyEnergies>* bodies = nullptr) const;
    /// What the damping f^h of the predict step (the seed's fregament) has taken from the
    /// kinetic energy since the world was made: Σ ½ m ((1 − k_x²) v_x² + (1 − k_y²) v_y²) over
    /// every substep, k = f^h, mass·px²/step². Exact: the damping is the only thing the
    /// predict step does to the velocities before gravity is added.
    double dampingLoss() const { return m_dampingLoss; }
    /// Contacts of the last step, the most of any of its substeps: particles a wall or an
    /// obstacle pushed back, and points pushed out of a body (another body's vertices, an
    /// obstacle's corners).
    int contactCount() const { return m_contactCount; }
    /// One body's share of the readouts above (the plots per body, docs/plots-over-time.md):
    /// over its vertices and the joints of the chains anchored to it (the frog's legs), the
    /// energy of its edges, area and bending and of those chains' links, what damping took
    /// from those particles, and its contacts in the substep the step's contactCount() is
    /// from. Summed over the bodies they give the world's own, less any free chain's part.
    /// motionEnergies and elasticEnergy fill in the energies (and what f took) in their own
    /// passes, with the world's; bodyLosses adds what the dashpots took and the contacts.
    struct BodyEnergies {
        double kinetic = 0, gravity = 0, movingMass = 0, elastic = 0, dampingLoss = 0;
        int contacts = 0;
    };
    void bodyLosses(std::vector<BodyEnergies>& bodies) const;

private:
    XpbdWorld() = default;

    struct Body {
        int first = 0;
        int count = 0;
        int firstEdge = 0;
        int firstAngle = 0;
        int angleCount = 0;
        double target = 0;
        double restArea = 0; // of the shape as given, px²
        double mass = 10;
        bool collides = true;
        bool recovering = false;
        double areaLambda = 0;
        double orientationSign = 1;
    };
    struct Chain {
        int first = 0;
        int count = 0;
        int firstLink = 0;
        int firstAngle = 0;
        int angleCount = 0;
        int anchorLink = -1; // index into m_anchorLinks (first link hanging from a body), or −1
        ChainAnchor anchor;
        Point fixedFrom; // fixed anchor at the step's start
        Point fixedTo;   // and at its end
    };

    int addParticle(Point x, Point v, double invMass);
    void rescaleRest(Body& b);
    void findContactPairs();
    /// One substep's constants: its length h, 1/h², the step's fraction done at its end
    /// (for what moves over the step: the mouse, fixed anchors), the speed cap and the
    /// velocity the damping keeps, f^h.
    struct Substep {
        double h = 0, invH2 = 0, fraction = 0, vCap = 0;
        Point keep;
    };
    /// The stages of a substep, in order (xpbd_step.cpp).
    void solveSubstep(double h, double fraction);
    void integrate(const Substep& s);
    void solveBodies(const Substep& s);
    void solveGrab(const Substep& s);
    void solveObstacleContacts();
    void solveBodyContacts();
    void solveChains(const Substep& s);
    void solveFrame(const Substep& s);
    void updateVelocities(const Substep& s);
    void dampEdges(const Substep& s);
    void applyFriction(const Substep& s);
    void updateValidity();
    void placeChainRoots(double fraction);
    bool checkValid(const Body& b) const;
    Point clampToFrame(Point p) const;

    XpbdParams m_params;
    long m_steps = 0;
    double m_dampingLoss = 0;
    int m_contactCount = 0;
    std::vector<double> m_bodyDampingLoss;     // per body: what its edges' dashpots took
    std::vector<double> m_particleDampingLoss; // per particle: what the damping f took from it
    std::vector<int> m_bodyContactCount;       // per body, in the substep m_contactCount is from
    std::vector<int> m_bodyContactsNow;        // scratch: per body, in the present substep

    // Particles (structure of arrays).
    std::vector<Point> m_x;
    std::vector<Point> m_xPrev;
    std::vector<Point> m_v;
    std::vector<double> m_w;        // inverse masses; 0 = moved by the program only
    std::vector<double> m_mass;     // the masses, 1/w (0 where w = 0), for the readouts
    std::vector<Point> m_contact;   // wall/obstacle normal of the substep, or (0, 0)
    std::vector<Point> m_restShape; // body vertices: the given shape about its centroid
    std::vector<Point> m_rest;      // the same scaled to the target area (shape-matching goal)
    std::vector<Point> m_delta;     // scratch: summed corrections of the Jacobi passes
    std::vector<int> m_owner;       // the body a particle is of (a leg's: its body's), or −1

    std::vector<Body> m_bodies;
    std::vector<Chain> m_chains;
    std::vector<DistanceConstraint> m_edges; // bodies' edges, body by body
    std::vector<double> m_edgeDampingLambda; // per edge: its dashpot's part of λ (ζ > 0)
    std::vector<DistanceConstraint> m_links; // chains' links
    std::vector<AngleConstraint> m_angles;   // bending of bodies and limits of chains
    std::vector<AnchoredDistanceConstraint> m_anchorLinks;

    std::vector<XpbdObstacle> m_obstacles;
    std::vector<Point> m_obstaclePoints;

    // Contacts.
    UniformGridBroadPhase m_grid;
    std::vector<Aabb> m_boxes;      // per body, grown by the step's motion
    std::vector<Aabb> m_gridBoxes;  // the same, empty for bodies that do not collide (broad phase)
    std::vector<Aabb> m_tightBoxes; // per body, at the start of the contact pass of a substep
    std::vector<BodyPair> m_pairs;
    std::vector<BodyPair> m_obstaclePairs;   // (obstacle, body)
    std::vector<BodyContact> m_bodyContacts; // contacts with bodies in the current substep (for friction)
    /// A vertex that may touch another body during this step, found once per step from the
    /// broad phase's pairs (collision detection per step, resolution per substep: Macklin
    /// et al. 2019, §4), with the edge of that body found nearest in the last substep.
    struct ContactCandidate {
        int particle = 0;
        int body = 0;
        int edge = -1;
        bool touching = false; // pushed out against `edge` in the last substep
    };
    std::vector<ContactCandidate> m_candidates;
    std::vector<double> m_reach; // per body: how far its vertices may travel this step, px

    // Mouse.
    int m_grabBody = -1;
    std::vector<int> m_grabIdx;
    std::vector<double> m_grabRest;
    Point m_mouse;
    Point m_mouseFrom;     // mouse at the start of the step
    Point m_mouseVelocity; // px/step over the last step
};

} // namespace granota
