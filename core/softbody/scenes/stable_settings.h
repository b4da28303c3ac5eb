#pragma once
/// \file stable_settings.h
/// The stable solver's own knobs that a scene may set (docs/solvers.md, "Knobs"): how many
/// substeps a step makes, and how stiff the body's edges are, as an XPBD compliance. The
/// seed ignores them (Annex II has neither). A scene file holds them as
/// `"stable": {"substeps": n, "edge_compliance": α}`, written only when they differ from
/// these defaults, which are XpbdParams' own (core/softbody/xpbd/xpbd_params.h).

#include "core/base/math_constants.h"

#include <cmath>
#include <limits>

namespace granota {

struct StableSettings {
    /// n, substeps per step, 1 … kMaxSubsteps; the error of a step falls like 1/n².
    int substeps = 8;
    /// α of an edge per px of its rest length, step²/mass, in [0, kMaxEdgeCompliance]
    /// (0 = rigid edges).
    double edgeCompliance = 2e-3;

    static constexpr int kMinSubsteps = 1;
    static constexpr int kMaxSubsteps = 32;
    static constexpr double kMaxEdgeCompliance = 1;

    /// A whole number of substeps in [kMinSubsteps, kMaxSubsteps]; a compliance in [0, kMaxEdgeCompliance].
    static bool validSubsteps(double n) { return n >= kMinSubsteps && n <= kMaxSubsteps && std::floor(n) == n; }
    static bool validEdgeCompliance(double a) { return a >= 0 && a <= kMaxEdgeCompliance; }
    bool valid() const { return validSubsteps(substeps) && validEdgeCompliance(edgeCompliance); }

    bool isDefault() const { return *this == StableSettings{}; }
    bool operator==(const StableSettings& o) const { return substeps == o.substeps && edgeCompliance == o.edgeCompliance; }
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

} // namespace granota
