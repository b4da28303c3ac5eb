#pragma once
/// \file math_constants.h
/// π, written once. C++17 has no std::numbers::pi, and M_PI is POSIX, not C++: every
/// angle of Granota (the regular polygon of §4.1, the legs' angle limits of Annex II, the
/// XPBD angle wrap, the frog's drawing) uses this one double. It is exactly the double
/// that M_PI and the literal 3.14159265358979323846 give, so results do not change.

namespace granota {

/// π rounded to the nearest double.
inline constexpr double kPi = 3.14159265358979323846;

/// The distance from 1 to the next double, 2⁻⁵² (std::numeric_limits<double>::epsilon()).
inline constexpr double kMachineEpsilon = 0x1p-52;

} // namespace granota
