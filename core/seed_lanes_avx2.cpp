#include "core/seed_lanes_avx2.h"

#include <atomic>

namespace granota {

namespace {
std::atomic<bool> g_wideAllowed{true};
}

bool seedWideLanes()
{
#ifdef GRANOTA_SEED_AVX2
    static const bool available = __builtin_cpu_supports("avx2");
    return available && g_wideAllowed.load(std::memory_order_relaxed);
#else
    return false;
#endif
}

void setSeedWideLanesAllowed(bool allowed) { g_wideAllowed.store(allowed, std::memory_order_relaxed); }

} // namespace granota
