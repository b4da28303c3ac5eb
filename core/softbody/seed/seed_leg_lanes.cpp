#include "core/softbody/seed/seed_leg_lanes.h"

#include <algorithm>

namespace granota {

template <class R> SeedLegLanes<R>::SeedLegLanes(const SeedLeg<R>* const* legs, int count)
{
    constexpr int W = kSeedLanes;
    static_assert(W == 4, "one leg per lane: the frog's four legs");
    m_count = std::clamp(count, 1, W);
    const SeedLeg<R>* in[W];
    for (int k = 0; k < W; ++k)
        in[k] = legs[k < m_count ? k : 0];
    const auto gather = [&in](auto field) { return L::set(field(*in[0]), field(*in[1]), field(*in[2]), field(*in[3])); };
    m_components = in[0]->m_components;
    m_mx = gather([](const SeedLeg<R>& l) { return l.m_muscle.x; });
    m_my = gather([](const SeedLeg<R>& l) { return l.m_muscle.y; });
    m_cx = gather([](const SeedLeg<R>& l) { return l.m_colze.pos.x; });
    m_cy = gather([](const SeedLeg<R>& l) { return l.m_colze.pos.y; });
    m_cpx = gather([](const SeedLeg<R>& l) { return l.m_colze.prev.x; });
    m_cpy = gather([](const SeedLeg<R>& l) { return l.m_colze.prev.y; });
    m_wx = gather([](const SeedLeg<R>& l) { return l.m_canell.pos.x; });
    m_wy = gather([](const SeedLeg<R>& l) { return l.m_canell.pos.y; });
    m_wpx = gather([](const SeedLeg<R>& l) { return l.m_canell.prev.x; });
    m_wpy = gather([](const SeedLeg<R>& l) { return l.m_canell.prev.y; });
    m_moll1 = gather([](const SeedLeg<R>& l) { return l.m_moll1; });
    m_moll2 = gather([](const SeedLeg<R>& l) { return l.m_moll2; });
    m_fx = gather([](const SeedLeg<R>& l) { return l.m_freg.x; });
    m_fy = gather([](const SeedLeg<R>& l) { return l.m_freg.y; });
    const bool gravity = m_components.gravity;
    m_gx = gather([gravity](const SeedLeg<R>& l) { return gravity ? l.m_grav.x : R(0); });
    m_gy = gather([gravity](const SeedLeg<R>& l) { return gravity ? l.m_grav.y : R(0); });
    m_velmax = gather([](const SeedLeg<R>& l) { return l.m_velmax; });
    m_floor = gather([](const SeedLeg<R>& l) { return l.m_floor; });
    m_xmax = gather([](const SeedLeg<R>& l) { return R(l.m_width - 1); });
    for (int k = 0; k < 4; ++k) {
        m_limitRatio[k] = gather([k](const SeedLeg<R>& l) { return l.m_limitRatio[k]; });
        m_limitOffX[k] = gather([k](const SeedLeg<R>& l) { return l.m_limitOffX[k]; });
        m_limitOffY[k] = gather([k](const SeedLeg<R>& l) { return l.m_limitOffY[k]; });
    }
}

template <class R> void SeedLegLanes<R>::store(SeedLeg<R>* const* legs) const
{
    constexpr int W = kSeedLanes;
    R out[10][W];
    const L* state[10] = {&m_mx, &m_my, &m_cx, &m_cy, &m_cpx, &m_cpy, &m_wx, &m_wy, &m_wpx, &m_wpy};
    for (int f = 0; f < 10; ++f)
        state[f]->store(out[f]);
    using Vec = Vec2<R>;
    for (int k = 0; k < m_count; ++k) {
        SeedLeg<R>& l = *legs[k];
        l.m_muscle = Vec(out[0][k], out[1][k]);
        l.m_colze.pos = Vec(out[2][k], out[3][k]);
        l.m_colze.prev = Vec(out[4][k], out[5][k]);
        l.m_canell.pos = Vec(out[6][k], out[7][k]);
        l.m_canell.prev = Vec(out[8][k], out[9][k]);
    }
}

template class SeedLegLanes<float>;
template class SeedLegLanes<double>;

} // namespace granota
