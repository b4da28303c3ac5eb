#pragma once
/// \file xpbd_constraints.h
/// The constraints of the stable solver and their XPBD projections. Each projection is
/// the update of Macklin, Müller and Chentanez 2016 ("XPBD"), eq. 18 and eq. 17:
///
///   Δλ = (−C − α̃ λ) / (Σᵢ wᵢ |∇ᵢC|² + α̃),   Δxᵢ = wᵢ ∇ᵢC Δλ,   α̃ = α / h²,
///
/// with wᵢ the inverse masses and h the substep. As in "Small steps in physics simulation"
/// (Macklin et al. 2019) λ starts at 0 in every substep (the caller resets it) and
/// accumulates over the passes of that substep (one for bodies, a few for rigid chains), so
/// λ/h² is the constraint's force in the last substep.
///
/// Everything works on flat arrays (positions `x`, inverse masses `w`) with no virtual call
/// or allocation: these run thousands of times per step.

#include "core/base/vec2.h"
#include "core/softbody/polygon_geometry.h" // signedArea
#include "core/softbody/seed_angle.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace granota {

/// Which compliance of XpbdParams a constraint uses.
enum class ConstraintKind : std::uint8_t {
    Edge,    ///< an edge of a body: edgeCompliance × rest length
    Link,    ///< a link of a chain: linkCompliance
    Bending, ///< the angle between two consecutive edges of a body: bendCompliance
    Rigid,   ///< always α = 0 (angle limits)
};

/// |xa − xb| = rest.
struct DistanceConstraint {
    int a = 0;
    int b = 0;
    double rest = 0;            ///< px
    double complianceScale = 1; ///< α = (compliance of the kind) × this (the rest length for edges)
    ConstraintKind kind = ConstraintKind::Edge;
    double lambda = 0; ///< λ of the last substep; the force is λ/h² (negative when stretched)
};

/// |x_joint − p| = rest with p = (1 − t)·x_a + t·x_b, a point of a body between two of its
/// vertices: the first link of a leg hanging from the frog's shoulder, which Annex II
/// l. 553–563 computes from two vertices. The shoulder is no free particle: it is put on
/// that point, so it sits exactly on the body, and the leg's weight pulls on both vertices.
struct AnchoredDistanceConstraint {
    int joint = 0;
    int a = 0;
    int b = 0;
    double t = 0;
    double rest = 0;
    double lambda = 0;
};

/// The angle of segment b0→b1 measured from segment a0→a1 (or from the downward vertical
/// when a0 < 0), minus `offset`, must lie in [lo, hi] (lo = hi: an equality). Angles follow
/// the seed (Annex II l. 466–491): a direction d has angle atan2(−d.x, d.y), 0 pointing
/// down the screen and growing towards −x.
struct AngleConstraint {
    int a0 = -1;
    int a1 = -1;
    int b0 = 0;
    int b1 = 0;
    double offset = 0; ///< rad
    double lo = 0;     ///< rad, in [−π, π]
    double hi = 0;     ///< rad, in [−π, π]
    ConstraintKind kind = ConstraintKind::Rigid;
    double lambda = 0;
    /// Cache of the cheap "inside the limits" test (filled on first use, refilled when lo,
    /// hi or offset change): the window [lo, hi] as its middle direction (cos, sin of
    /// offset + (lo + hi)/2) and the cosine of its half width.
    double windowLo = std::numeric_limits<double>::quiet_NaN();
    double windowHi = 0;
    double windowOffset = 0;
    double windowCos = 1;
    double windowSin = 0;
    double windowCosHalf = 1;
};

/// ∇ᵢA = ½·perp(xᵢ₊₁ − xᵢ₋₁), perp(d) = (d.y, −d.x): the direction in which Annex II
/// l. 292 pushes a vertex to grow the area, here with its exact length.
inline Point areaGradient(const Point& prev, const Point& next) { return {0.5 * (next.y - prev.y), 0.5 * (prev.x - next.x)}; }

/// One XPBD projection of a distance constraint; returns Δλ.
inline double solveDistance(DistanceConstraint& c, Point* x, const double* w, double alphaTilde)
{
    const double wa = w[c.a];
    const double wb = w[c.b];
    const Point d = x[c.a] - x[c.b];
    const double len = std::sqrt(dot(d, d));
    const double denom = wa + wb + alphaTilde;
    if (len < 1e-12 || denom <= 0) // coincident points: no direction to push along
        return 0;
    const double dLambda = (-(len - c.rest) - alphaTilde * c.lambda) / denom; // eq. 18
    c.lambda += dLambda;
    const Point n((d.x / len) * dLambda, (d.y / len) * dLambda);
    x[c.a] += Point(wa * n.x, wa * n.y);
    x[c.b] -= Point(wb * n.x, wb * n.y);
    return dLambda;
}

/// One averaged-Jacobi XPBD pass over the closed ring of edges e[0..n) of a body (edge k
/// joins vertices k and k + 1): all Δλ from the same positions, each vertex then moved by
/// half the sum of its two corrections (Macklin et al. 2014, §4.2, ω = 1/2). The compliance
/// in the denominator is halved too, so that a soft edge still pulls with −C/α (α̃ of an
/// edge = alphaTildePerLength × its complianceScale). `delta` is scratch, zero on entry and
/// on exit, indexed like x. A damping ratio ζ > 0 adds a dashpot along each soft edge
/// (XPBD's damping, Macklin et al. 2016, eq. 26) of b = 2ζ √(k m), k = 1/α, m = 1/(w_a + w_b),
/// acting on how far the edge has stretched since xPrev (the substep's start); its part of
/// each edge's λ goes to dampingLambda[k] when that is given (kept apart from the
/// constraints, which the step reads every substep, so that they stay as small).
void solveEdgeRing(DistanceConstraint* e, int n, Point* x, const Point* xPrev, const double* w, double alphaTildePerLength,
                   double dampingRatio, double* dampingLambda, Point* delta);
/// What the dashpots of solveEdgeRing took in a substep of length h: each one's force
/// (dampingLambda[k] / h²) times how far its edge stretched from xPrev to x.
double edgeDashpotLoss(const DistanceConstraint* e, const double* dampingLambda, int n, const Point* x, const Point* xPrev,
                       double h);

/// One XPBD projection of the area constraint C = A − target of the polygon x[0..n), in
/// place: gradients are taken at the positions before the update. Returns λ.
double solveArea(Point* x, const double* w, int n, double target, double alphaTilde);

/// One XPBD projection of an anchored distance constraint; returns Δλ.
double solveAnchoredDistance(AnchoredDistanceConstraint& c, Point* x, const double* w, double alphaTilde);

/// One XPBD projection of an angle constraint (inactive inside [lo, hi]); returns Δλ.
double solveAngle(AngleConstraint& c, Point* x, const double* w, double alphaTilde);

/// The bending constraints of a body's ring (constraint k: the turn at vertex k, between
/// edges k−1→k and k→k+1), averaged Jacobi like solveEdgeRing with ω = 1/3, as each vertex
/// takes part in three of them. Over-constrained rings (rigid edges, angles and area) stay
/// calm this way, where Gauss–Seidel pumps energy into them. λ is reset here.
void solveBendingRing(AngleConstraint* a, int n, Point* x, const double* w, double alphaTilde, Point* delta);

/// The constrained angle θ of c, wrapped into (−π, π] (for readouts and tests).
double constraintAngle(const AngleConstraint& c, const Point* x);

} // namespace granota
