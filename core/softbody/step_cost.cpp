#include "core/softbody/step_cost.h"

namespace granota {

double estimatedStepNanoseconds(const Simulation& s)
{
    std::vector<Point> points;
    double vertices = 0, joints = 0, edgePairs = 0;
    for (int b = 0; b < s.bodyCount(); ++b) {
        s.bodyVertices(b, points);
        const double n = static_cast<double>(points.size());
        vertices += n;
        edgePairs += n * (n - 1) / 2;
    }
    for (int c = 0; c < s.chainCount(); ++c) {
        s.chainJoints(c, points);
        joints += static_cast<double>(points.size());
    }
    if (s.solver() == SolverKind::Seed)
        return kSeedNsPerPoint * (vertices + joints);
    return s.substeps() * (kStableNsPerVertex * vertices + kStableNsPerJoint * joints) + kStableNsPerEdgePair * edgePairs;
}

} // namespace granota
