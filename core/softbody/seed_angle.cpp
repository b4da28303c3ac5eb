#include "core/softbody/seed_angle.h"

#include "core/base/math_constants.h"

namespace granota {

double wrapAngle(double a)
{
    // Nearly every angle met in a step is a difference of two angles in (−π, π], so within
    // one turn of the answer: one add instead of std::remainder, which costs as much as a
    // whole constraint projection (it was a fifth of a frog step's time).
    if (a > -kPi && a <= kPi)
        return a;
    if (a > -3 * kPi && a <= 3 * kPi)
        return a > 0 ? a - 2 * kPi : a + 2 * kPi;
    // std::remainder returns a − 2π·k with k the nearest integer: a value in [−π, π].
    const double r = std::remainder(a, 2 * kPi);
    return r <= -kPi ? r + 2 * kPi : r;
}

} // namespace granota
