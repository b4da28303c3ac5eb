#include "core/softbody/xpbd/xpbd_chain.h"

#include <cmath>

namespace granota {

ChainAnchor frogLegAnchor(int body, int leg, int sides)
{
    // Annex II: posDreDav = v8 − (v8 − v2)/5, posEsDav = v2 + (v8 − v2)/5,
    // posDreDar = v6 + (v7 − v6)/2, posEsDar = v4 + (v3 − v4)/2.
    static const int a[4] = {2, 2, 6, 4};
    static const int b[4] = {8, 8, 7, 3};
    static const double t[4] = {0.8, 0.2, 0.5, 0.5};
    const int k = leg < 0 ? 0 : (leg > 3 ? 3 : leg);
    const auto scale = [sides](int v) { return static_cast<int>(std::lround(v * sides / 10.0)) % (sides > 0 ? sides : 1); };
    ChainAnchor anchor;
    anchor.body = body;
    anchor.vertexA = scale(a[k]);
    anchor.vertexB = scale(b[k]);
    anchor.t = t[k];
    return anchor;
}

ChainDef frogLegChain(const LegParams& leg, const ChainAnchor& anchor, Point shoulder, double jointMass)
{
    ChainDef def;
    def.anchor = anchor;
    def.joints = {shoulder, shoulder + Point(0, leg.upper), shoulder + Point(0, leg.upper + leg.lower)};
    def.limits = {{leg.shoulderMin, leg.shoulderMax, AngleReference::World}, {leg.elbowMin, leg.elbowMax, AngleReference::World}};
    def.jointMass = jointMass;
    def.pullsBody = false; // §4.16: the legs hang from the body and never act on it
    return def;
}

} // namespace granota
