#pragma once
/// \file seed_angle.h
/// Angles as Annex II measures them (§4.15): a direction's angle from straight down the
/// screen (y grows downwards), growing towards −x, so that a joint at angle θ from its parent
/// sits at parent + (−sin θ, cos θ)·L (Annex II l. 467). Both solvers' limits, the phase plot
/// and the Frog tab's protractor use it.

#include "core/base/vec2.h"

#include <cmath>

namespace granota {

/// The seed's angle of a direction: 0 = straight down, π/2 = −x.
inline double seedAngle(const Point& d) { return std::atan2(-d.x, d.y); }

/// The unit direction of seed angle a: (−sin a, cos a).
inline Point seedDirection(double a) { return {-std::sin(a), std::cos(a)}; }

/// The angle of the link from `from` to `to`, in (−π, π].
inline double linkAngle(Point from, Point to) { return seedAngle(to - from); }

/// Wraps an angle into (−π, π].
double wrapAngle(double a);

} // namespace granota
