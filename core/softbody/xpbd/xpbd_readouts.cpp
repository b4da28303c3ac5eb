#include "core/softbody/xpbd/xpbd_world.h"

#include "core/softbody/xpbd/xpbd_index.h"
#include "core/softbody/xpbd/xpbd_recovery.h"

#include <algorithm>
#include <cmath>

// XpbdWorld's state and readouts: the particles of a body or chain, areas, shapes, energies
// and losses (what the Frog tab's readouts and the series show).

namespace granota {

using xpbd::at;

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
