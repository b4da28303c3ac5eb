#include "core/softbody/scenes/stable_settings.h"

#include "core/base/number_format.h"

namespace granota {

bool setStableKnob(StableSettings& s, StableKnob k, double value)
{
    switch (k) {
    case StableKnob::Substeps:
        if (!StableSettings::validSubsteps(value))
            return false;
        s.substeps = static_cast<int>(value);
        return true;
    case StableKnob::EdgeCompliance:
        if (!StableSettings::validEdgeCompliance(value))
            return false;
        s.edgeCompliance = value;
        return true;
    case StableKnob::EdgeDampingRatio:
        if (!StableSettings::validEdgeDampingRatio(value))
            return false;
        s.edgeDampingRatio = value;
        return true;
    }
    return false;
}

bool setStableKnob(StableSettings& s, const std::string& key, double value)
{
    const std::optional<StableKnob> k = parseName(kStableKnobNames, key);
    return k && setStableKnob(s, *k, value);
}

const std::vector<std::string>& stableKnobKeys()
{
    static const std::vector<std::string> keys = [] {
        std::vector<std::string> out;
        for (const auto& entry : kStableKnobNames)
            out.emplace_back(entry.name);
        return out;
    }();
    return keys;
}

std::string stableKnobRange(const std::string& key)
{
    switch (parseName(kStableKnobNames, key).value_or(StableKnob(-1))) {
    case StableKnob::Substeps:
        return "a whole number from " + std::to_string(StableSettings::kMinSubsteps) + " to " +
               std::to_string(StableSettings::kMaxSubsteps);
    case StableKnob::EdgeCompliance:
        return "a number from 0 (rigid edges) to " + formatDouble(StableSettings::kMaxEdgeCompliance);
    case StableKnob::EdgeDampingRatio:
        return "a number from 0 (no damping) to " + formatDouble(StableSettings::kMaxEdgeDampingRatio);
    }
    std::string names;
    for (const auto& entry : kStableKnobNames)
        names += (names.empty() ? "" : ", ") + std::string(entry.name);
    return "one of " + names;
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
