#include "core/seed_leg.h"

#include "core/seed_lanes.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

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
    l.precomputeLimits();
    return l;
}

namespace {

/// A float or double as a signed integer in the same order as the numbers (−0 and +0 both
/// 0), so that bisection can run over the representable numbers themselves.
template <class R> using OrderedKey = std::conditional_t<sizeof(R) == 4, std::int32_t, std::int64_t>;
template <class R> OrderedKey<R> orderedKey(R r)
{
    OrderedKey<R> bits;
    std::memcpy(&bits, &r, sizeof bits);
    return bits >= 0 ? bits : OrderedKey<R>(-(bits & std::numeric_limits<OrderedKey<R>>::max()));
}
template <class R> R fromOrderedKey(OrderedKey<R> key)
{
    const OrderedKey<R> bits = key >= 0 ? key : OrderedKey<R>((-key) | std::numeric_limits<OrderedKey<R>>::min());
    R r;
    std::memcpy(&r, &bits, sizeof r);
    return r;
}

/// The seed tests `acos(ratio) > limit` with acos in double rounded to R. That function of
/// the ratio only falls as the ratio grows, so the test holds exactly for the ratios up to
/// some T: found here once by bisection over the numbers of R in [−1, 1], so that the
/// step compares `ratio <= T` — the same answer for every ratio, without an acos.
/// Returns −2 (below every ratio) when no ratio passes.
template <class R> R largestRatioAbove(R limit)
{
    const auto passes = [limit](R ratio) { return seedmath::acos(ratio) > limit; };
    if (!passes(R(-1)))
        return R(-2);
    if (passes(R(1)))
        return R(1);
    OrderedKey<R> lo = orderedKey(R(-1)), hi = orderedKey(R(1)); // passes(lo), !passes(hi)
    while (hi - lo > 1) {
        const OrderedKey<R> mid = lo + (hi - lo) / 2;
        (passes(fromOrderedKey<R>(mid)) ? lo : hi) = mid;
    }
    return fromOrderedKey<R>(lo);
}

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

template <class R> void SeedLeg<R>::precomputeLimits()
{
    // (limit, length) of §4.15's four clamps: a joint past `limit` goes to the parent plus
    // (−sin(limit), cos(limit))·length — constants, so their sines and cosines are too.
    const R limit[4] = {m_angmax1, R(-m_angmin1), m_angmax2, R(-m_angmin2)};
    const R angle[4] = {m_angmax1, m_angmin1, m_angmax2, m_angmin2};
    const R length[4] = {m_moll1, m_moll1, m_moll2, m_moll2};
    for (int k = 0; k < 4; ++k) {
        m_limitRatio[k] = largestRatioAbove(limit[k]);
        m_limitOffX[k] = R(seedmath::sin(angle[k]) * length[k]);
        m_limitOffY[k] = R(seedmath::cos(angle[k]) * length[k]);
    }
}

template <class R> void SeedLeg<R>::moveShoulder(const Point& shoulder)
{
    // A non-finite shoulder is ignored (the leg keeps the last one); float(double(x)) == x,
    // so the frog passing its float shoulders through Point loses nothing.
    if (std::isfinite(shoulder.x)) m_muscle.x = R(std::clamp(shoulder.x, -1e15, 1e15));
    if (std::isfinite(shoulder.y)) m_muscle.y = R(std::clamp(shoulder.y, -1e15, 1e15));
}

template <class R> void SeedLeg<R>::step(const Point& shoulder)
{
    SeedLeg* self = this;
    stepTogether(&self, &shoulder, 1);
}

template <class R> void SeedLeg<R>::stepTogether(SeedLeg* const* legs, const Point* shoulders, int count)
{
    // Annex II, Pota.actualitza(mov), one leg per lane. Every branch of the seed becomes a
    // mask; lanes past `count` repeat leg 0 and are not written back.
    using L = Lanes<R>;
    constexpr int W = kSeedLanes;
    count = std::clamp(count, 0, W);
    if (count == 0)
        return;
    for (int k = 0; k < count; ++k)
        legs[k]->moveShoulder(shoulders[k]);
    const SeedLeg* in[W];
    for (int k = 0; k < W; ++k)
        in[k] = legs[k < count ? k : 0];
    static_assert(W == 4, "one leg per lane: the frog's four legs");
    const auto gather = [&in](auto field) { return L::set(field(*in[0]), field(*in[1]), field(*in[2]), field(*in[3])); };
    const SeedComponents comp = in[0]->m_components;
    L mx = gather([](const SeedLeg& l) { return l.m_muscle.x; });
    L my = gather([](const SeedLeg& l) { return l.m_muscle.y; });
    L cx = gather([](const SeedLeg& l) { return l.m_colze.pos.x; });
    L cy = gather([](const SeedLeg& l) { return l.m_colze.pos.y; });
    L cpx = gather([](const SeedLeg& l) { return l.m_colze.prev.x; });
    L cpy = gather([](const SeedLeg& l) { return l.m_colze.prev.y; });
    L wx = gather([](const SeedLeg& l) { return l.m_canell.pos.x; });
    L wy = gather([](const SeedLeg& l) { return l.m_canell.pos.y; });
    L wpx = gather([](const SeedLeg& l) { return l.m_canell.prev.x; });
    L wpy = gather([](const SeedLeg& l) { return l.m_canell.prev.y; });
    const L moll1 = gather([](const SeedLeg& l) { return l.m_moll1; });
    const L moll2 = gather([](const SeedLeg& l) { return l.m_moll2; });
    const L zero = L::splat(R(0));

    {
        const L fx = gather([](const SeedLeg& l) { return l.m_freg.x; });
        const L fy = gather([](const SeedLeg& l) { return l.m_freg.y; });
        const L gx = comp.gravity ? gather([](const SeedLeg& l) { return l.m_grav.x; }) : zero;
        const L gy = comp.gravity ? gather([](const SeedLeg& l) { return l.m_grav.y; }) : zero;
        const L vmax = gather([](const SeedLeg& l) { return l.m_velmax; });
        verletLanes(cx, cy, cpx, cpy, fx, fy, gx, gy, vmax);
        verletLanes(wx, wy, wpx, wpy, fx, fy, gx, gy, vmax);
    }

    // §4.15: the angle of parent→joint measured from straight down, acos(Δy/|Δ|), taken
    // positive when the joint is left of its parent and negative when right of it; past
    // [min, max] the joint is put on the limit. `a > max` is `ratio <= T` (largestRatioAbove)
    // and −a < min is a > −min. Guard: a zero length gives 0/0 — NaN in the seed, whose
    // comparisons are then false and leave the joint alone; the mask `len > 0` does the
    // same. The ratio is clamped to [−1, 1] as acos would need.
    const auto clampAngle = [&](const L& fx, const L& fy, L& x, L& y, int maxIndex) {
        const L dx = x - fx, dy = y - fy;
        const L len = sqrt(dx * dx + dy * dy);
        const L ratio = clampLanes(dy / len, L::splat(R(-1)), L::splat(R(1)));
        const auto measured = gt(len, zero);
        const auto right = ge(fx - x, zero);
        const L maxRatio = gather([maxIndex](const SeedLeg& l) { return l.m_limitRatio[maxIndex]; });
        const L minRatio = gather([maxIndex](const SeedLeg& l) { return l.m_limitRatio[maxIndex + 1]; });
        const auto left = !right;
        const auto pastMax = right & measured & le(ratio, maxRatio);
        const auto pastMin = left & measured & le(ratio, minRatio);
        if (!(pastMax.any() || pastMin.any()))
            return;
        const auto off = [&](int k, bool offY) {
            return gather([k, offY](const SeedLeg& l) { return offY ? l.m_limitOffY[k] : l.m_limitOffX[k]; });
        };
        x = select(pastMax, fx - off(maxIndex, false), select(pastMin, fx - off(maxIndex + 1, false), x));
        y = select(pastMax, fy + off(maxIndex, true), select(pastMin, fy + off(maxIndex + 1, true), y));
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
    const L floor = gather([](const SeedLeg& l) { return l.m_floor; });
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
            const L root = sqrt(disc), twoA = L::splat(R(2));
            const L noux = select(ge(cx, mx), (-qb + root) / twoA, (-qb - root) / twoA);
            const L dx = noux - cx;
            wx = select(below, wx + dx, wx), wy = select(below, wy - dy, wy);
            cx = select(below, cx + dx, cx), cy = select(below, cy - dy, cy);
        }
    }

    // Beyond the seed (SeedComponents::clampLegs): the joints stay in the frame like the
    // body's vertices. Only the current position is clamped, as `fita` does.
    if (comp.clampLegs) {
        const L xmax = gather([](const SeedLeg& l) { return R(l.m_width - 1); });
        cx = clampLanes(cx, zero, xmax), cy = clampLanes(cy, zero, floor);
        wx = clampLanes(wx, zero, xmax), wy = clampLanes(wy, zero, floor);
    }

    R out[8][W];
    const L* state[8] = {&cx, &cy, &cpx, &cpy, &wx, &wy, &wpx, &wpy};
    for (int f = 0; f < 8; ++f)
        state[f]->store(out[f]);
    for (int k = 0; k < count; ++k) {
        SeedLeg& l = *legs[k];
        l.m_colze.pos = Vec(out[0][k], out[1][k]);
        l.m_colze.prev = Vec(out[2][k], out[3][k]);
        l.m_canell.pos = Vec(out[4][k], out[5][k]);
        l.m_canell.prev = Vec(out[6][k], out[7][k]);
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
