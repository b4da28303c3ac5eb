#pragma once
/// \file seed_leg_lanes.h
/// Up to four of the `seed` solver's legs (core/seed_leg.h) side by side, one per SIMD
/// lane (core/seed_lanes.h), and kept so from one step to the next: the frog's four legs
/// live here, their constants (lengths, friction, gravity, velmax, floor, §4.15's limits)
/// gathered into lanes once, and are copied back into SeedLeg objects only when read.
/// Annex II steps the legs one after the other; they do not act on each other, so
/// stepping them side by side is exactly stepping each.

#include "core/seed_lanes.h"
#include "core/seed_leg.h"

namespace granota {

template <class R> class SeedLegLanes {
public:
    using L = Lanes<R>;

    SeedLegLanes() = default;
    /// legs[0 .. count) (1 to 4 legs sharing their SeedComponents, as the frog's four do),
    /// one per lane; the lanes past `count` repeat leg 0 and are never written back.
    SeedLegLanes(const SeedLeg<R>* const* legs, int count);

    /// SeedLeg::step's move of the shoulder, lane by lane: a non-finite coordinate keeps
    /// the last one, the others are clamped to ±1e15.
    void moveShoulders(const L& sx, const L& sy)
    {
        // SeedLeg::moveShoulder takes R(clamp(double(s), −1e15, 1e15)). For R = float the
        // clamp in float to ±R(1e15) picks the same number: no float lies between R(1e15)
        // and 1e15. s − s is 0 exactly when s is finite (∞ − ∞ and NaN − NaN are NaN).
        const L zero = L::splat(R(0)), lo = L::splat(R(-1e15)), hi = L::splat(R(1e15));
        m_mx = select(ne(sx - sx, zero), m_mx, clampLanes(sx, lo, hi));
        m_my = select(ne(sy - sy, zero), m_my, clampLanes(sy, lo, hi));
    }
    /// Annex II, Pota.actualitza, every lane from its current shoulder.
    void step();
    /// The shoulders, elbows and wrists back into legs[0 .. count).
    void store(SeedLeg<R>* const* legs) const;
    int count() const { return m_count; }

private:
    SeedComponents m_components;
    int m_count = 0;
    // The state: shoulder (muscle), elbow (colze) and wrist (canell), current and previous.
    L m_mx, m_my, m_cx, m_cy, m_cpx, m_cpy, m_wx, m_wy, m_wpx, m_wpy;
    // The constants of each leg (SeedLeg's members of the same names).
    L m_moll1, m_moll2, m_fx, m_fy, m_gx, m_gy, m_velmax, m_floor, m_xmax;
    L m_limitRatio[4], m_limitOffX[4], m_limitOffY[4];
};

extern template class SeedLegLanes<float>;
extern template class SeedLegLanes<double>;

} // namespace granota
