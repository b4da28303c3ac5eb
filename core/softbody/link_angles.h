#pragma once
/// \file link_angles.h
/// The Frog tab's protractor (§4.15): each link of a chain (a leg, the pendulum) read as
/// its solver measures it, against the limits the solver keeps it in (Simulation::chainLimits).

#include "core/base/math_constants.h"
#include "core/softbody/simulation.h"

#include <optional>
#include <vector>

namespace granota {

struct LinkAngleReading {
    /// rad: the link's seed angle (seed_angle.h) less `reference`, in (−π, π] or, with a
    /// limit, within half a turn of the limit's middle.
    double angle = 0;
    /// rad: the seed angle the link is measured from, 0 (straight down) or the angle of the
    /// link before it (LinkLimit::fromParent).
    double reference = 0;
    /// The limit, when the chain has them.
    std::optional<LinkLimit> limit;
    /// The link sits on an end of its limit (within kAtLimitRadians) or past it.
    bool atLimit = false;
};

/// A quarter of a degree: both solvers put a link that reaches its limit on it, to rounding.
inline constexpr double kAtLimitRadians = kPi / 720;

/// Chain `chain`'s links, first link first; `joints` is scratch (its capacity reused).
void readLinkAngles(const Simulation& sim, int chain, std::vector<Point>& joints, std::vector<LinkAngleReading>& out);

} // namespace granota
