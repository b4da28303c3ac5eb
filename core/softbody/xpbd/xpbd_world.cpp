#include "core/softbody/xpbd/xpbd_world.h"
#include "core/base/math_constants.h"

#include "core/softbody/regular_polygon.h"
#include "core/softbody/xpbd/xpbd_recovery.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

namespace granota {

namespace {

/// A body below this share of its target area is taken as squashed flat and recovered by
/// shape matching (xpbd_recovery.h)…
constexpr double kCollapsedShare = 0.2;
/// …and is valid again from this share on (hysteresis: no flicker at the threshold).
constexpr double kRecoveredShare = 0.5;
/// Passes over each chain per substep (alternately root to tip and back).
constexpr int kChainPasses = 4;

std::size_t at(int i) { return static_cast<std::size_t>(i); }

Error outOfRange(const std::string& message) { return makeError(ErrorCode::OutOfRange, message); }
/// The smallest power of two ≥ n: what a list that grows to n one by one reserves.
std::size_t roomFor(std::size_t n)
{
    std::size_t room = 1;
    while (room < n)
        room *= 2;
    return room;
}
Error invalid(const std::string& message) { return makeError(ErrorCode::InvalidInput, message); }

bool allFinite(const std::vector<Point>& pts)
{
    return std::all_of(pts.begin(), pts.end(), [](const Point& p) { return isFinite(p); });
}

} // namespace

// ---------------------------------------------------------------------------------------
// Building
// ---------------------------------------------------------------------------------------

Expected<XpbdWorld> XpbdWorld::create(const XpbdParams& params)
{
    const Expected<XpbdParams> checked = validateXpbdParams(params);
    if (!checked)
        return checked.error();
    XpbdWorld world;
    world.m_params = params;
    world.m_mouse = world.m_mouseFrom = world.clampToFrame({0, 0});
    return world;
}

Expected<void> XpbdWorld::setParams(const XpbdParams& params)
{
    const Expected<XpbdParams> checked = validateXpbdParams(params);
    if (!checked)
        return checked.error();
    m_params = params;
    return {};
}

Point XpbdWorld::clampToFrame(Point p) const
{
    if (!isFinite(p)) // NaN has no side: the middle of the frame
        return {0.5 * (m_params.width - 1), 0.5 * (m_params.height - 1)};
    return {std::clamp(p.x, 0.0, m_params.width - 1), std::clamp(p.y, 0.0, m_params.height - 1)};
}

int XpbdWorld::addParticle(Point x, Point v, double invMass)
{
    m_x.push_back(x);
    m_xPrev.push_back(x);
    m_v.push_back(v);
    m_w.push_back(invMass);
    m_mass.push_back(invMass > 0 ? 1 / invMass : 0.0);
    m_particleDampingLoss.push_back(0);
    m_contact.push_back(Point());
    m_restShape.push_back(Point());
    m_rest.push_back(Point());
    m_delta.push_back(Point());
    m_owner.push_back(-1);
    return static_cast<int>(m_x.size()) - 1;
}

void XpbdWorld::rescaleRest(Body& b)
{
    // The rest shape, scaled about its centroid to the target area: edges, bending angles
    // and the shape-matching goal all agree with A₀, so the body has one rest state.
    const double s = std::sqrt(b.target / b.restArea);
    for (int i = 0; i < b.count; ++i) {
        const Point& r = m_restShape[at(b.first + i)];
        m_rest[at(b.first + i)] = Point(s * r.x, s * r.y);
    }
    for (int i = 0; i < b.count; ++i) {
        DistanceConstraint& e = m_edges[at(b.firstEdge + i)];
        e.rest = distance(m_rest[at(e.a)], m_rest[at(e.b)]);
        e.complianceScale = e.rest; // α per unit length: a longer edge is a softer spring (k = EA/L)
    }
}

Expected<int> XpbdWorld::addBody(const std::vector<Point>& restShape, double targetArea, Point velocity,
                                 const BodyOptions& options)
{
    if (restShape.size() < 3)
        return makeError(ErrorCode::TooFewPoints, "a body needs at least 3 vertices");
    if (restShape.size() > 100000)
        return outOfRange("a body may have at most 100000 vertices");
    if (!allFinite(restShape))
        return invalid("the body's vertices must be finite numbers");
    if (!(std::isfinite(targetArea) && targetArea >= 0))
        return outOfRange("the target area must be a finite number ≥ 0");
    if (!isFinite(velocity))
        return invalid("the initial velocity must be finite");
    if (!(std::isfinite(options.mass) && options.mass > 0))
        return outOfRange("the body's mass must be positive and finite");

    std::vector<Point> shape = restShape;
    const int n = static_cast<int>(shape.size());
    double area = signedArea(shape.data(), n);
    const Aabb box = boundingBox(shape.data(), n);
    const double span = std::max(box.maxX - box.minX, box.maxY - box.minY);
    if (!(std::abs(area) > 1e-9 * span * span) || !(span > 0))
        return invalid("the body's rest shape has no area (its vertices are on one line)");
    if (polygonSelfIntersects(shape.data(), n))
        return invalid("the body's rest shape crosses itself");
    if (area < 0) { // the other orientation: reverse it, vertex 0 staying first
        std::reverse(shape.begin() + 1, shape.end());
        area = -area;
    }

    Body b;
    b.first = static_cast<int>(m_x.size());
    b.count = n;
    b.firstEdge = static_cast<int>(m_edges.size());
    b.target = targetArea;
    b.restArea = area;
    b.mass = options.mass;
    b.collides = options.collides;
    const Point c = vertexCentroid(shape.data(), n);
    const double invMass = n / options.mass;
    for (const Point& p : shape) {
        const int i = addParticle(clampToFrame(p), velocity, invMass);
        m_restShape[at(i)] = p - c;
        m_owner[at(i)] = bodyCount();
    }
    for (int i = 0; i < n; ++i) {
        DistanceConstraint e;
        e.a = b.first + i;
        e.b = b.first + (i + 1) % n;
        e.kind = ConstraintKind::Edge;
        m_edges.push_back(e);
        m_edgeDampingLambda.push_back(0);
    }
    rescaleRest(b);
    b.firstAngle = static_cast<int>(m_angles.size());
    if (options.bending) {
        // §5.2.3: "una restricció angular que faci referència als angles que poden arribar a
        // formar dos vèrtexs consecutius": the turn between edge i−1→i and edge i→i+1 keeps
        // its rest value (θ − offset = 0).
        for (int i = 0; i < n; ++i) {
            AngleConstraint a;
            a.a0 = b.first + (i + n - 1) % n;
            a.a1 = b.first + i;
            a.b0 = b.first + i;
            a.b1 = b.first + (i + 1) % n;
            a.offset = constraintAngle(a, m_rest.data()); // the turn at rest (offset still 0 here)
            a.lo = a.hi = 0;
            a.kind = ConstraintKind::Bending;
            m_angles.push_back(a);
        }
        b.angleCount = n;
    }
    m_bodies.push_back(b);
    m_bodyDampingLoss.push_back(0);
    m_bodyContactCount.push_back(0);
    m_bodyContactsNow.push_back(0);
    // Room for the contact lists now, so that step() does not allocate: a body touches a
    // handful of others, and every obstacle at most. In powers of two, so that adding N
    // bodies one by one reallocates log N times, not N times (N² copying: 5000 bodies took
    // seconds).
    const std::size_t bodies = roomFor(m_bodies.size());
    m_boxes.reserve(bodies);
    m_gridBoxes.reserve(bodies);
    m_tightBoxes.reserve(bodies);
    m_pairs.reserve(8 * bodies);
    m_obstaclePairs.reserve(bodies * std::max<std::size_t>(m_obstacles.size(), 4));
    m_grid.reserve(static_cast<int>(bodies));
    const std::size_t vertices = roomFor(m_x.size());
    m_bodyContacts.reserve(vertices);   // about one contact per vertex at most, in a pile
    m_candidates.reserve(2 * vertices); // a vertex near two or three bodies, in a pile
    m_reach.reserve(bodies);
    m_grabIdx.reserve(std::max(m_grabIdx.capacity(), at(n)));
    m_grabRest.reserve(std::max(m_grabRest.capacity(), at(n)));
    return static_cast<int>(m_bodies.size()) - 1;
}

Expected<int> XpbdWorld::addRegularBody(Point centre, double radius, int sides, double targetArea, Point velocity,
                                        const BodyOptions& options)
{
    if (sides < 3)
        return makeError(ErrorCode::TooFewPoints, "a body needs at least 3 sides");
    if (sides > 100000)
        return outOfRange("a body may have at most 100000 sides");
    if (!isFinite(centre))
        return invalid("the body's centre must be finite");
    if (!(std::isfinite(radius) && radius > 0))
        return outOfRange("the body's radius must be positive and finite");
    return addBody(regularPolygon(centre, radius, sides), targetArea, velocity, options);
}

Expected<void> XpbdWorld::setTargetArea(int body, double targetArea)
{
    if (body < 0 || body >= bodyCount())
        return outOfRange("no such body");
    if (!(std::isfinite(targetArea) && targetArea >= 0))
        return outOfRange("the target area must be a finite number ≥ 0");
    Body& b = m_bodies[at(body)];
    b.target = targetArea;
    rescaleRest(b); // bending offsets are angles: a change of scale leaves them as they are
    return {};
}

Expected<void> XpbdWorld::setBodyVertices(int body, const std::vector<Point>& vertices)
{
    if (body < 0 || body >= bodyCount())
        return outOfRange("no such body");
    const Body& b = m_bodies[at(body)];
    if (static_cast<int>(vertices.size()) != b.count)
        return invalid("the number of vertices must stay " + std::to_string(b.count));
    if (!allFinite(vertices))
        return invalid("vertices must be finite numbers");
    for (int i = 0; i < b.count; ++i) {
        m_x[at(b.first + i)] = m_xPrev[at(b.first + i)] = clampToFrame(vertices[at(i)]);
        m_v[at(b.first + i)] = Point();
    }
    return {};
}

Expected<void> XpbdWorld::setBodyVelocity(int body, Point velocity)
{
    if (body < 0 || body >= bodyCount())
        return outOfRange("no such body");
    if (!isFinite(velocity))
        return invalid("the velocity must be finite");
    const Body& b = m_bodies[at(body)];
    for (int i = 0; i < b.count; ++i)
        m_v[at(b.first + i)] = velocity;
    return {};
}

Expected<void> XpbdWorld::setBodyVelocities(int body, const std::vector<Point>& velocities)
{
    if (body < 0 || body >= bodyCount())
        return outOfRange("no such body");
    const Body& b = m_bodies[at(body)];
    if (static_cast<int>(velocities.size()) != b.count)
        return invalid("give one velocity per vertex (" + std::to_string(b.count) + ")");
    if (!allFinite(velocities))
        return invalid("velocities must be finite");
    for (int i = 0; i < b.count; ++i)
        m_v[at(b.first + i)] = velocities[at(i)];
    return {};
}

Point XpbdWorld::anchorPoint(const ChainAnchor& a) const
{
    if (a.body < 0)
        return a.point;
    const Body& b = m_bodies[at(a.body)];
    const Point& pa = m_x[at(b.first + a.vertexA)];
    const Point& pb = m_x[at(b.first + a.vertexB)];
    return pa + Point(a.t * (pb.x - pa.x), a.t * (pb.y - pa.y));
}

Expected<int> XpbdWorld::addChain(const ChainDef& def)
{
    const int joints = static_cast<int>(def.joints.size());
    if (joints < 2)
        return makeError(ErrorCode::TooFewPoints, "a chain needs at least 2 joints");
    if (!allFinite(def.joints))
        return invalid("the chain's joints must be finite numbers");
    for (int k = 0; k + 1 < joints; ++k)
        if (!(distance(def.joints[at(k)], def.joints[at(k + 1)]) > 1e-9))
            return invalid("every link of a chain must have a positive length");
    if (!def.limits.empty() && static_cast<int>(def.limits.size()) != joints - 1)
        return invalid("give one angle limit per link, or none");
    for (const AngleLimit& l : def.limits)
        if (!(l.min >= -kPi - 1e-9 && l.max <= kPi + 1e-9 && l.min <= l.max))
            return outOfRange("angle limits must satisfy −π ≤ min ≤ max ≤ π");
    if (!(std::isfinite(def.jointMass) && def.jointMass > 0))
        return outOfRange("the joints' mass must be positive and finite");
    const ChainAnchor& a = def.anchor;
    if (a.body >= bodyCount() || a.body < -1)
        return outOfRange("the chain's anchor body does not exist");
    if (a.body >= 0) {
        const int n = m_bodies[at(a.body)].count;
        if (a.vertexA < 0 || a.vertexA >= n || a.vertexB < 0 || a.vertexB >= n)
            return outOfRange("the chain's anchor vertices are not vertices of the body");
        if (!(a.t >= 0 && a.t <= 1))
            return outOfRange("the chain's anchor parameter t must lie in [0, 1]");
        if (!def.pullsBody && !def.limits.empty() && def.limits[0].reference == AngleReference::Parent)
            return invalid("a chain that does not pull its body cannot measure its first angle from the body");
    } else if (!isFinite(a.point)) {
        return invalid("the chain's fixed anchor must be finite");
    }

    Chain c;
    c.anchor = a;
    c.first = static_cast<int>(m_x.size());
    c.count = joints;
    const Point root = a.body >= 0 ? anchorPoint(a) : clampToFrame(a.point);
    const Point shift = root - def.joints[0];
    const double invMass = 1 / def.jointMass;
    // The first joint (the seed's nail) is moved by the program only (w = 0): onto the
    // fixed point, or onto the body's point, through which the first link pulls the body
    // (pullsBody; otherwise the first link is an ordinary one from that joint).
    addParticle(root, Point(), 0.0);
    for (int k = 1; k < joints; ++k)
        addParticle(clampToFrame(def.joints[at(k)] + shift), Point(), invMass);
    for (int k = 0; k < joints; ++k) // a leg is its body's: its energy and contacts too
        m_owner[at(c.first + k)] = a.body;
    if (a.body >= 0 && def.pullsBody) {
        const Body& b = m_bodies[at(a.body)];
        AnchoredDistanceConstraint link;
        link.joint = c.first + 1;
        link.a = b.first + a.vertexA;
        link.b = b.first + a.vertexB;
        link.t = a.t;
        link.rest = distance(def.joints[0], def.joints[1]);
        c.anchorLink = static_cast<int>(m_anchorLinks.size());
        m_anchorLinks.push_back(link);
    }
    c.fixedFrom = c.fixedTo = root;
    c.firstLink = static_cast<int>(m_links.size());
    for (int k = 0; k + 1 < joints; ++k) {
        DistanceConstraint l;
        l.a = c.first + k;
        l.b = c.first + k + 1;
        l.rest = distance(def.joints[at(k)], def.joints[at(k + 1)]);
        l.kind = ConstraintKind::Link;
        m_links.push_back(l);
    }
    c.firstAngle = static_cast<int>(m_angles.size());
    for (int k = 0; k < static_cast<int>(def.limits.size()); ++k) {
        const AngleLimit& lim = def.limits[at(k)];
        AngleConstraint ac;
        ac.b0 = c.first + k;
        ac.b1 = c.first + k + 1;
        ac.lo = std::max(lim.min, -kPi);
        ac.hi = std::min(lim.max, kPi);
        ac.kind = ConstraintKind::Rigid;
        if (lim.reference == AngleReference::Parent && k > 0) {
            ac.a0 = c.first + k - 1;
            ac.a1 = c.first + k;
        } else if (lim.reference == AngleReference::Parent && a.body >= 0) {
            // The first link of a leg, measured from the body: from the segment v_A → v_B
            // as it has turned since now (offset = its present angle).
            const Body& b = m_bodies[at(a.body)];
            ac.a0 = b.first + a.vertexA;
            ac.a1 = b.first + (a.vertexB != a.vertexA ? a.vertexB : (a.vertexA + 1) % b.count);
            ac.offset = -seedAngle(m_x[at(ac.a1)] - m_x[at(ac.a0)]);
        }
        m_angles.push_back(ac);
    }
    c.angleCount = static_cast<int>(def.limits.size());
    m_chains.push_back(c);
    return static_cast<int>(m_chains.size()) - 1;
}

Expected<int> XpbdWorld::addSegmentObstacle(Point a, Point b, double radius)
{
    if (!isFinite(a) || !isFinite(b))
        return invalid("the obstacle's end points must be finite");
    if (!(std::isfinite(radius) && radius >= 0))
        return outOfRange("the obstacle's thickness must be finite and not negative");
    XpbdObstacle o;
    o.shape = XpbdObstacle::Shape::Segment;
    o.first = static_cast<int>(m_obstaclePoints.size());
    o.count = 2;
    o.radius = radius;
    m_obstaclePoints.push_back(a);
    m_obstaclePoints.push_back(b);
    o.box = boundingBox(&m_obstaclePoints[at(o.first)], 2);
    o.box.minX -= radius, o.box.minY -= radius, o.box.maxX += radius, o.box.maxY += radius;
    m_obstacles.push_back(o);
    m_obstaclePairs.reserve(roomFor(m_bodies.size() * m_obstacles.size()));
    return static_cast<int>(m_obstacles.size()) - 1;
}

Expected<int> XpbdWorld::addPolygonObstacle(const std::vector<Point>& polygon)
{
    if (polygon.size() < 3)
        return makeError(ErrorCode::TooFewPoints, "a polygon obstacle needs at least 3 vertices");
    if (!allFinite(polygon))
        return invalid("the obstacle's vertices must be finite numbers");
    const int n = static_cast<int>(polygon.size());
    if (!(std::abs(signedArea(polygon.data(), n)) > 0))
        return invalid("the polygon obstacle has no area");
    if (polygonSelfIntersects(polygon.data(), n))
        return invalid("the polygon obstacle crosses itself");
    XpbdObstacle o;
    o.shape = XpbdObstacle::Shape::Polygon;
    o.first = static_cast<int>(m_obstaclePoints.size());
    o.count = n;
    m_obstaclePoints.insert(m_obstaclePoints.end(), polygon.begin(), polygon.end());
    o.box = boundingBox(polygon.data(), n);
    m_obstacles.push_back(o);
    m_obstaclePairs.reserve(roomFor(m_bodies.size() * m_obstacles.size()));
    return static_cast<int>(m_obstacles.size()) - 1;
}

void XpbdWorld::moveChainAnchor(int chain, Point p)
{
    if (chain < 0 || chain >= chainCount() || !isFinite(p))
        return;
    Chain& c = m_chains[at(chain)];
    if (c.anchor.body < 0)
        c.fixedTo = clampToFrame(p);
}

// ---------------------------------------------------------------------------------------
// Stepping
// ---------------------------------------------------------------------------------------

void XpbdWorld::findContactPairs()
{
    // Boxes grown by how far a body can travel this step (|v| dt + |g| dt²) and the skin,
    // so that pairs found now stay valid for all substeps (Macklin et al. 2019, §4).
    const double dt = m_params.dt;
    const double g = norm(m_params.gravity) * dt * dt;
    const int nb = bodyCount();
    m_boxes.resize(at(nb));
    m_gridBoxes.resize(at(nb));
    m_reach.resize(at(nb));
    for (int k = 0; k < nb; ++k) {
        const Body& b = m_bodies[at(k)];
        Aabb box = boundingBox(&m_x[at(b.first)], b.count);
        double speed = 0;
        for (int i = 0; i < b.count; ++i)
            speed = std::max(speed, std::abs(m_v[at(b.first + i)].x) + std::abs(m_v[at(b.first + i)].y));
        const double grow = speed * dt + g + m_params.contactMargin;
        m_reach[at(k)] = grow;
        box.minX -= grow, box.minY -= grow, box.maxX += grow, box.maxY += grow;
        m_boxes[at(k)] = box;
        m_gridBoxes[at(k)] = b.collides ? box : Aabb(); // an empty box meets nothing
    }
    m_grid.findPairs(m_gridBoxes, m_pairs);

    // The narrow phase's candidates, once per step instead of once per substep: a vertex
    // of body a can reach body b only if it starts within b's grown box grown again by its
    // own reach (the pair test, point by point). In a pile this keeps about a fifth of the
    // vertices of each pair; the substeps test only those. Order: pairs, then side, then
    // vertex, as the substeps solved them before, so results do not depend on this list.
    m_candidates.clear();
    for (const BodyPair& pair : m_pairs)
        for (int side = 0; side < 2; ++side) {
            const int a = side == 0 ? pair.first : pair.second;
            const int other = side == 0 ? pair.second : pair.first;
            const Body& body = m_bodies[at(a)];
            const Aabb& box = m_boxes[at(other)];
            const double reach = m_reach[at(a)];
            for (int i = body.first; i < body.first + body.count; ++i)
                if (box.contains(m_x[at(i)], reach))
                    m_candidates.push_back({i, other, -1});
        }

    // Obstacles are few: every (obstacle, body) pair whose boxes meet (§5.2.1's box test).
    m_obstaclePairs.clear();
    for (int o = 0; o < obstacleCount(); ++o)
        for (int k = 0; k < nb; ++k)
            if (m_boxes[at(k)].overlaps(m_obstacles[at(o)].box))
                m_obstaclePairs.push_back({o, k});
}

void XpbdWorld::step()
{
    const int n = m_params.substeps;
    const double h = m_params.dt / n;
    findContactPairs();
    m_contactCount = 0;
    std::fill(m_bodyContactCount.begin(), m_bodyContactCount.end(), 0);
    for (int s = 0; s < n; ++s)
        solveSubstep(h, double(s + 1) / n);
    updateValidity();

    // Mouse velocity over the step, for release(); the fixed anchors have arrived.
    m_mouseVelocity = Point((m_mouse.x - m_mouseFrom.x) / m_params.dt, (m_mouse.y - m_mouseFrom.y) / m_params.dt);
    m_mouseFrom = m_mouse;
    for (Chain& c : m_chains)
        c.fixedFrom = c.fixedTo;
    ++m_steps;
}

void XpbdWorld::solveSubstep(double h, double fraction)
{
    const XpbdParams& p = m_params;
    const double invH2 = 1 / (h * h);
    const int np = particleCount();
    // A particle cannot usefully cross more than the frame in one substep: this cap keeps
    // every number finite for any gravity, step or initial velocity; velmax is the seed's.
    const double vCap = std::min(p.velmax, (p.width + p.height) / h);
    // Velocity kept per substep: f per step (dt = 1) becomes f^h, so n substeps keep f.
    const Point keep(std::pow(p.damping.x, h), std::pow(p.damping.y, h));

    // 1. Predict.
    Point* x = m_x.data();
    Point* xPrev = m_xPrev.data();
    Point* v = m_v.data();
    const double* w = m_w.data();
    const Point lost(1 - keep.x * keep.x, 1 - keep.y * keep.y);
    double dampingLoss = 0; // ×2m
    for (int i = 0; i < np; ++i) {
        xPrev[i] = x[i];
        m_contact[at(i)] = Point();
        if (!(w[i] > 0))
            continue;
        const double loss = (lost.x * v[i].x * v[i].x + lost.y * v[i].y * v[i].y) / w[i];
        dampingLoss += loss;
        m_particleDampingLoss[at(i)] += 0.5 * loss; // summed per body when asked (motionEnergies)
        Point vi(keep.x * v[i].x + p.gravity.x * h, keep.y * v[i].y + p.gravity.y * h);
        vi.x = std::clamp(vi.x, -vCap, vCap);
        vi.y = std::clamp(vi.y, -vCap, vCap);
        v[i] = vi;
        x[i] += Point(vi.x * h, vi.y * h);
    }
    m_dampingLoss += 0.5 * dampingLoss;
    placeChainRoots(fraction);

    // 2. Constraints, one pass, λ = 0 at the start (Macklin et al. 2019, alg. 1).
    const double edgeAlpha = p.edgeCompliance * invH2;
    const double areaAlpha = p.areaCompliance * invH2;
    const double bendAlpha = p.bendCompliance * invH2;
    for (Body& b : m_bodies) {
        if (b.recovering) {
            // Invalid body: elastic constraints off (they would only tangle it further),
            // shape matching pulls it towards its rest shape, which cannot be inside out.
            shapeMatchingPull(x + b.first, m_rest.data() + b.first, b.count, p.recoveryRate);
            b.areaLambda = 0;
            continue;
        }
        // The ring of edges is solved Jacobi-style with averaging (Macklin et al. 2014, §4.2):
        // every edge from the same positions, each vertex moved by the mean of its two
        // corrections. Gauss–Seidel in ring order would drag the outline along the sweep, and
        // a body at rest would slowly roll like a caterpillar track; any fixed reordering
        // (red–black) still leaves a slow creep for odd n, and alternating orders between
        // substeps pumps energy into a zigzag. The average is symmetric and cannot overshoot.
        solveEdgeRing(m_edges.data() + b.firstEdge, b.count, x, xPrev, w, edgeAlpha, p.edgeDampingRatio,
                      p.edgeDampingRatio > 0 ? m_edgeDampingLambda.data() + b.firstEdge : nullptr, m_delta.data());
        b.areaLambda = solveArea(x + b.first, w + b.first, b.count, b.target, areaAlpha);
        if (b.angleCount > 0)
            solveBendingRing(m_angles.data() + b.firstAngle, b.angleCount, x, w, bendAlpha, m_delta.data());
    }
    // The mouse ties: ropes of fixed length to the mouse (Annex II l. 266–283), compliant,
    // each force capped: |λ|/h² ≤ grabMaxForce.
    if (m_grabBody >= 0) {
        const Point m = m_mouseFrom + Point(fraction * (m_mouse.x - m_mouseFrom.x), fraction * (m_mouse.y - m_mouseFrom.y));
        const double alpha = p.grabCompliance * invH2;
        const double cap = p.grabMaxForce * h * h;
        for (std::size_t k = 0; k < m_grabIdx.size(); ++k) {
            const int i = m_grabIdx[k];
            const Point d = x[i] - m;
            const double len = std::sqrt(dot(d, d));
            if (len < 1e-12)
                continue;
            double dl = -(len - m_grabRest[k]) / (w[i] + alpha);
            dl = std::clamp(dl, -cap, cap);
            x[i] += Point(w[i] * dl * d.x / len, w[i] * dl * d.y / len);
        }
    }

    m_bodyContacts.clear();

    // 3. Contacts. Obstacles (§5.2.1): bodies' vertices against the obstacle, and the
    // obstacle's corners against the bodies (a sharp corner between two vertices).
    const double margin = p.contactMargin;
    for (const BodyPair& op : m_obstaclePairs) {
        const XpbdObstacle& o = m_obstacles[at(op.first)];
        const Body& b = m_bodies[at(op.second)];
        for (int i = b.first; i < b.first + b.count; ++i) {
            Point nrm;
            if (solveObstacle(o, m_obstaclePoints.data(), x[i], xPrev[i], margin, p.wallFriction, &nrm))
                m_contact[at(i)] = nrm;
        }
        const Aabb box = boundingBox(x + b.first, b.count);
        const double orient = signedArea(x + b.first, b.count) < 0 ? -1.0 : 1.0;
        for (int k = 0; k < o.count; ++k) {
            const Point& c = m_obstaclePoints[at(o.first + k)];
            BodyContact contact;
            if (box.contains(c, margin) && solvePointInBody(x, w, -1, c, b.first, b.count, orient, margin, &contact)) {
                contact.friction = p.wallFriction;
                m_bodyContacts.push_back(contact);
            }
        }
    }
    for (const Chain& c : m_chains)
        for (int i = c.first; i < c.first + c.count; ++i) {
            if (!(w[i] > 0))
                continue;
            for (const XpbdObstacle& o : m_obstacles) {
                Point nrm;
                if (solveObstacle(o, m_obstaclePoints.data(), x[i], xPrev[i], margin, p.wallFriction, &nrm))
                    m_contact[at(i)] = nrm;
            }
        }

    // Bodies against bodies (§5.2.2): the pairs of the broad phase; the vertices of each
    // inside (or within the skin of) the other are pushed out against its nearest edge.
    if (!m_candidates.empty()) {
        m_tightBoxes.resize(m_bodies.size());
        for (std::size_t k = 0; k < m_bodies.size(); ++k) {
            const Body& b = m_bodies[k];
            Aabb box = boundingBox(x + b.first, b.count);
            box.minX -= margin, box.minY -= margin, box.maxX += margin, box.maxY += margin;
            m_tightBoxes[k] = box;
            m_bodies[k].orientationSign = signedArea(x + b.first, b.count) < 0 ? -1.0 : 1.0;
        }
        // A vertex pushed out against an edge last substep is, in a pile, nearly always
        // still behind that edge: it is solved against that edge alone, at the cost of one
        // edge; the exact test (every edge, twice) runs only when it has left the edge's span
        // or front, and for every other candidate — so new contacts are met at once.
        for (ContactCandidate& cand : m_candidates) {
            const int i = cand.particle;
            const Body& b = m_bodies[at(cand.body)];
            BodyContact contact;
            const bool kept = cand.touching &&
                              solvePointAgainstEdge(x, w, i, b.first + cand.edge, b.first + (cand.edge + 1) % b.count,
                                                    b.orientationSign, margin, &contact);
            cand.touching = kept || (m_tightBoxes[at(cand.body)].contains(x[i]) &&
                                     solvePointInBody(x, w, i, Point(), b.first, b.count, b.orientationSign, margin, &contact,
                                                      &cand.edge));
            if (cand.touching) {
                contact.friction = p.contactFriction;
                m_bodyContacts.push_back(contact);
            }
        }
    }

    // Chains, after everything that moves the bodies they hang from (mouse, contacts), so
    // that the shoulders do not move under them: Gauss–Seidel from the root outwards, as
    // §4.14 corrects joint after joint, then back. Legs are rigid (α = 0) and light, hung
    // from a heavy body: one pass leaves the root link stretched by whatever the next link
    // pulled, so a few passes are made; chains are tiny, so this costs next to nothing.
    // λ accumulates over the passes.
    const double linkAlpha = p.linkCompliance * invH2;
    placeChainRoots(fraction);
    for (const Chain& c : m_chains) {
        for (int k = 0; k < c.angleCount; ++k)
            m_angles[at(c.firstAngle + k)].lambda = 0;
        for (int k = 0; k + 1 < c.count; ++k)
            m_links[at(c.firstLink + k)].lambda = 0;
        if (c.anchorLink >= 0)
            m_anchorLinks[at(c.anchorLink)].lambda = 0;
        for (int pass = 0; pass < kChainPasses; ++pass) {
            // Angle limits first: their linearised correction moves a joint along a tangent,
            // which lengthens the link a little (L·δθ²/2); the links put the lengths back.
            for (int k = 0; k < c.angleCount; ++k)
                solveAngle(m_angles[at(c.firstAngle + k)], x, w, 0.0);
            const int links = c.count - 1;
            for (int step = 0; step < links; ++step) {
                const int k = pass % 2 == 0 ? step : links - 1 - step;
                if (k == 0 && c.anchorLink >= 0) {
                    solveAnchoredDistance(m_anchorLinks[at(c.anchorLink)], x, w, linkAlpha);
                    x[c.first] = anchorPoint(c.anchor);
                } else {
                    solveDistance(m_links[at(c.firstLink + k)], x, w, linkAlpha);
                }
            }
            // The frame inside the passes, so that links and floor agree (§4.15: "s'han de
            // revisar les col·lisions amb els extrems del marc"). Without friction, as the
            // seed's joints (a wrist below the floor is lifted, the elbow slides, §4.16):
            // a joint held by friction, rammed into the floor by its link, would pin the
            // leg folded past its limits.
            solveWalls(x + c.first, xPrev + c.first, w + c.first, m_contact.data() + c.first, c.count, p.width, p.height, 0.0);
        }
    }

    // The frame, last: whatever happened above, every particle ends the substep inside.
    solveWalls(x, xPrev, w, m_contact.data(), np, p.width, p.height, p.wallFriction);
    placeChainRoots(fraction); // shoulders follow the body wherever the contacts put it

    // 4. Velocities, with restitution at walls and obstacles (Müller et al. 2020, eq. 34):
    // the normal speed becomes −e times the one before the solve; slow hits (below 2|g|h)
    // do not bounce, so that resting contact stays at rest.
    const double slow = 2 * norm(p.gravity) * h;
    int contacts = static_cast<int>(m_bodyContacts.size());
    std::fill(m_bodyContactsNow.begin(), m_bodyContactsNow.end(), 0);
    for (const BodyContact& c : m_bodyContacts) // an obstacle's corner in a body: that body's
        if (const int b = m_owner[at(c.p >= 0 ? c.p : c.e0)]; b >= 0)
            ++m_bodyContactsNow[at(b)];
    for (int i = 0; i < np; ++i) {
        Point vi((x[i].x - xPrev[i].x) / h, (x[i].y - xPrev[i].y) / h);
        const Point n = m_contact[at(i)];
        if (n.x != 0 || n.y != 0) {
            ++contacts;
            if (const int b = m_owner[at(i)]; b >= 0)
                ++m_bodyContactsNow[at(b)];
            const double before = dot(v[i], n);
            if (before < 0) {
                const double e = -before > slow ? p.restitution : 0.0;
                const double now = dot(vi, n);
                const double wanted = -e * before;
                vi += Point((wanted - now) * n.x, (wanted - now) * n.y);
            }
        }
        v[i] = vi;
    }
    if (contacts > m_contactCount) // each body's count from the substep the step's count is from
        m_bodyContactCount = m_bodyContactsNow;
    m_contactCount = std::max(m_contactCount, contacts);
    // What the edges' dashpots took (ζ > 0), with the damping f: the damping loss.
    if (p.edgeDampingRatio > 0)
        for (std::size_t k = 0; k < m_bodies.size(); ++k) {
            const Body& b = m_bodies[k];
            if (b.recovering)
                continue;
            const double loss = edgeDashpotLoss(m_edges.data() + b.firstEdge, m_edgeDampingLambda.data() + b.firstEdge, b.count,
                                                x, xPrev, h);
            m_dampingLoss += loss;
            m_bodyDampingLoss[k] += loss;
        }
    for (const BodyContact& c : m_bodyContacts)
        applyContactFriction(c, v, w, c.friction, h);
    for (int i = 0; i < np; ++i) {
        v[i].x = std::clamp(v[i].x, -vCap, vCap);
        v[i].y = std::clamp(v[i].y, -vCap, vCap);
    }
}

void XpbdWorld::placeChainRoots(double fraction)
{
    for (const Chain& c : m_chains)
        m_x[at(c.first)] = c.anchor.body >= 0 ? anchorPoint(c.anchor)
                                              : c.fixedFrom + Point(fraction * (c.fixedTo.x - c.fixedFrom.x),
                                                                    fraction * (c.fixedTo.y - c.fixedFrom.y));
}

bool XpbdWorld::checkValid(const Body& b) const
{
    const double a = signedArea(&m_x[at(b.first)], b.count);
    if (a < 0 || a < kRecoveredShare * b.target)
        return false;
    return !polygonSelfIntersects(&m_x[at(b.first)], b.count);
}

void XpbdWorld::updateValidity()
{
    for (Body& b : m_bodies) {
        const Point* x = &m_x[at(b.first)];
        const double a = signedArea(x, b.count);
        if (!b.recovering) {
            // Inside out, squashed flat or crossing itself: recover.
            b.recovering = a < 0 || a < kCollapsedShare * b.target || polygonSelfIntersects(x, b.count);
        } else {
            b.recovering = !checkValid(b);
        }
    }
}

// ---------------------------------------------------------------------------------------
// Grabbing
// ---------------------------------------------------------------------------------------

bool XpbdWorld::press(Point p)
{
    if (m_grabBody >= 0 || !isFinite(p))
        return false;
    for (int k = bodyCount() - 1; k >= 0; --k) { // the last added is drawn on top
        const Body& b = m_bodies[at(k)];
        const Point* x = &m_x[at(b.first)];
        if (!boundingBox(x, b.count).contains(p) || !pointInPolygon(x, b.count, p))
            continue;
        m_grabIdx.clear();
        m_grabRest.clear();
        switch (m_params.grabMode) {
        case GrabMode::Above: // §4.7: "els vèrtexs situats per damunt del punt"
            for (int i = 0; i < b.count; ++i)
                if (x[i].y < p.y)
                    m_grabIdx.push_back(b.first + i);
            if (m_grabIdx.empty()) {
                int nearest = 0;
                for (int i = 1; i < b.count; ++i)
                    if (distance(x[i], p) < distance(x[nearest], p))
                        nearest = i;
                m_grabIdx.push_back(b.first + nearest);
            }
            break;
        case GrabMode::Anchors: // Annex II l. 363–367
            m_grabIdx = {b.first, b.first + 1, b.first + b.count - 1};
            break;
        case GrabMode::All:
            for (int i = 0; i < b.count; ++i)
                m_grabIdx.push_back(b.first + i);
            break;
        }
        for (int i : m_grabIdx)
            m_grabRest.push_back(distance(m_x[at(i)], p)); // the seed's estruc
        m_grabBody = k;
        m_mouse = m_mouseFrom = p;
        m_mouseVelocity = Point();
        return true;
    }
    return false;
}

void XpbdWorld::move(Point p)
{
    if (!isFinite(p))
        return;
    m_mouse = clampToFrame(p);
}

void XpbdWorld::release()
{
    if (m_grabBody < 0)
        return;
    // The body leaves with the mouse's velocity: shift every vertex's velocity so that
    // their mean is the mouse's (the spin and wobble relative to it are kept).
    const Body& b = m_bodies[at(m_grabBody)];
    Point mean;
    for (int i = 0; i < b.count; ++i)
        mean += m_v[at(b.first + i)];
    mean = Point(mean.x / b.count, mean.y / b.count);
    Point target = m_mouseVelocity;
    target.x = std::clamp(target.x, -m_params.velmax, m_params.velmax);
    target.y = std::clamp(target.y, -m_params.velmax, m_params.velmax);
    for (int i = 0; i < b.count; ++i)
        m_v[at(b.first + i)] += target - mean;
    m_grabBody = -1;
    m_grabIdx.clear();
    m_grabRest.clear();
}

// ---------------------------------------------------------------------------------------
// State and readouts
// ---------------------------------------------------------------------------------------

ParticleRange XpbdWorld::bodyRange(int body) const
{
    assert(body >= 0 && body < bodyCount());
    return {m_bodies[at(body)].first, m_bodies[at(body)].count};
}

ParticleRange XpbdWorld::chainRange(int chain) const
{
    assert(chain >= 0 && chain < chainCount());
    return {m_chains[at(chain)].first, m_chains[at(chain)].count};
}

std::vector<Point> XpbdWorld::bodyVertices(int body) const
{
    const ParticleRange r = bodyRange(body);
    return {m_x.begin() + r.first, m_x.begin() + r.first + r.count};
}

std::vector<Point> XpbdWorld::chainJoints(int chain) const
{
    const ParticleRange r = chainRange(chain);
    return {m_x.begin() + r.first, m_x.begin() + r.first + r.count};
}

std::vector<Point> XpbdWorld::obstaclePoints(int index) const
{
    const XpbdObstacle& o = obstacle(index);
    return {m_obstaclePoints.begin() + o.first, m_obstaclePoints.begin() + o.first + o.count};
}

double XpbdWorld::area(int body) const
{
    const ParticleRange r = bodyRange(body);
    return signedArea(&m_x[at(r.first)], r.count);
}

double XpbdWorld::targetArea(int body) const
{
    assert(body >= 0 && body < bodyCount());
    return m_bodies[at(body)].target;
}

double XpbdWorld::areaErrorPercent(int body) const { return areaErrorPercent(area(body), targetArea(body)); }

double XpbdWorld::areaErrorPercent(double area, double target) { return 100 * (area - target) / std::max(target, 1.0); }

double XpbdWorld::maxEdgeStretch(int body) const { return bodyShape(body).stretch(); }

double XpbdWorld::BodyShape::stretch() const
{
    if (!(smallestRatio2 <= largestRatio2))
        return tiny;
    return std::max({tiny, std::sqrt(largestRatio2) - 1, 1 - std::sqrt(smallestRatio2)});
}

XpbdWorld::BodyShape XpbdWorld::bodyShape(int body) const
{
    const double h = m_params.dt / m_params.substeps;
    const double invH2 = 1 / (h * h);
    const Body& b = m_bodies[at(body)];
    BodyShape s;
    // |L/L₀ − 1| is largest at the edge longest or the edge shortest for its rest length, so
    // the pass keeps the largest and the smallest L²/L₀², and stretch() takes a square root
    // of those two only (a readout of every step: the scene's takes two for all its bodies).
    // max and min compile to no branch: keeping the longest edge's pair by comparing cross
    // products branched on each new longest edge, mispredicted a few times a body. An edge
    // under 1 px at rest is measured against 1 px, |L − L₀|. A position that is not a number
    // is passed over. The area is summed in the same pass, as signedArea sums it (relative
    // to the first vertex, in the same order: the same bits).
    // Kept in locals, not in `s`: the compiler cannot tell that the result does not alias
    // the positions, and would store it on every edge.
    const Point* x = &m_x[at(b.first)];
    const Point o = x[0];
    double twiceArea = 0, tension = s.tension, largest = s.largestRatio2, smallest = s.smallestRatio2, tiny = s.tiny;
    Point prev = b.count > 1 ? x[1] - o : Point();
    for (int k = 0; k < b.count; ++k) {
        if (k >= 2) { // signedArea: the cross products of vertices 1–2, 2–3, …, relative to x₀
            const Point cur = x[k] - o;
            twiceArea += cross(prev, cur);
            prev = cur;
        }
        const DistanceConstraint& e = m_edges[at(b.firstEdge + k)];
        const Point d = m_x[at(e.b)] - m_x[at(e.a)];
        const double l2 = d.x * d.x + d.y * d.y;
        tension = std::max(tension, -e.lambda * invH2);
        if (!(l2 >= 0))
            continue;
        if (e.rest < 1) {
            tiny = std::max(tiny, std::abs(std::sqrt(l2) - e.rest));
            continue;
        }
        const double q = l2 / (e.rest * e.rest);
        largest = std::max(largest, q);
        smallest = std::min(smallest, q);
    }
    s.area = 0.5 * twiceArea;
    s.tension = tension;
    s.largestRatio2 = largest;
    s.smallestRatio2 = smallest;
    s.tiny = tiny;
    return s;
}

double XpbdWorld::areaPressure(int body) const
{
    const double h = m_params.dt / m_params.substeps;
    return m_bodies[at(body)].areaLambda / (h * h);
}

double XpbdWorld::maxEdgeTension(int body) const { return bodyShape(body).tension; }

double XpbdWorld::angleLimitTorque(int chain) const
{
    const double h = m_params.dt / m_params.substeps;
    const Chain& c = m_chains[at(chain)];
    double worst = 0;
    for (int k = 0; k < c.angleCount; ++k)
        worst = std::max(worst, std::abs(m_angles[at(c.firstAngle + k)].lambda) / (h * h));
    return worst;
}

XpbdWorld::EdgeRest XpbdWorld::edgeRest(int body, int edge) const
{
    assert(body >= 0 && body < bodyCount() && edge >= 0 && edge < m_bodies[at(body)].count);
    const DistanceConstraint& c = m_edges[at(m_bodies[at(body)].firstEdge + edge)];
    const double w = m_w[at(c.a)];
    return {c.rest, w > 0 ? 1 / w : 0.0};
}

Point XpbdWorld::centroid(int body) const
{
    const ParticleRange r = bodyRange(body);
    return vertexCentroid(&m_x[at(r.first)], r.count);
}

double XpbdWorld::orientation(int body) const
{
    const ParticleRange r = bodyRange(body);
    const Point* x = &m_x[at(r.first)];
    return bestFitRotation(x, &m_rest[at(r.first)], r.count, vertexCentroid(x, r.count));
}

bool XpbdWorld::recovering(int body) const
{
    assert(body >= 0 && body < bodyCount());
    return m_bodies[at(body)].recovering;
}

bool XpbdWorld::isValid(int body) const
{
    assert(body >= 0 && body < bodyCount());
    return checkValid(m_bodies[at(body)]);
}

double XpbdWorld::kineticEnergy() const
{
    double e = 0;
    for (std::size_t i = 0; i < m_x.size(); ++i)
        if (m_w[i] > 0)
            e += 0.5 * dot(m_v[i], m_v[i]) / m_w[i];
    return e;
}

XpbdWorld::MotionEnergies XpbdWorld::motionEnergies(std::vector<BodyEnergies>* bodies) const
{
    // The sums in locals and the arrays through plain pointers: stores to a body's energies
    // could otherwise alias them, and be made (and the arrays' ends reloaded) every particle.
    const Point g = m_params.gravity;
    const std::size_t n = m_x.size();
    const Point* x = m_x.data();
    const Point* v = m_v.data();
    const double* w = m_w.data();
    const double* mass = m_mass.data();
    double kineticSum = 0, gravitySum = 0, movingMass = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (!(w[i] > 0))
            continue;
        const double m = mass[i];
        const double kinetic = 0.5 * dot(v[i], v[i]) * m;
        const double gravity = dot(g, x[i]) * m;
        kineticSum += kinetic;
        gravitySum -= gravity;
        movingMass += m;
        if (bodies && m_owner[i] >= 0) {
            BodyEnergies& b = (*bodies)[at(m_owner[i])];
            b.kinetic += kinetic;
            b.gravity -= gravity;
            b.movingMass += m;
            b.dampingLoss += m_particleDampingLoss[i];
        }
    }
    MotionEnergies e;
    e.kinetic = kineticSum;
    e.gravity = gravitySum;
    e.movingMass = movingMass;
    return e;
}

