#include "core/softbody/scenes/stable_settings.h"

#include "core/base/number_format.h"

namespace granota {

bool setStableKnob(StableSettings& s, const std::string& key, double value)
{
    if (key == "substeps" && StableSettings::validSubsteps(value))
        s.substeps = static_cast<int>(value);
    else if (key == "edge_compliance" && StableSettings::validEdgeCompliance(value))
        s.edgeCompliance = value;
    else if (key == "edge_damping_ratio" && StableSettings::validEdgeDampingRatio(value))
        s.edgeDampingRatio = value;
    else
        return false;
    return true;
}

const std::vector<std::string>& stableKnobKeys()
{
    static const std::vector<std::string> keys{"substeps", "edge_compliance", "edge_damping_ratio"};
    return keys;
}

std::string stableKnobRange(const std::string& key)
{
    if (key == "substeps")
        return "a whole number from " + std::to_string(StableSettings::kMinSubsteps) + " to " +
               std::to_string(StableSettings::kMaxSubsteps);
    if (key == "edge_compliance")
        return "a number from 0 (rigid edges) to " + formatDouble(StableSettings::kMaxEdgeCompliance);
    if (key == "edge_damping_ratio")
        return "a number from 0 (no damping) to " + formatDouble(StableSettings::kMaxEdgeDampingRatio);
    return "one of substeps, edge_compliance, edge_damping_ratio";
}

double edgeRingHertz(double edgeCompliance, double restLength, double mass, double stepsPerSecond)
{
    const double period = edgeRingPeriodSteps(edgeCompliance, restLength, mass);
    return std::isfinite(period) ? stepsPerSecond / period : 0.0;
}

double edgeComplianceForHertz(double hertz, double restLength, double mass, double stepsPerSecond)
{
    // T = 2π √(α L m) steps = stepsPerSecond / f: α = (stepsPerSecond / (2π f))² / (L m).
    const double period = stepsPerSecond / hertz;
    return period * period / (4 * kPi * kPi * restLength * mass);
}

} // namespace granota
