#include "core/seed_leg_lanes.h"

#include <algorithm>

namespace granota {

namespace {

/// SeedVertex::verlet on lanes.
template <class R>
void verletLanes(Lanes<R>& x, Lanes<R>& y, Lanes<R>& px, Lanes<R>& py, const Lanes<R>& fx, const Lanes<R>& fy,
                 const Lanes<R>& gx, const Lanes<R>& gy, const Lanes<R>& vmax)
{
    const Lanes<R> nx = x + fx * (x - px) + gx;
    const Lanes<R> ny = y + fy * (y - py) + gy;
    px = x, py = y;
    x = clampLanes(nx, x - vmax, x + vmax);
    y = clampLanes(ny, y - vmax, y + vmax);
}

/// §4.14 on lanes: joint (x, y) back to distance `length` from (fx, fy) along the line
/// joining them, moved with Desp (position and previous position: the velocity is kept).
/// dist() and PVector.normalize measure the same vector: one square root serves both.
template <class R>
void restoreLengthLanes(const Lanes<R>& fx, const Lanes<R>& fy, Lanes<R>& x, Lanes<R>& y, Lanes<R>& px,
                        Lanes<R>& py, const Lanes<R>& length)
{
    Lanes<R> dx = x - fx, dy = y - fy;
    const Lanes<R> m = sqrt(dx * dx + dy * dy);
    const auto moved = ne(m, length);
    // A joint on its parent: d stays 0 and it is put on the parent (finite, as in the seed).
    normalizeLanes(dx, dy, m);
    const Lanes<R> movx = fx + dx * length - x, movy = fy + dy * length - y;
    px = select(moved, px + movx, px), py = select(moved, py + movy, py);
    x = select(moved, x + movx, x), y = select(moved, y + movy, y);
}

} // namespace

template <class R> SeedLegLanes<R>::SeedLegLanes(const SeedLeg<R>* const* legs, int count)
{
    constexpr int W = kSeedLanes;
    static_assert(W == 4, "one leg per lane: the frog's four legs");
    m_count = std::clamp(count, 1, W);
    const SeedLeg<R>* in[W];
    for (int k = 0; k < W; ++k)
        in[k] = legs[k < m_count ? k : 0];
    const auto gather = [&in](auto field) {
        return L::set(field(*in[0]), field(*in[1]), field(*in[2]), field(*in[3]));
    };
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

template <class R> void SeedLegLanes<R>::step()
{
    // Annex II, Pota.actualitza(mov), one leg per lane. Every branch of the seed becomes a
    // mask. The state is taken into registers and put back at the end.
    const SeedComponents comp = m_components;
    const L mx = m_mx, my = m_my;
    L cx = m_cx, cy = m_cy, cpx = m_cpx, cpy = m_cpy;
    L wx = m_wx, wy = m_wy, wpx = m_wpx, wpy = m_wpy;
    const L moll1 = m_moll1, moll2 = m_moll2;
    const L zero = L::splat(R(0));

    verletLanes(cx, cy, cpx, cpy, m_fx, m_fy, m_gx, m_gy, m_velmax);
    verletLanes(wx, wy, wpx, wpy, m_fx, m_fy, m_gx, m_gy, m_velmax);

    // §4.15: the angle of parent→joint measured from straight down, acos(Δy/|Δ|), taken
    // positive when the joint is left of its parent and negative when right of it; past
    // [min, max] the joint is put on the limit. `a > max` is `ratio <= T` (largestRatioAbove
    // in seed_leg.cpp) and −a < min is a > −min. Guard: a zero length gives 0/0 — NaN in the
    // seed, whose comparisons are then false and leave the joint alone; the mask `len > 0`
    // does the same. The ratio is clamped to [−1, 1] as acos would need.
    const auto clampAngle = [&](const L& fx, const L& fy, L& x, L& y, int maxIndex) {
        const L dx = x - fx, dy = y - fy;
        const L len = sqrt(dx * dx + dy * dy);
        const L ratio = clampLanes(dy / len, L::splat(R(-1)), L::splat(R(1)));
        const auto measured = gt(len, zero);
        const auto right = ge(fx - x, zero);
        const auto left = !right;
        const auto pastMax = right & measured & le(ratio, m_limitRatio[maxIndex]);
        const auto pastMin = left & measured & le(ratio, m_limitRatio[maxIndex + 1]);
        if (!(pastMax.any() || pastMin.any()))
            return;
        x = select(pastMax, fx - m_limitOffX[maxIndex], select(pastMin, fx - m_limitOffX[maxIndex + 1], x));
        y = select(pastMax, fy + m_limitOffY[maxIndex], select(pastMin, fy + m_limitOffY[maxIndex + 1], y));
    };

    // §4.14: shoulder–elbow length, then its angle; elbow–wrist length, then its angle
    // (measured in the screen's frame, not the elbow's).
    restoreLengthLanes(mx, my, cx, cy, cpx, cpy, moll1);
    if (comp.angleLimits)
        clampAngle(mx, my, cx, cy, 0);
    restoreLengthLanes(cx, cy, wx, wy, wpx, wpy, moll2);
    if (comp.angleLimits)
        clampAngle(cx, cy, wx, wy, 2);

    // "Corregim la posicio del canell si se n'ix del marc": a wrist below the floor is
    // lifted by dy, and the elbow, lifted by the same dy, slides horizontally back onto
    // the circle of radius moll1 round the shoulder: (x − mx)² + (my − (cy − dy))² = moll1²,
    // i.e. x² + b x + c = 0 with a = 1, b = −2 mx. Both joints move by the same dx.
    const L floor = m_floor;
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
        cx = clampLanes(cx, zero, m_xmax), cy = clampLanes(cy, zero, floor);
        wx = clampLanes(wx, zero, m_xmax), wy = clampLanes(wy, zero, floor);
    }

    m_cx = cx, m_cy = cy, m_cpx = cpx, m_cpy = cpy;
    m_wx = wx, m_wy = wy, m_wpx = wpx, m_wpy = wpy;
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
