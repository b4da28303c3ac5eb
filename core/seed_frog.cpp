#include "core/seed_frog.h"

#include <algorithm>
#include <utility>

namespace granota {

template <class R>
SeedFrog<R>::SeedFrog(SeedBody<R> body, std::vector<SeedLeg<R>> legs, const Vec& centre)
    : m_body(std::move(body)), m_legs(std::move(legs))
{
    m_shoulders.fill(centre);
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
    return SeedFrog(std::move(body).value(), std::move(legs), centre);
}

template <class R> void SeedFrog<R>::computeShoulders()
{
    // Annex II, Granota.actualitza: the front legs sit on the chord v2–v8, a fifth of the
    // way in from each end; the back legs at the midpoints of the edges v3–v4 and v6–v7.
    const auto& v = m_body.seedVertices();
    const Vec& v2 = v[std::size_t(m_attach[0])].pos;
    const Vec& v3 = v[std::size_t(m_attach[1])].pos;
    const Vec& v4 = v[std::size_t(m_attach[2])].pos;
    const Vec& v6 = v[std::size_t(m_attach[3])].pos;
    const Vec& v7 = v[std::size_t(m_attach[4])].pos;
    const Vec& v8 = v[std::size_t(m_attach[5])].pos;
    const R desx = (v8.x - v2.x) / R(5), desy = (v8.y - v2.y) / R(5);
    const Vec esDav(R(v2.x + desx), R(v2.y + desy));
    const Vec dreDav(R(v8.x - desx), R(v8.y - desy));
    const R desyd = (v3.y - v4.y) / R(2), desxd = (v3.x - v4.x) / R(2);
    const R desye = (v7.y - v6.y) / R(2), desxe = (v7.x - v6.x) / R(2);
    const Vec esDar(R(v4.x + desxd), R(v4.y + desyd));
    const Vec dreDar(R(v6.x + desxe), R(v6.y + desye));
    m_shoulders[seedleg::FrontRight] = dreDav;
    m_shoulders[seedleg::FrontLeft] = esDav;
    m_shoulders[seedleg::BackRight] = dreDar;
    m_shoulders[seedleg::BackLeft] = esDar;
}

template <class R> void SeedFrog<R>::step()
{
    m_body.step();
    if (m_legs.empty())
        return;
    computeShoulders();
    // Annex II steps the legs one after the other (dd, dr, ed, er); they do not act on
    // each other, so all four go at once, one per SIMD lane (SeedLeg::stepTogether).
    SeedLeg<R>* legs[4];
    Point shoulders[4];
    const int count = static_cast<int>(std::min<std::size_t>(m_legs.size(), 4));
    for (int i = 0; i < count; ++i) {
        legs[i] = &m_legs[std::size_t(i)];
        const Vec& s = m_shoulders[std::size_t(i)];
        shoulders[i] = Point(double(s.x), double(s.y));
    }
    SeedLeg<R>::stepTogether(legs, shoulders, count);
}

template class SeedFrog<float>;
template class SeedFrog<double>;

} // namespace granota
