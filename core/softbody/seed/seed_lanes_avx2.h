#pragma once
/// \file seed_lanes_avx2.h
/// Eight floats at once (one 256-bit AVX2 register) for the `seed` solver's body step, used
/// when the processor has AVX2: the frog's eleven vertices fit two packs of eight instead
/// of three packs of four. Every operation is the same correctly rounded IEEE operation as
/// Lanes<float> (core/softbody/seed/seed_lanes.h) does on each lane — compares keep SSE's ordered and
/// unordered predicates, min/max keep SSE's operand order — so the trace is the same to the
/// bit. Only AVX2 is asked for, not FMA: a product and a sum are never fused.
///
/// Every function carries the target attribute, so this code is compiled for AVX2 while
/// the rest of the program is not; SeedBody calls it only after seedWideLanes() said yes.

#include "core/softbody/seed/seed_lanes.h"

#include <atomic>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define GRANOTA_SEED_AVX2 1
#define GRANOTA_AVX2_TARGET __attribute__((target("avx2")))
#include <immintrin.h>
#endif

namespace granota {

namespace detail {
extern const bool g_seedAvx2;               ///< the processor has AVX2 (asked once, at start-up)
extern std::atomic<bool> g_seedWideAllowed; ///< setSeedWideLanesAllowed
} // namespace detail

/// Whether the body step may use eight lanes: the processor has AVX2 and
/// setSeedWideLanesAllowed(false) was not called. Asked at every step: two loads.
inline bool seedWideLanes() { return detail::g_seedAvx2 && detail::g_seedWideAllowed.load(std::memory_order_relaxed); }
/// Tests use this to run the four-lane step on a machine with AVX2 (both must give the
/// same trace). Not thread-safe against a step running at the same time.
void setSeedWideLanesAllowed(bool allowed);

#ifdef GRANOTA_SEED_AVX2

template <class R> struct Lanes8; // only Lanes8<float>

struct LaneMask8 {
    __m256 m;
    GRANOTA_AVX2_TARGET friend LaneMask8 operator&(const LaneMask8& p, const LaneMask8& q) { return {_mm256_and_ps(p.m, q.m)}; }
    GRANOTA_AVX2_TARGET friend LaneMask8 operator!(const LaneMask8& p)
    {
        return {_mm256_xor_ps(p.m, _mm256_castsi256_ps(_mm256_set1_epi32(-1)))};
    }
    GRANOTA_AVX2_TARGET bool any() const { return _mm256_movemask_ps(m) != 0; }
    GRANOTA_AVX2_TARGET bool all() const { return _mm256_movemask_ps(m) == 0xff; }
};

template <> struct Lanes8<float> {
    static constexpr int kWidth = 8;
    __m256 v;

    GRANOTA_AVX2_TARGET static Lanes8 load(const float* p) { return {_mm256_loadu_ps(p)}; }
    GRANOTA_AVX2_TARGET static Lanes8 splat(float a) { return {_mm256_set1_ps(a)}; }
    /// (0, 1, …, 7)
    GRANOTA_AVX2_TARGET static Lanes8 iota() { return {_mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7)}; }
    GRANOTA_AVX2_TARGET void store(float* p) const { _mm256_storeu_ps(p, v); }

    GRANOTA_AVX2_TARGET friend Lanes8 operator+(const Lanes8& a, const Lanes8& b) { return {_mm256_add_ps(a.v, b.v)}; }
    GRANOTA_AVX2_TARGET friend Lanes8 operator-(const Lanes8& a, const Lanes8& b) { return {_mm256_sub_ps(a.v, b.v)}; }
    GRANOTA_AVX2_TARGET friend Lanes8 operator*(const Lanes8& a, const Lanes8& b) { return {_mm256_mul_ps(a.v, b.v)}; }
    GRANOTA_AVX2_TARGET friend Lanes8 operator/(const Lanes8& a, const Lanes8& b) { return {_mm256_div_ps(a.v, b.v)}; }
    // SSE's cmpltps, cmpleps, cmpgtps, cmpgeps are ordered; cmpneqps is unordered (true
    // for NaN); cmpeqps is ordered.
    GRANOTA_AVX2_TARGET friend LaneMask8 lt(const Lanes8& a, const Lanes8& b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LT_OS)}; }
    GRANOTA_AVX2_TARGET friend LaneMask8 le(const Lanes8& a, const Lanes8& b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_LE_OS)}; }
    GRANOTA_AVX2_TARGET friend LaneMask8 gt(const Lanes8& a, const Lanes8& b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OS)}; }
    GRANOTA_AVX2_TARGET friend LaneMask8 ge(const Lanes8& a, const Lanes8& b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GE_OS)}; }
    GRANOTA_AVX2_TARGET friend LaneMask8 ne(const Lanes8& a, const Lanes8& b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_NEQ_UQ)}; }
    GRANOTA_AVX2_TARGET friend LaneMask8 eq(const Lanes8& a, const Lanes8& b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_EQ_OQ)}; }
    GRANOTA_AVX2_TARGET friend Lanes8 operator-(const Lanes8& a) { return {_mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f))}; }
    GRANOTA_AVX2_TARGET friend Lanes8 sqrt(const Lanes8& a) { return {_mm256_sqrt_ps(a.v)}; }
    GRANOTA_AVX2_TARGET friend Lanes8 select(const LaneMask8& m, const Lanes8& a, const Lanes8& b)
    {
        return {_mm256_or_ps(_mm256_and_ps(m.m, a.v), _mm256_andnot_ps(m.m, b.v))};
    }
    GRANOTA_AVX2_TARGET friend Lanes8 zeroUnless(const LaneMask8& m, const Lanes8& a) { return {_mm256_and_ps(m.m, a.v)}; }
    /// (a1, …, a7, b0), as Lanes::nextLanes.
    GRANOTA_AVX2_TARGET friend Lanes8 nextLanes(const Lanes8& a, const Lanes8& b)
    {
        const __m256 t = _mm256_permute2f128_ps(a.v, b.v, 0x21); // (a4 … a7, b0 … b3)
        return {_mm256_castsi256_ps(_mm256_alignr_epi8(_mm256_castps_si256(t), _mm256_castps_si256(a.v), 4))};
    }
    /// (a7, b0, …, b6), as Lanes::previousLanes.
    GRANOTA_AVX2_TARGET friend Lanes8 previousLanes(const Lanes8& a, const Lanes8& b)
    {
        const __m256 t = _mm256_permute2f128_ps(a.v, b.v, 0x21); // (a4 … a7, b0 … b3)
        return {_mm256_castsi256_ps(_mm256_alignr_epi8(_mm256_castps_si256(b.v), _mm256_castps_si256(t), 12))};
    }
    /// clampLanes of seed_lanes.h: maxps(lo, minps(hi, p)).
    GRANOTA_AVX2_TARGET friend Lanes8 clampLanes(const Lanes8& p, const Lanes8& lo, const Lanes8& hi)
    {
        return {_mm256_max_ps(lo.v, _mm256_min_ps(hi.v, p.v))};
    }
    /// normalizeLanes of seed_lanes.h.
    GRANOTA_AVX2_TARGET friend void normalizeLanes(Lanes8& x, Lanes8& y, const Lanes8& m)
    {
        const Lanes8 d = m + zeroUnless(eq(m, splat(0.0f)), splat(1.0f));
        x = x / d;
        y = y / d;
    }
};

#endif

} // namespace granota
