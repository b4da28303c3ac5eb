#include "core/softbody/seed/seed_frog.h"

#include <algorithm>
#include <utility>

namespace granota {

template <class R>
SeedFrog<R>::SeedFrog(SeedBody<R> body, std::vector<SeedLeg<R>> legs) : m_body(std::move(body)), m_legs(std::move(legs))
{
    if (!m_legs.empty()) {
        const SeedLeg<R>* in[4];
        for (std::size_t i = 0; i < 4; ++i)
            in[i] = &m_legs[std::min(i, m_legs.size() - 1)];
        m_legLanes = SeedLegLanes<R>(in, static_cast<int>(std::min<std::size_t>(m_legs.size(), 4)));
    }
    // Annex II assumes ten vertices ("Podem assumir ara ja que el poligon del cos te 10
    // vertex") and attaches the legs between vertices 2, 3, 4, 6, 7 and 8. For another N
    // the vertex at the same angle is taken, round(k·N/10) (half up): the same indices for
    // N = 10, and always in 0..N (vertex N is the seed's copy of vertex 0).
    const int n = m_body.sides();
    const int k[6] = {2, 3, 4, 6, 7, 8};
    for (int i = 0; i < 6; ++i)
        m_attach[std::size_t(i)] = (2 * k[i] * n + 10) / 20;
}

template <class R> Expected<SeedFrog<R>> SeedFrog<R>::create(const FrogParams& params, SeedComponents components)
{
    auto body = SeedBody<R>::create(params, components);
    if (!body)
        return body.error();
    const Vec centre(R(params.center.x), R(params.center.y));
    std::vector<SeedLeg<R>> legs;
    if (components.legs) {
        // SeedFrog.java, main: the legs start at the centre (not clamped to the frame, as
        // in the seed), along +x.
        const Point c(double(centre.x), double(centre.y));
        for (int i = 0; i < 4; ++i) {
            auto leg = SeedLeg<R>::create(params, i, c, components);
            if (!leg)
                return leg.error();
            legs.push_back(std::move(leg).value());
        }
    }
    return SeedFrog(std::move(body).value(), std::move(legs));
}

template <class R> void SeedFrog<R>::step()
{
    if (m_legs.empty()) {
        m_body.step();
        return;
    }
    // The legs' step owed from the last call (see seed_frog.h) goes between the parts of
    // this body step: the legs follow the body of the last step, which is done.
    if (m_legsOwed) {
        typename SeedLegLanes<R>::Step legs(m_legLanes);
        m_body.stepWith(legs);
    } else {
        m_body.step();
    }
    // Annex II, Granota.actualitza: the front legs sit on the chord v2–v8, a fifth of the
    // way in from each end; the back legs at the midpoints of the edges v3–v4 and v6–v7:
    //   front right v8 − (v8 − v2)/5, front left v2 + (v8 − v2)/5,
    //   back right v6 + (v7 − v6)/2,  back left v4 + (v3 − v4)/2,
    // one leg per lane as a + (p − q)/d·s. s = ±1 only gives the sign (exact), and
    // v8 + (−des) is v8 − des exactly (IEEE subtraction is the addition of the negation).
    using L = Lanes<R>;
    const R* const x = m_body.positionsX();
    const R* const y = m_body.positionsY();
    const int v2 = m_attach[0], v3 = m_attach[1], v4 = m_attach[2], v6 = m_attach[3], v7 = m_attach[4], v8 = m_attach[5];
    const L d = L::set(R(5), R(5), R(2), R(2)), s = L::set(R(-1), R(1), R(1), R(1));
    const auto shoulder = [&](const R* c) {
        const L p = L::set(c[v8], c[v8], c[v7], c[v3]);
        const L q = L::set(c[v2], c[v2], c[v6], c[v4]);
        const L a = firstLaneFrom(q, p); // (v8, v2, v6, v4)
        return a + (p - q) / d * s;
    };
    // Annex II steps the legs one after the other (dd, dr, ed, er); they do not act on
    // each other, so all four go at once, one per SIMD lane (SeedLegLanes).
    m_legLanes.moveShoulders(shoulder(x), shoulder(y));
    m_legsOwed = true;
    m_legsStale = true;
}

template <class R> void SeedFrog<R>::settleLegs() const
{
    if (m_legsOwed) {
        m_legLanes.step();
        m_legsOwed = false;
    }
}

template <class R> void SeedFrog<R>::syncLegs() const
{
    settleLegs();
    SeedLeg<R>* out[4];
    for (std::size_t i = 0; i < m_legs.size() && i < 4; ++i)
        out[i] = &m_legs[i];
    m_legLanes.store(out);
    m_legsStale = false;
}

template class SeedFrog<float>;
template class SeedFrog<double>;

} // namespace granota
