#include "core/seed_leg.h"

#include <algorithm>
#include <string>

namespace granota {

template <class R>
Expected<SeedLeg<R>> SeedLeg<R>::create(const FrogParams& params, int index, const Point& shoulder,
                                        SeedComponents components)
{
    if (index < 0 || index > 3)
        return makeError(ErrorCode::OutOfRange, "leg index must be 0 to 3, got " + std::to_string(index));
    return create(params, params.legs[std::size_t(index)], shoulder, components);
}

template <class R>
Expected<SeedLeg<R>> SeedLeg<R>::create(const FrogParams& params, const LegParams& leg, const Point& shoulder,
                                        SeedComponents components)
{
    FrogParams checked = params;
    checked.legs.fill(leg);
    if (auto e = checkSeedParams(checked))
        return *e;
    if (!isFinite(shoulder) || std::abs(shoulder.x) > 1e15 || std::abs(shoulder.y) > 1e15)
        return makeError(ErrorCode::InvalidInput, "the shoulder must be a finite point");
    SeedLeg l;
    l.m_components = components;
    // Annex II, Granota(...): punts = {centre, (centre.x + longit.x, centre.y),
    // (centre.x + longit.x + longit.y, centre.y)}, then Pota(punts, ...).
    const Vec p0(R(shoulder.x), R(shoulder.y));
    const Vec p1(R(p0.x + R(leg.upper)), p0.y);
    const Vec p2(R(p0.x + R(leg.upper) + R(leg.lower)), p0.y);
    l.m_muscle = p0;
    l.m_colze.pos = l.m_colze.prev = p1;
    l.m_canell.pos = l.m_canell.prev = p2;
    l.m_angmin1 = R(leg.shoulderMin);
    l.m_angmax1 = R(leg.shoulderMax);
    l.m_angmin2 = R(leg.elbowMin);
    l.m_angmax2 = R(leg.elbowMax);
    l.m_moll1 = seedmath::dist(p0.x, p0.y, p1.x, p1.y);
    l.m_moll2 = seedmath::dist(p1.x, p1.y, p2.x, p2.y);
    l.m_grav = Vec(R(params.gravity.x), R(params.gravity.y));
    l.m_freg = Vec(R(params.friction.x), R(params.friction.y));
    l.m_velmax = R(params.velmax);
    l.m_floor = R(params.height - 1);
    l.m_width = params.width;
    return l;
}

template <class R> void SeedLeg<R>::step(const Point& shoulder)
{
    // A non-finite shoulder is ignored (the leg keeps the last one); float(double(x)) == x,
    // so the frog passing its float shoulders through Point loses nothing.
    Vec m = m_muscle;
    if (std::isfinite(shoulder.x)) m.x = R(std::clamp(shoulder.x, -1e15, 1e15));
    if (std::isfinite(shoulder.y)) m.y = R(std::clamp(shoulder.y, -1e15, 1e15));
    update(m);
}

template <class R> void SeedLeg<R>::update(const Vec& mov)
{
    using namespace seedmath;
    m_muscle = mov;
    const Vec g = m_components.gravity ? m_grav : Vec(R(0), R(0));
    m_colze.verlet(m_freg, g, m_velmax);
    m_canell.verlet(m_freg, g, m_velmax);
    const Vec& mu = m_muscle;

    // §4.14: shoulder–elbow length, restored at once with Desp (the velocity is kept).
    if (dist(mu.x, mu.y, m_colze.pos.x, m_colze.pos.y) != m_moll1) {
        Vec d(R(m_colze.pos.x - mu.x), R(m_colze.pos.y - mu.y));
        // Elbow on the shoulder: d stays 0 and the elbow is put on the shoulder (finite, as
        // in the seed); the next Verlet step moves it off again.
        normalize(d);
        const Vec pr(R(mu.x + d.x * m_moll1), R(mu.y + d.y * m_moll1));
        m_colze.desp(Vec(R(pr.x - m_colze.pos.x), R(pr.y - m_colze.pos.y)));
    }

    // §4.15: the angle of shoulder→elbow measured from straight down, acos(Δy/|Δ|), taken
    // positive when the elbow is left of the shoulder and negative when right of it.
    // Guard: a zero length gives 0/0 — NaN in the seed, whose comparisons are then false
    // and leave the point alone; we skip the test, which is the same. The ratio is
    // clamped to [−1, 1]: rounding can never push |Δy|/|Δ| past 1 with correctly rounded
    // operations, but acos of anything beyond is NaN.
    auto angleOf = [](const Vec& from, const Vec& to, R& angle) {
        const R len = dist(from.x, from.y, to.x, to.y);
        if (!(len > 0))
            return false;
        R ratio = (to.y - from.y) / len;
        ratio = std::min(std::max(ratio, R(-1)), R(1));
        angle = acos(ratio);
        return true;
    };
    R a = 0;
    if (m_components.angleLimits) {
        if (mu.x - m_colze.pos.x >= 0) {
            if (angleOf(mu, m_colze.pos, a) && a > m_angmax1)
                m_colze.pos = Vec(R(mu.x - sin(m_angmax1) * m_moll1), R(mu.y + cos(m_angmax1) * m_moll1));
        } else {
            if (angleOf(mu, m_colze.pos, a) && -a < m_angmin1)
                m_colze.pos = Vec(R(mu.x - sin(m_angmin1) * m_moll1), R(mu.y + cos(m_angmin1) * m_moll1));
        }
    }

    // Elbow–wrist length.
    const Vec& c = m_colze.pos;
    if (dist(c.x, c.y, m_canell.pos.x, m_canell.pos.y) != m_moll2) {
        Vec d(R(m_canell.pos.x - c.x), R(m_canell.pos.y - c.y));
        normalize(d);
        const Vec pr(R(c.x + d.x * m_moll2), R(c.y + d.y * m_moll2));
        m_canell.desp(Vec(R(pr.x - m_canell.pos.x), R(pr.y - m_canell.pos.y)));
    }

    // Elbow–wrist angle, measured the same way (in the screen's frame, not the elbow's).
    if (m_components.angleLimits) {
        if (c.x - m_canell.pos.x >= 0) {
            if (angleOf(c, m_canell.pos, a) && a > m_angmax2)
                m_canell.pos = Vec(R(c.x - sin(m_angmax2) * m_moll2), R(c.y + cos(m_angmax2) * m_moll2));
        } else {
            if (angleOf(c, m_canell.pos, a) && -a < m_angmin2)
                m_canell.pos = Vec(R(c.x - sin(m_angmin2) * m_moll2), R(c.y + cos(m_angmin2) * m_moll2));
        }
    }

    // "Corregim la posicio del canell si se n'ix del marc": a wrist below the floor is
    // lifted by dy, and the elbow, lifted by the same dy, slides horizontally back onto
    // the circle of radius moll1 round the shoulder: (x − mx)² + (my − (cy − dy))² = moll1²,
    // i.e. x² + b x + c = 0 with b = −2 mx. Both joints move by the same dx.
    if (m_components.bounds && m_canell.pos.y > m_floor) {
        const R dy = dist(m_canell.pos.x, m_canell.pos.y, m_canell.pos.x, m_floor);
        const R qa = 1;
        const R qb = R(-2) * mu.x;
        const R lifted = R(mu.y - R(m_colze.pos.y - dy));
        const R qc = R(mu.x * mu.x + lifted * lifted - m_moll1 * m_moll1);
        R disc = R(qb * qb - R(4) * qa * qc);
        // Guard: when the lifted elbow is more than moll1 above or below the shoulder the
        // circle has no point at that height and the seed takes sqrt of a negative number,
        // writing NaN into the leg for good. We take the nearest real solution
        // (discriminant 0: the elbow on the vertical through the shoulder).
        if (!(disc >= 0))
            disc = 0;
        const R noux = m_colze.pos.x >= mu.x ? R((-qb + sqrt(disc)) / (R(2) * qa))
                                             : R((-qb - sqrt(disc)) / (R(2) * qa));
        const R dx = noux - m_colze.pos.x;
        m_canell.pos = Vec(R(m_canell.pos.x + dx), R(m_canell.pos.y - dy));
        m_colze.pos = Vec(R(m_colze.pos.x + dx), R(m_colze.pos.y - dy));
    }

    // Beyond the seed (SeedComponents::clampLegs): the joints stay in the frame like the
    // body's vertices. Only the current position is clamped, as `fita` does.
    if (m_components.clampLegs) {
        const R xmax = R(m_width - 1);
        m_colze.fita(R(0), xmax, R(0), m_floor);
        m_canell.fita(R(0), xmax, R(0), m_floor);
    }
}

template <class R> std::vector<Point> SeedLeg<R>::joints() const
{
    return {Point(double(m_muscle.x), double(m_muscle.y)), Point(double(m_colze.pos.x), double(m_colze.pos.y)),
            Point(double(m_canell.pos.x), double(m_canell.pos.y))};
}

template class SeedLeg<float>;
template class SeedLeg<double>;

} // namespace granota
