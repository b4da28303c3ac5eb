#include "core/softbody/xpbd/xpbd_world.h"

#include "core/softbody/xpbd/xpbd_index.h"
#include "core/softbody/xpbd/xpbd_recovery.h"

#include <algorithm>
#include <cmath>

// XpbdWorld's step (Macklin et al. 2019, alg. 1, with the stages of Box2D v3's solver named
// one by one): the broad phase once per step, then per substep integrate, the bodies'
// constraints, the mouse, the contacts with obstacles and between bodies, the chains, the
// frame, the velocities, the dashpots and the friction; validity at the end of the step.

namespace granota {

using xpbd::at;

namespace {

/// A body below this share of its target area is taken as squashed flat and recovered by
/// shape matching (xpbd_recovery.h)…
constexpr double kCollapsedShare = 0.2;
/// …and is valid again from this share on (hysteresis: no flicker at the threshold).
constexpr double kRecoveredShare = 0.5;
/// Passes over each chain per substep (alternately root to tip and back).
constexpr int kChainPasses = 4;

} // namespace

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
    Substep s;
    s.h = h;
    s.invH2 = 1 / (h * h);
    s.fraction = fraction;
    // A particle cannot usefully cross more than the frame in one substep: this cap keeps
    // every number finite for any gravity, step or initial velocity; velmax is the seed's.
    s.vCap = std::min(p.velmax, (p.width + p.height) / h);
    // Velocity kept per substep: f per step (dt = 1) becomes f^h, so n substeps keep f.
    s.keep = Point(std::pow(p.damping.x, h), std::pow(p.damping.y, h));

    integrate(s);            // 1. predict
    solveBodies(s);          // 2. constraints, one pass, λ = 0 at the start
    solveGrab(s);            //    the mouse's ropes
    solveObstacleContacts(); // 3. contacts: obstacles (§5.2.1)
    solveBodyContacts();     //    bodies against bodies (§5.2.2)
    solveChains(s);          //    the legs and ropes, after what moves what they hang from
    solveFrame(s);           //    the frame, last
    updateVelocities(s);     // 4. velocities, with restitution
    dampEdges(s);            //    what the edges' dashpots took
    applyFriction(s);        //    contact friction, then the speed cap
}

// 1. Predict: the damping f^h and gravity on every velocity, the speed cap, x += v h.
void XpbdWorld::integrate(const Substep& s)
{
    const XpbdParams& p = m_params;
    const double h = s.h;
    const int np = particleCount();
    Point* x = m_x.data();
    Point* xPrev = m_xPrev.data();
    Point* v = m_v.data();
    const double* w = m_w.data();
    const Point lost(1 - s.keep.x * s.keep.x, 1 - s.keep.y * s.keep.y);
    double dampingLoss = 0; // ×2m
    for (int i = 0; i < np; ++i) {
        xPrev[i] = x[i];
        m_contact[at(i)] = Point();
        if (!(w[i] > 0))
            continue;
        const double loss = (lost.x * v[i].x * v[i].x + lost.y * v[i].y * v[i].y) / w[i];
        dampingLoss += loss;
        m_particleDampingLoss[at(i)] += 0.5 * loss; // summed per body when asked (motionEnergies)
        Point vi(s.keep.x * v[i].x + p.gravity.x * h, s.keep.y * v[i].y + p.gravity.y * h);
        vi.x = std::clamp(vi.x, -s.vCap, s.vCap);
        vi.y = std::clamp(vi.y, -s.vCap, s.vCap);
        v[i] = vi;
        x[i] += Point(vi.x * h, vi.y * h);
    }
    m_dampingLoss += 0.5 * dampingLoss;
    placeChainRoots(s.fraction);
}

// 2. The bodies' constraints, one pass, λ = 0 at the start (Macklin et al. 2019, alg. 1).
void XpbdWorld::solveBodies(const Substep& s)
{
    const XpbdParams& p = m_params;
    Point* x = m_x.data();
    const Point* xPrev = m_xPrev.data();
    const double* w = m_w.data();
    const double edgeAlpha = p.edgeCompliance * s.invH2;
    const double areaAlpha = p.areaCompliance * s.invH2;
    const double bendAlpha = p.bendCompliance * s.invH2;
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
}

