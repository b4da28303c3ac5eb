#pragma once
/// \file xpbd_params.h
/// The parameters of the `stable` solver (XpbdWorld), with the units of the seed: pixels
/// and steps (one step is one frame, one call of Annex II's `actualitza()`), masses in
/// "vertex units" (a vertex of the seed's 10-vertex frog weighs 1).
///
/// Stiffness is given as compliance α, the inverse of a stiffness (Macklin, Müller and
/// Chentanez 2016, "XPBD", §3): α = 0 is an infinitely stiff (rigid) constraint and a
/// larger α a softer one. Unlike the seed's correction factors (C = reescala, "5 passes")
/// the result does not depend on the number of substeps or of vertices: it is a physical
/// stiffness. `complianceForPeriod` turns an oscillation period into a compliance.

#include "core/base/expected.h"
#include "core/softbody/scenes/frog_params.h"
#include "core/softbody/scenes/grab_mode.h"
#include "core/softbody/scenes/stable_settings.h"
#include "core/base/vec2.h"

#include <limits>

namespace granota {

struct XpbdParams {
    /// g, acceleration, px/step² (gravetat).
    Point gravity = FrogParams{}.gravity;
    /// f, share of the velocity kept per step, per axis, in [0, 1] (fregament); a substep of
    /// length h keeps f^h.
    Point damping = FrogParams{}.friction;
    /// n, substeps per step; the error of a step falls like 1/n² (Macklin et al. 2019).
    int substeps = StableSettings{}.substeps;
    /// Length of one step, in frames (the seed's unit); > 1 = large steps.
    double dt = 1;
    /// α of an edge per px of its rest length, step²/mass (0 = rigid edges).
    double edgeCompliance = StableSettings{}.edgeCompliance;
    /// ζ, the damping ratio of a dashpot along each edge (0 = none; solveEdgeRing).
    double edgeDampingRatio = StableSettings{}.edgeDampingRatio;
    /// α of a body's area constraint, step²/(mass·px²) (0 = incompressible, §4.5).
    double areaCompliance = 0;
    /// α of the turn between consecutive edges of a body with bending on, step²/(mass·px²)
    /// (§5.2.3).
    double bendCompliance = 5e-4;
    /// α of a chain link, step²/mass (0 = rigid, as the legs of §4.13).
    double linkCompliance = 0;
    /// Frame width, px; positions stay in [0, width − 1].
    double width = FrogParams{}.width;
    /// Frame height, px; positions stay in [0, height − 1].
    double height = FrogParams{}.height;
    /// e, share of a vertex's normal speed kept when it hits a wall or obstacle, [0, 1] (§4.3).
    double restitution = 0;
    /// μ, Coulomb friction at walls and obstacles (≥ 0).
    double wallFriction = 0.6;
    /// μ, Coulomb friction between bodies (≥ 0).
    double contactFriction = 0.4;
    /// velmax, largest speed per axis, px/step; infinity = no clamp.
    double velmax = FrogParams{}.velmax;
    /// Skin, px: vertices closer than this to a body or obstacle are pushed out to it.
    double contactMargin = 0;
    /// Which vertices follow the mouse.
    GrabMode grabMode = GrabMode::Above;
    /// α of each mouse tie, step²/mass.
    double grabCompliance = 0.02;
    /// Largest pull of one mouse tie, mass·px/step² (infinity = no cap).
    double grabMaxForce = 30;
    /// Share of the way to the shape-matching goal per substep while a body is invalid, (0, 1].
    double recoveryRate = 0.15;
};

/// The stable solver's parameters for the frog's constants: gravity, friction (as damping),
/// velmax and the frame come from FrogParams; stiffness and contact parameters keep their
/// defaults. `xpbdParamsFrom(FrogParams{})` equals `XpbdParams{}`.
XpbdParams xpbdParamsFrom(const FrogParams& frog);

/// The compliance that makes a particle of mass `mass` on a constraint oscillate with a
/// period of `periodSteps` steps: α = 1/(m ω²), ω = 2π/T (a spring k = m ω²).
double complianceForPeriod(double periodSteps, double mass);

/// Rejects parameters that make no sense (negative compliance, frame ≤ 0, NaN, …) with a
/// message naming the parameter; returns them unchanged otherwise.
Expected<XpbdParams> validateXpbdParams(const XpbdParams& params);

} // namespace granota