void XpbdWorld::bodyLosses(std::vector<BodyEnergies>& bodies) const
{
    for (std::size_t k = 0; k < m_bodies.size(); ++k) {
        bodies[k].dampingLoss += m_bodyDampingLoss[k];
        bodies[k].contacts = m_bodyContactCount[k];
    }
}

double XpbdWorld::movingMass() const
{
    double m = 0;
    for (double w : m_w)
        if (w > 0)
            m += 1 / w;
    return m;
}


double XpbdWorld::gravityEnergy() const
{
    double e = 0;
    for (std::size_t i = 0; i < m_x.size(); ++i)
        if (m_w[i] > 0)
            e -= dot(m_params.gravity, m_x[i]) / m_w[i];
    return e;
}

double XpbdWorld::elasticEnergy(std::vector<BodyEnergies>* bodies) const
{
    // U = ½ α F² with F = λ/h² the force of the last substep: the complementary form of
    // ½ C²/α (at the XPBD solution C = −α F, Macklin et al. 2016, eq. 9). Unlike C²/(2α) it
    // does not blow up the leftover error of a very stiff constraint, and is 0 for α = 0.
    const double h = m_params.dt / m_params.substeps;
    const double invH2 = 1 / (h * h);
    double e = 0;
    // Each constraint's energy, also booked to the body of its particle `owner` (bodies).
    const auto add = [&](double alpha, double lambda, int owner) {
        const double f = lambda * invH2;
        const double u = 0.5 * alpha * f * f;
        e += u;
        if (bodies && m_owner[at(owner)] >= 0)
            (*bodies)[at(m_owner[at(owner)])].elastic += u;
    };
    const bool dashpots = m_params.edgeDampingRatio > 0; // then λ holds their part too
    for (std::size_t k = 0; k < m_edges.size(); ++k) {   // the spring's force, not the dashpot's
        const DistanceConstraint& c = m_edges[k];
        add(m_params.edgeCompliance * c.complianceScale, dashpots ? c.lambda - m_edgeDampingLambda[k] : c.lambda, c.a);
    }
    for (const DistanceConstraint& c : m_links)
        add(m_params.linkCompliance, c.lambda, c.b);
    for (const AnchoredDistanceConstraint& c : m_anchorLinks)
        add(m_params.linkCompliance, c.lambda, c.joint);
    for (const Body& b : m_bodies)
        add(m_params.areaCompliance, b.areaLambda, b.first);
    for (const AngleConstraint& a : m_angles)
        if (a.kind == ConstraintKind::Bending)
            add(m_params.bendCompliance, a.lambda, a.a1);
    return e;
}

} // namespace granota
