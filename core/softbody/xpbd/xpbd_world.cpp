#include "core/softbody/xpbd/xpbd_world.h"
#include "core/base/math_constants.h"

#include "core/softbody/regular_polygon.h"
#include "core/softbody/xpbd/xpbd_index.h"
#include "core/softbody/xpbd/xpbd_recovery.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

// XpbdWorld's building (bodies, chains, obstacles, their checks) and the mouse's grab; the
// step is in xpbd_step.cpp, the readouts in xpbd_readouts.cpp.

namespace granota {

using xpbd::at;

namespace {

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

} // namespace granota
