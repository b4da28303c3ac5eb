#include "core/softbody/seed/seed_lanes_avx2.h"

namespace granota {

namespace detail {
#ifdef GRANOTA_SEED_AVX2
// Zero (four lanes) for a step taken before the start-up constructors have run.
const bool g_seedAvx2 = (__builtin_cpu_init(), __builtin_cpu_supports("avx2"));
#else
const bool g_seedAvx2 = false;
#endif
std::atomic<bool> g_seedWideAllowed{true};
} // namespace detail

void setSeedWideLanesAllowed(bool allowed) { detail::g_seedWideAllowed.store(allowed, std::memory_order_relaxed); }

} // namespace granota
