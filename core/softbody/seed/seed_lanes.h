#pragma once
/// \file seed_lanes.h
/// Four numbers handled at once (SIMD "lanes") for the `seed` solver's hot loops: the
/// vertices of Annex II's body and the four legs of the frog do the same arithmetic side
/// by side, so one instruction can do it for four of them. Every operation is the
/// correctly rounded IEEE operation on each lane — exactly what the scalar code computes —
/// so the seed's single-precision trace is reproduced bit for bit.
///
/// With SSE2 (every x86-64 CPU) `Lanes<float>` is one 128-bit register; any other R or
/// platform uses a plain array of four, which the compiler vectorises as it can.
/// Branches of the seed become masks: both sides are computed and `select` keeps one, so a
/// lane that does not take a branch may compute garbage (0/0, say) that is then dropped.

#include <cmath>
#include <cstring>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define GRANOTA_SEED_SSE2 1
#endif

namespace granota {

/// Lanes per pack.
constexpr int kSeedLanes = 4;

template <class R> struct LaneMask {
    bool b[kSeedLanes];
    friend LaneMask operator&(const LaneMask& p, const LaneMask& q)
    {
        LaneMask m;
        for (int i = 0; i < kSeedLanes; ++i)
            m.b[i] = p.b[i] && q.b[i];
        return m;
    }
    friend LaneMask operator!(const LaneMask& p)
    {
        LaneMask m;
        for (int i = 0; i < kSeedLanes; ++i)
            m.b[i] = !p.b[i];
        return m;
    }
    bool any() const { return b[0] || b[1] || b[2] || b[3]; }
    bool all() const { return b[0] && b[1] && b[2] && b[3]; }
};

/// Four values of R; loads and stores are unaligned (any R* will do).
template <class R> struct Lanes {
    static constexpr int kWidth = kSeedLanes;
    R v[kSeedLanes];

    static Lanes load(const R* p)
    {
        Lanes l;
        std::memcpy(l.v, p, sizeof l.v);
        return l;
    }
    static Lanes splat(R a) { return Lanes{{a, a, a, a}}; }
    static Lanes set(R a, R b, R c, R d) { return Lanes{{a, b, c, d}}; }
    /// (0, 1, 2, 3)
    static Lanes iota() { return set(R(0), R(1), R(2), R(3)); }
    void store(R* p) const { std::memcpy(p, v, sizeof v); }

#define GRANOTA_LANES_OP(op)                                                                                                     \
    friend Lanes operator op(const Lanes& a, const Lanes& b)                                                                     \
    {                                                                                                                            \
        Lanes r;                                                                                                                 \
        for (int i = 0; i < kSeedLanes; ++i)                                                                                     \
            r.v[i] = R(a.v[i] op b.v[i]);                                                                                        \
        return r;                                                                                                                \
    }
    GRANOTA_LANES_OP(+)
    GRANOTA_LANES_OP(-)
    GRANOTA_LANES_OP(*)
    GRANOTA_LANES_OP(/)
#undef GRANOTA_LANES_OP
#define GRANOTA_LANES_CMP(name, op)                                                                                              \
    friend LaneMask<R> name(const Lanes& a, const Lanes& b)                                                                      \
    {                                                                                                                            \
        LaneMask<R> m;                                                                                                           \
        for (int i = 0; i < kSeedLanes; ++i)                                                                                     \
            m.b[i] = a.v[i] op b.v[i];                                                                                           \
        return m;                                                                                                                \
    }
    GRANOTA_LANES_CMP(lt, <)
    GRANOTA_LANES_CMP(le, <=)
    GRANOTA_LANES_CMP(gt, >)
    GRANOTA_LANES_CMP(ge, >=)
    GRANOTA_LANES_CMP(ne, !=)
    GRANOTA_LANES_CMP(eq, ==)
#undef GRANOTA_LANES_CMP
    /// −a: flips the sign bit, exactly as the scalar −a (0 − a would turn −0 into +0).
    friend Lanes operator-(const Lanes& a)
    {
        Lanes r;
        for (int i = 0; i < kSeedLanes; ++i)
            r.v[i] = -a.v[i];
        return r;
    }
    friend Lanes sqrt(const Lanes& a)
    {
        Lanes r;
        for (int i = 0; i < kSeedLanes; ++i)
            r.v[i] = std::sqrt(a.v[i]);
        return r;
    }
    /// m ? a : b, lane by lane.
    friend Lanes select(const LaneMask<R>& m, const Lanes& a, const Lanes& b)
    {
        Lanes r;
        for (int i = 0; i < kSeedLanes; ++i)
            r.v[i] = m.b[i] ? a.v[i] : b.v[i];
        return r;
    }
    /// m ? a : +0, lane by lane.
    friend Lanes zeroUnless(const LaneMask<R>& m, const Lanes& a) { return select(m, a, splat(R(0))); }
    /// (a1, a2, a3, b0): element i + 1 of an array for each lane i of `a`, when b holds
    /// the four elements after a. Built in registers: a load from p + 1 just after stores
    /// to p and p + 4 would wait for the stores to reach the cache.
    friend Lanes nextLanes(const Lanes& a, const Lanes& b) { return Lanes{{a.v[1], a.v[2], a.v[3], b.v[0]}}; }
    /// (a3, b0, b1, b2): element i − 1 for each lane i of b, when a holds the four before.
    friend Lanes previousLanes(const Lanes& a, const Lanes& b) { return Lanes{{a.v[3], b.v[0], b.v[1], b.v[2]}}; }
    /// (b0, a1, a2, a3): a with its first lane taken from b.
    friend Lanes firstLaneFrom(const Lanes& a, const Lanes& b) { return Lanes{{b.v[0], a.v[1], a.v[2], a.v[3]}}; }
};

#ifdef GRANOTA_SEED_SSE2
template <> struct LaneMask<float> {
    __m128 m;
    friend LaneMask operator&(const LaneMask& p, const LaneMask& q) { return {_mm_and_ps(p.m, q.m)}; }
    friend LaneMask operator!(const LaneMask& p) { return {_mm_xor_ps(p.m, _mm_castsi128_ps(_mm_set1_epi32(-1)))}; }
    bool any() const { return _mm_movemask_ps(m) != 0; }
    bool all() const { return _mm_movemask_ps(m) == 0xf; }
};

template <> struct Lanes<float> {
    static constexpr int kWidth = kSeedLanes;
    __m128 v;

    static Lanes load(const float* p) { return {_mm_loadu_ps(p)}; }
    static Lanes splat(float a) { return {_mm_set1_ps(a)}; }
    /// Built in registers: four scalar stores read back as one vector would stall the
    /// store-to-load forwarding of the CPU.
    static Lanes set(float a, float b, float c, float d) { return {_mm_setr_ps(a, b, c, d)}; }
    static Lanes iota() { return set(0, 1, 2, 3); }
    void store(float* p) const { _mm_storeu_ps(p, v); }

    friend Lanes operator+(const Lanes& a, const Lanes& b) { return {_mm_add_ps(a.v, b.v)}; }
    friend Lanes operator-(const Lanes& a, const Lanes& b) { return {_mm_sub_ps(a.v, b.v)}; }
    friend Lanes operator*(const Lanes& a, const Lanes& b) { return {_mm_mul_ps(a.v, b.v)}; }
    friend Lanes operator/(const Lanes& a, const Lanes& b) { return {_mm_div_ps(a.v, b.v)}; }
    friend LaneMask<float> lt(const Lanes& a, const Lanes& b) { return {_mm_cmplt_ps(a.v, b.v)}; }
    friend LaneMask<float> le(const Lanes& a, const Lanes& b) { return {_mm_cmple_ps(a.v, b.v)}; }
    friend LaneMask<float> gt(const Lanes& a, const Lanes& b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
    friend LaneMask<float> ge(const Lanes& a, const Lanes& b) { return {_mm_cmpge_ps(a.v, b.v)}; }
    friend LaneMask<float> ne(const Lanes& a, const Lanes& b) { return {_mm_cmpneq_ps(a.v, b.v)}; }
    friend LaneMask<float> eq(const Lanes& a, const Lanes& b) { return {_mm_cmpeq_ps(a.v, b.v)}; }
    friend Lanes operator-(const Lanes& a) { return {_mm_xor_ps(a.v, _mm_set1_ps(-0.0f))}; }
    friend Lanes sqrt(const Lanes& a) { return {_mm_sqrt_ps(a.v)}; }
    friend Lanes select(const LaneMask<float>& m, const Lanes& a, const Lanes& b)
    {
        return {_mm_or_ps(_mm_and_ps(m.m, a.v), _mm_andnot_ps(m.m, b.v))};
    }
    friend Lanes zeroUnless(const LaneMask<float>& m, const Lanes& a) { return {_mm_and_ps(m.m, a.v)}; }
    friend Lanes nextLanes(const Lanes& a, const Lanes& b)
    {
        const __m128 t = _mm_move_ss(a.v, b.v); // (b0, a1, a2, a3)
        return {_mm_shuffle_ps(t, t, _MM_SHUFFLE(0, 3, 2, 1))};
    }
    friend Lanes previousLanes(const Lanes& a, const Lanes& b)
    {
        const __m128 t = _mm_shuffle_ps(a.v, b.v, _MM_SHUFFLE(0, 0, 3, 3)); // (a3, a3, b0, b0)
        return {_mm_shuffle_ps(t, b.v, _MM_SHUFFLE(2, 1, 2, 0))};
    }
    friend Lanes firstLaneFrom(const Lanes& a, const Lanes& b) { return {_mm_move_ss(a.v, b.v)}; }
};
#endif

/// Annex II's clamp `if (p < lo) p = lo; else if (p > hi) p = hi;`, lane by lane, for
/// lo <= hi (every clamp of the seed: a value ± velmax, ±velmax, the frame, [−1, 1]).
template <class R> Lanes<R> clampLanes(const Lanes<R>& p, const Lanes<R>& lo, const Lanes<R>& hi)
{
    return select(lt(p, lo), lo, select(gt(p, hi), hi, p));
}

#ifdef GRANOTA_SEED_SSE2
/// The same clamp as minps/maxps, two instructions instead of eight. minps(hi, p) is
/// `hi < p ? hi : p`, the inner branch exactly (a NaN p stays p); maxps(lo, q) is
/// `lo > q ? lo : q`, which with lo <= hi is true exactly when p < lo (then q = p).
template <> inline Lanes<float> clampLanes(const Lanes<float>& p, const Lanes<float>& lo, const Lanes<float>& hi)
{
    return {_mm_max_ps(lo.v, _mm_min_ps(hi.v, p.v))};
}
#endif

/// PVector.normalize on lanes: (x, y) divided by m = |(x, y)| unless m is 0 or 1. `m` is
/// passed in because the seed often needs the length itself as well. x/1 is x exactly, so
/// only m = 0 needs care: there the divisor is made 1 (m + 1 = 1), elsewhere m + 0 = m.
template <class R> void normalizeLanes(Lanes<R>& x, Lanes<R>& y, const Lanes<R>& m)
{
    const Lanes<R> d = m + zeroUnless(eq(m, Lanes<R>::splat(R(0))), Lanes<R>::splat(R(1)));
    x = x / d;
    y = y / d;
}

} // namespace granota
