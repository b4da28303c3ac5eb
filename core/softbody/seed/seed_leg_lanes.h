#pragma once
/// \file seed_leg_lanes.h
/// Up to four of the `seed` solver's legs (core/softbody/seed/seed_leg.h) side by side, one per SIMD
/// lane (core/softbody/seed/seed_lanes.h), and kept so from one step to the next: the frog's four legs
/// live here, their constants (lengths, friction, gravity, velmax, floor, §4.15's limits)
/// gathered into lanes once, and are copied back into SeedLeg objects only when read.
/// Annex II steps the legs one after the other; they do not act on each other, so
/// stepping them side by side is exactly stepping each.

#include "core/softbody/seed/seed_lanes.h"
#include "core/softbody/seed/seed_leg.h"

namespace granota {

template <class R> class SeedLegLanes {
public:
    using L = Lanes<R>;
    class Step;

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

/// One step of the legs (Annex II, Pota.actualitza) in its parts, in their order: verlet(),
/// upper(), upperAngle(), lower(), lowerAngle(), floor(), the last writing the state back.
/// step() runs them one after the other; the frog runs them between the parts of its
/// body's next step (SeedBody::stepWith), so that the processor works on the legs'
/// chain of square roots and divisions while it also works on the body's. The operations
/// are the same, in the same order, whatever runs in between.
template <class R> class SeedLegLanes<R>::Step {
public:
    explicit Step(SeedLegLanes& legs)
        : m_legs(legs), m_cx(legs.m_cx), m_cy(legs.m_cy), m_cpx(legs.m_cpx), m_cpy(legs.m_cpy), m_wx(legs.m_wx), m_wy(legs.m_wy),
          m_wpx(legs.m_wpx), m_wpy(legs.m_wpy)
    {
    }

    /// SeedVertex::verlet for both joints.
    void verlet()
    {
        verletJoint(m_cx, m_cy, m_cpx, m_cpy);
        verletJoint(m_wx, m_wy, m_wpx, m_wpy);
    }
    /// §4.14: the shoulder–elbow length.
    void upper() { restoreLength(m_legs.m_mx, m_legs.m_my, m_cx, m_cy, m_cpx, m_cpy, m_legs.m_moll1); }
    /// §4.15: the shoulder–elbow angle.
    void upperAngle()
    {
        if (m_legs.m_components.angleLimits)
            clampAngle(m_legs.m_mx, m_legs.m_my, m_cx, m_cy, 0);
    }
    /// §4.14: the elbow–wrist length.
    void lower() { restoreLength(m_cx, m_cy, m_wx, m_wy, m_wpx, m_wpy, m_legs.m_moll2); }
    /// §4.15: the elbow–wrist angle (measured in the screen's frame, not the elbow's).
    void lowerAngle()
    {
        if (m_legs.m_components.angleLimits)
            clampAngle(m_cx, m_cy, m_wx, m_wy, 2);
    }
    /// "Corregim la posicio del canell si se n'ix del marc", then the state back into the legs.
    void floor();
    /// Part 0 … 5 of the list above (SeedBody::stepWith's interface).
    void run(int part)
    {
        switch (part) {
        case 0: verlet(); break;
        case 1: upper(); break;
        case 2: upperAngle(); break;
        case 3: lower(); break;
        case 4: lowerAngle(); break;
        default: floor(); break;
        }
    }

private:
    void verletJoint(L& x, L& y, L& px, L& py) const
    {
        const SeedLegLanes& l = m_legs;
        const L nx = x + l.m_fx * (x - px) + l.m_gx;
        const L ny = y + l.m_fy * (y - py) + l.m_gy;
        px = x, py = y;
        x = clampLanes(nx, x - l.m_velmax, x + l.m_velmax);
        y = clampLanes(ny, y - l.m_velmax, y + l.m_velmax);
    }
    /// §4.14 on lanes: joint (x, y) back to distance `length` from (fx, fy) along the line
    /// joining them, moved with Desp (position and previous position: the velocity is
    /// kept). dist() and PVector.normalize measure the same vector: one square root serves
    /// both.
    static void restoreLength(const L& fx, const L& fy, L& x, L& y, L& px, L& py, const L& length)
    {
        L dx = x - fx, dy = y - fy;
        const L m = sqrt(dx * dx + dy * dy);
        const auto moved = ne(m, length);
        // A joint on its parent: d stays 0 and it is put on the parent (finite, as in the seed).
        normalizeLanes(dx, dy, m);
        const L movx = fx + dx * length - x, movy = fy + dy * length - y;
        if (moved.all()) { // the usual case: no lane needs a mask
            px = px + movx, py = py + movy;
            x = x + movx, y = y + movy;
            return;
        }
        px = select(moved, px + movx, px), py = select(moved, py + movy, py);
        x = select(moved, x + movx, x), y = select(moved, y + movy, y);
    }
    /// §4.15: the angle of parent→joint measured from straight down, acos(Δy/|Δ|), taken
    /// positive when the joint is left of its parent and negative when right of it; past
    /// [min, max] the joint is put on the limit. `a > max` is `ratio <= T`
    /// (largestRatioAbove in seed_leg.cpp) and −a < min is a > −min. Guard: a zero length
    /// gives 0/0 — NaN in the seed, whose comparisons are then false and leave the joint
    /// alone; the mask `len > 0` does the same. The ratio is clamped to [−1, 1] as acos
    /// would need.
    void clampAngle(const L& fx, const L& fy, L& x, L& y, int maxIndex) const
    {
        const SeedLegLanes& l = m_legs;
        const L zero = L::splat(R(0));
        const L dx = x - fx, dy = y - fy;
        const L len = sqrt(dx * dx + dy * dy);
        const L ratio = clampLanes(dy / len, L::splat(R(-1)), L::splat(R(1)));
        const auto measured = gt(len, zero);
        const auto right = ge(fx - x, zero);
        const auto left = !right;
        const auto pastMax = right & measured & le(ratio, l.m_limitRatio[maxIndex]);
        const auto pastMin = left & measured & le(ratio, l.m_limitRatio[maxIndex + 1]);
        if (!(pastMax.any() || pastMin.any()))
            return;
        x = select(pastMax, fx - l.m_limitOffX[maxIndex], select(pastMin, fx - l.m_limitOffX[maxIndex + 1], x));
        y = select(pastMax, fy + l.m_limitOffY[maxIndex], select(pastMin, fy + l.m_limitOffY[maxIndex + 1], y));
    }

    SeedLegLanes& m_legs;
    L m_cx, m_cy, m_cpx, m_cpy, m_wx, m_wy, m_wpx, m_wpy;
};

template <class R> inline void SeedLegLanes<R>::Step::floor()
{
    // A wrist below the floor is lifted by dy, and the elbow, lifted by the same dy, slides
    // horizontally back onto the circle of radius moll1 round the shoulder:
    // (x − mx)² + (my − (cy − dy))² = moll1², i.e. x² + b x + c = 0 with a = 1, b = −2 mx.
    // Both joints move by the same dx.
    SeedLegLanes& l = m_legs;
    const SeedComponents comp = l.m_components;
    const L zero = L::splat(R(0));
    const L mx = l.m_mx, my = l.m_my, moll1 = l.m_moll1, floor = l.m_floor;
    L cx = m_cx, cy = m_cy, wx = m_wx, wy = m_wy;
    if (comp.bounds) {
        const auto below = gt(wy, floor);
        if (below.any()) {
            // dy = dist(wx, wy, wx, floor), whose x term is (wx − wx)² = 0.
            const L zx = wx - wx, zy = floor - wy;
            const L dy = sqrt(zx * zx + zy * zy);
            const L qb = L::splat(R(-2)) * mx;
            const L lifted = my - (cy - dy);
            const L qc = mx * mx + lifted * lifted - moll1 * moll1;
            L disc = qb * qb - L::splat(R(4)) * qc; // 4·a·c with a = 1
            // Guard: when the lifted elbow is more than moll1 above or below the shoulder
            // the circle has no point at that height and the seed takes sqrt of a negative
            // number, writing NaN into the leg for good. We take the nearest real solution
            // (discriminant 0: the elbow on the vertical through the shoulder).
            disc = select(ge(disc, zero), disc, zero);
            // x = (−b ± √disc)/(2a) with a = 1; halving is exact, so ·0.5 gives the very
            // same bits as /2 (and does not wait for a division).
            const L root = sqrt(disc), half = L::splat(R(0.5f));
            const L noux = select(ge(cx, mx), (-qb + root) * half, (-qb - root) * half);
            const L dx = noux - cx;
            wx = select(below, wx + dx, wx), wy = select(below, wy - dy, wy);
            cx = select(below, cx + dx, cx), cy = select(below, cy - dy, cy);
        }
    }

    // Beyond the seed (SeedComponents::clampLegs): the joints stay in the frame like the
    // body's vertices. Only the current position is clamped, as `fita` does.
    if (comp.clampLegs) {
        cx = clampLanes(cx, zero, l.m_xmax), cy = clampLanes(cy, zero, floor);
        wx = clampLanes(wx, zero, l.m_xmax), wy = clampLanes(wy, zero, floor);
    }

    l.m_cx = cx, l.m_cy = cy, l.m_cpx = m_cpx, l.m_cpy = m_cpy;
    l.m_wx = wx, l.m_wy = wy, l.m_wpx = m_wpx, l.m_wpy = m_wpy;
}

template <class R> inline void SeedLegLanes<R>::step()
{
    // Annex II, Pota.actualitza(mov), one leg per lane. Every branch of the seed becomes a
    // mask. §4.14: shoulder–elbow length, then its angle; elbow–wrist length, then its
    // angle; then the floor.
    Step s(*this);
    s.verlet();
    s.upper();
    s.upperAngle();
    s.lower();
    s.lowerAngle();
    s.floor();
}

extern template class SeedLegLanes<float>;
extern template class SeedLegLanes<double>;

} // namespace granota
