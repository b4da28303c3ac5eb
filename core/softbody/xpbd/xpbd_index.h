#pragma once
/// \file xpbd_index.h
/// XpbdWorld counts its particles, bodies, edges and chains with int, as scenes do; `at`
/// turns such an index into a vector's position, in one place for the files of the world
/// (building, step, readouts).

#include <cstddef>

namespace granota::xpbd {

inline std::size_t at(int i) { return static_cast<std::size_t>(i); }

} // namespace granota::xpbd