// The mouse ties: ropes of fixed length to the mouse (Annex II l. 266–283), compliant, each
// force capped: |λ|/h² ≤ grabMaxForce.
void XpbdWorld::solveGrab(const Substep& s)
{
    if (m_grabBody < 0)
        return;
    const XpbdParams& p = m_params;
    Point* x = m_x.data();
    const double* w = m_w.data();
    const Point m = m_mouseFrom + Point(s.fraction * (m_mouse.x - m_mouseFrom.x), s.fraction * (m_mouse.y - m_mouseFrom.y));
    const double alpha = p.grabCompliance * s.invH2;
    const double cap = p.grabMaxForce * s.h * s.h;
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

// 3. Contacts with the obstacles (§5.2.1): bodies' vertices against the obstacle, and the
// obstacle's corners against the bodies (a sharp corner between two vertices); the chains'
// joints against every obstacle.
void XpbdWorld::solveObstacleContacts()
{
    const XpbdParams& p = m_params;
    Point* x = m_x.data();
    Point* xPrev = m_xPrev.data();
    const double* w = m_w.data();
    m_bodyContacts.clear();
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
}

// Bodies against bodies (§5.2.2): the pairs of the broad phase; the vertices of each inside
// (or within the skin of) the other are pushed out against its nearest edge.
void XpbdWorld::solveBodyContacts()
{
    if (m_candidates.empty())
        return;
    const XpbdParams& p = m_params;
    Point* x = m_x.data();
    const double* w = m_w.data();
    const double margin = p.contactMargin;
    m_tightBoxes.resize(m_bodies.size());
    for (std::size_t k = 0; k < m_bodies.size(); ++k) {
        const Body& b = m_bodies[k];
        Aabb box = boundingBox(x + b.first, b.count);
        box.minX -= margin, box.minY -= margin, box.maxX += margin, box.maxY += margin;
        m_tightBoxes[k] = box;
        m_bodies[k].orientationSign = signedArea(x + b.first, b.count) < 0 ? -1.0 : 1.0;
    }
    // A vertex pushed out against an edge last substep is, in a pile, nearly always still
    // behind that edge: it is solved against that edge alone, at the cost of one edge; the
    // exact test (every edge, twice) runs only when it has left the edge's span or front,
    // and for every other candidate — so new contacts are met at once.
    for (ContactCandidate& cand : m_candidates) {
        const int i = cand.particle;
        const Body& b = m_bodies[at(cand.body)];
        BodyContact contact;
        const bool kept = cand.touching &&
                          solvePointAgainstEdge(x, w, i, b.first + cand.edge, b.first + (cand.edge + 1) % b.count,
                                                b.orientationSign, margin, &contact);
        cand.touching = kept ||
                        (m_tightBoxes[at(cand.body)].contains(x[i]) &&
                         solvePointInBody(x, w, i, Point(), b.first, b.count, b.orientationSign, margin, &contact, &cand.edge));
        if (cand.touching) {
            contact.friction = p.contactFriction;
            m_bodyContacts.push_back(contact);
        }
    }
}

// Chains, after everything that moves the bodies they hang from (mouse, contacts), so that
// the shoulders do not move under them: Gauss–Seidel from the root outwards, as §4.14
// corrects joint after joint, then back. Legs are rigid (α = 0) and light, hung from a heavy
// body: one pass leaves the root link stretched by whatever the next link pulled, so a few
// passes are made; chains are tiny, so this costs next to nothing. λ accumulates over the
// passes.
void XpbdWorld::solveChains(const Substep& s)
{
    const XpbdParams& p = m_params;
    Point* x = m_x.data();
    Point* xPrev = m_xPrev.data();
    const double* w = m_w.data();
    const double linkAlpha = p.linkCompliance * s.invH2;
    placeChainRoots(s.fraction);
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
}

// The frame, last: whatever happened above, every particle ends the substep inside.
void XpbdWorld::solveFrame(const Substep& s)
{
    const XpbdParams& p = m_params;
    solveWalls(m_x.data(), m_xPrev.data(), m_w.data(), m_contact.data(), particleCount(), p.width, p.height, p.wallFriction);
    placeChainRoots(s.fraction); // shoulders follow the body wherever the contacts put it
}

// 4. Velocities, with restitution at walls and obstacles (Müller et al. 2020, eq. 34): the
// normal speed becomes −e times the one before the solve; slow hits (below 2|g|h) do not
// bounce, so that resting contact stays at rest. The contacts are counted here.
void XpbdWorld::updateVelocities(const Substep& s)
{
    const XpbdParams& p = m_params;
    const double h = s.h;
    const int np = particleCount();
    const Point* x = m_x.data();
    const Point* xPrev = m_xPrev.data();
    Point* v = m_v.data();
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
}

// What the edges' dashpots took (ζ > 0), with the damping f: the damping loss.
void XpbdWorld::dampEdges(const Substep& s)
{
    if (!(m_params.edgeDampingRatio > 0))
        return;
    for (std::size_t k = 0; k < m_bodies.size(); ++k) {
        const Body& b = m_bodies[k];
        if (b.recovering)
            continue;
        const double loss = edgeDashpotLoss(m_edges.data() + b.firstEdge, m_edgeDampingLambda.data() + b.firstEdge, b.count,
                                            m_x.data(), m_xPrev.data(), s.h);
        m_dampingLoss += loss;
        m_bodyDampingLoss[k] += loss;
    }
}

// Friction at every contact of a body, then the speed cap on every particle.
void XpbdWorld::applyFriction(const Substep& s)
{
    Point* v = m_v.data();
    const double* w = m_w.data();
    for (const BodyContact& c : m_bodyContacts)
        applyContactFriction(c, v, w, c.friction, s.h);
    const int np = particleCount();
    for (int i = 0; i < np; ++i) {
        v[i].x = std::clamp(v[i].x, -s.vCap, s.vCap);
        v[i].y = std::clamp(v[i].y, -s.vCap, s.vCap);
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

} // namespace granota
