#pragma once
/// \file stable_settings.h
/// The stable solver's own knobs that a scene may set (docs/solvers.md, "Knobs"): how many
/// substeps a step makes, how stiff the body's edges are, as an XPBD compliance (or the
/// frequency it makes an edge ring at), and how damped, as a damping ratio (Box2D's soft
/// constraints). The seed ignores them (Annex II has none). A scene file holds them as
/// `"stable": {"substeps": n, "edge_compliance": α, "edge_damping_ratio": ζ}`, written only
/// when they differ from these defaults, which are XpbdParams' own
/// (core/softbody/xpbd/xpbd_params.h).

#include "core/base/enum_names.h"
#include "core/base/math_constants.h"

#include <array>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace granota {

struct StableSettings {
    /// n, substeps per step, 1 … kMaxSubsteps; the error of a step falls like 1/n².
    int substeps = 8;
    /// α of an edge per px of its rest length, step²/mass, in [0, kMaxEdgeCompliance]
    /// (0 = rigid edges).
    double edgeCompliance = 2e-3;
    /// ζ, each edge's damping ratio: a dashpot along it of 2ζ √(k m) (k = 1/(α L), m the
    /// edge's reduced mass), in [0, kMaxEdgeDampingRatio]: 0 none (the default), 1 critical.
    double edgeDampingRatio = 0;

    static constexpr int kMinSubsteps = 1;
    static constexpr int kMaxSubsteps = 32;
    static constexpr double kMaxEdgeCompliance = 1;
    static constexpr double kMaxEdgeDampingRatio = 2;

    /// A whole number of substeps in [kMinSubsteps, kMaxSubsteps]; a compliance in
    /// [0, kMaxEdgeCompliance]; a damping ratio in [0, kMaxEdgeDampingRatio].
    static bool validSubsteps(double n) { return n >= kMinSubsteps && n <= kMaxSubsteps && std::floor(n) == n; }
    static bool validEdgeCompliance(double a) { return a >= 0 && a <= kMaxEdgeCompliance; }
    static bool validEdgeDampingRatio(double z) { return z >= 0 && z <= kMaxEdgeDampingRatio; }
    bool valid() const
    {
        return validSubsteps(substeps) && validEdgeCompliance(edgeCompliance) && validEdgeDampingRatio(edgeDampingRatio);
    }

    bool isDefault() const { return *this == StableSettings{}; }
    bool operator==(const StableSettings& o) const
    {
        return substeps == o.substeps && edgeCompliance == o.edgeCompliance && edgeDampingRatio == o.edgeDampingRatio;
    }
    bool operator!=(const StableSettings& o) const { return !(*this == o); }
};

/// The period, in steps, at which a vertex of mass `mass` on an edge of rest length `restLength`
/// px with compliance `edgeCompliance` per px rings on its own: T = 2π √(α L m) (α L is the
/// edge's compliance, its stiffness k = 1/(α L)). Infinite for α = 0 (a rigid edge does not ring).
inline double edgeRingPeriodSteps(double edgeCompliance, double restLength, double mass)
{
    const double k = edgeCompliance * restLength * mass;
    return k > 0 ? 2 * kPi * std::sqrt(k) : std::numeric_limits<double>::infinity();
}

/// The knobs, and their names: the scene file's "stable" keys, --set's and a recording's knob
/// events (recorded_run.h), the one list of them.
enum class StableKnob { Substeps, EdgeCompliance, EdgeDampingRatio };
inline constexpr std::array<EnumName<StableKnob>, 3> kStableKnobNames{{
    {StableKnob::Substeps, "substeps"},
    {StableKnob::EdgeCompliance, "edge_compliance"},
    {StableKnob::EdgeDampingRatio, "edge_damping_ratio"},
}};
constexpr std::string_view stableKnobName(StableKnob k) { return nameOf(kStableKnobNames, k); }

/// Knob `k` set to `value` in `s`, or false (and `s` as it was) for a value out of its range.
bool setStableKnob(StableSettings& s, StableKnob k, double value);
/// The same by the knob's name; an unknown name is false too.
bool setStableKnob(StableSettings& s, const std::string& key, double value);
/// "substeps", "edge_compliance", "edge_damping_ratio".
const std::vector<std::string>& stableKnobKeys();
/// What `key` takes, for messages: "a whole number from 1 to 32", "a number from 0 (rigid
/// edges) to 1", "a number from 0 (no damping) to 2".
std::string stableKnobRange(const std::string& key);

/// The frequency an edge of rest length `restLength` px rings at, in Hz at `stepsPerSecond`
/// (a vertex of mass `mass` on it, edgeRingPeriodSteps; 0 for a rigid edge, which does not
/// ring), and back: the compliance that makes it ring at `hertz` > 0. The Frog tab states the
/// edges' stiffness either way (Box2D's soft constraints name a frequency).
double edgeRingHertz(double edgeCompliance, double restLength, double mass, double stepsPerSecond);
double edgeComplianceForHertz(double hertz, double restLength, double mass, double stepsPerSecond);

} // namespace granota
