#include "core/softbody/link_angles.h"

#include "core/softbody/seed_angle.h"

namespace granota {

void readLinkAngles(const Simulation& sim, int chain, std::vector<Point>& joints, std::vector<LinkAngleReading>& out)
{
    out.clear();
    sim.chainJoints(chain, joints);
    thread_local std::vector<LinkLimit> limits; // its capacity reused: no allocation a frame
    sim.chainLimits(chain, limits);
    for (std::size_t k = 0; k + 1 < joints.size(); ++k) {
        LinkAngleReading r;
        if (k < limits.size())
            r.limit = limits[k];
        if (r.limit && r.limit->fromParent && k > 0)
            r.reference = linkAngle(joints[k - 1], joints[k]);
        r.angle = wrapAngle(linkAngle(joints[k], joints[k + 1]) - r.reference);
        if (r.limit) {
            // The turn nearest the limit's middle: a link a hair past a limit at ±π reads
            // just past it, not a whole turn away.
            const double mid = 0.5 * (r.limit->min + r.limit->max);
            r.angle = mid + wrapAngle(r.angle - mid);
            r.atLimit = !(r.angle > r.limit->min + kAtLimitRadians && r.angle < r.limit->max - kAtLimitRadians);
        }
        out.push_back(r);
    }
}

} // namespace granota
