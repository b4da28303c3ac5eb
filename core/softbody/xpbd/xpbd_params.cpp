#include "core/softbody/xpbd/xpbd_params.h"
#include "core/base/math_constants.h"

#include <cmath>
#include <string>

namespace granota {

XpbdParams xpbdParamsFrom(const FrogParams& frog)
{
    XpbdParams p;
    p.gravity = frog.gravity;
    p.damping = frog.friction;
    p.velmax = frog.velmax;
    p.width = frog.width;
    p.height = frog.height;
    return p;
}

double complianceForPeriod(double periodSteps, double mass)
{
    const double omega = 2 * kPi / periodSteps;
    return 1.0 / (mass * omega * omega);
}

namespace {

Error bad(const std::string& what) { return makeError(ErrorCode::OutOfRange, what); }

bool finiteNonNegative(double v) { return std::isfinite(v) && v >= 0; }

} // namespace

Expected<XpbdParams> validateXpbdParams(const XpbdParams& p)
{
    if (!isFinite(p.gravity))
        return bad("gravity must be a finite vector");
    if (!(p.damping.x >= 0 && p.damping.x <= 1 && p.damping.y >= 0 && p.damping.y <= 1))
        return bad("friction (velocity kept per step) must lie in [0, 1]");
    if (p.substeps < 1 || p.substeps > 1000)
        return bad("substeps must lie between 1 and 1000");
    if (!(std::isfinite(p.dt) && p.dt > 0))
        return bad("the time step must be positive and finite");
    if (!finiteNonNegative(p.edgeCompliance) || !finiteNonNegative(p.areaCompliance) || !finiteNonNegative(p.bendCompliance) ||
        !finiteNonNegative(p.linkCompliance) || !finiteNonNegative(p.grabCompliance))
        return bad("compliances must be finite and not negative (0 = infinitely stiff)");
    if (!finiteNonNegative(p.edgeDampingRatio))
        return bad("the edges' damping ratio must be finite and not negative");
    if (!(std::isfinite(p.width) && p.width >= 1 && std::isfinite(p.height) && p.height >= 1))
        return bad("the frame must be at least 1 px wide and 1 px high, and finite");
    if (!(p.restitution >= 0 && p.restitution <= 1))
        return bad("restitution must lie in [0, 1]");
    if (!finiteNonNegative(p.wallFriction) || !finiteNonNegative(p.contactFriction))
        return bad("friction coefficients must be finite and not negative");
    if (!(p.velmax > 0)) // +inf is allowed: no clamp
        return bad("velmax must be positive (infinity turns the clamp off)");
    if (!finiteNonNegative(p.contactMargin))
        return bad("the contact margin must be finite and not negative");
    if (!(p.grabMaxForce > 0)) // +inf is allowed: no cap
        return bad("the largest grab force must be positive");
    if (!(p.recoveryRate > 0 && p.recoveryRate <= 1))
        return bad("the recovery rate must lie in (0, 1]");
    return p;
}

} // namespace granota
