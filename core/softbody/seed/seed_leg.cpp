#include "core/softbody/seed/seed_leg.h"

#include "core/softbody/seed/seed_leg_lanes.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>

namespace granota {

template <class R>
Expected<SeedLeg<R>> SeedLeg<R>::create(const FrogParams& params, int index, const Point& shoulder, SeedComponents components)
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
    if (std::isfinite(shoulder.x))
        m_muscle.x = R(std::clamp(shoulder.x, -1e15, 1e15));
    if (std::isfinite(shoulder.y))
        m_muscle.y = R(std::clamp(shoulder.y, -1e15, 1e15));
}

template <class R> void SeedLeg<R>::step(const Point& shoulder)
{
    // One leg in the lanes of SeedLegLanes (the other three repeat it and are dropped).
    moveShoulder(shoulder);
    SeedLeg* self = this;
    SeedLegLanes<R> lanes(&self, 1);
    lanes.step();
    lanes.store(&self);
}

template <class R> std::vector<Point> SeedLeg<R>::joints() const
{
    return {Point(double(m_muscle.x), double(m_muscle.y)), Point(double(m_colze.pos.x), double(m_colze.pos.y)),
            Point(double(m_canell.pos.x), double(m_canell.pos.y))};
}

template class SeedLeg<float>;
template class SeedLeg<double>;

} // namespace granota
