#pragma once
/// \file kochanek_bartels.h
/// Kochanek–Bartels (TCB) splines: Def 2.8's Hermite segments with tangents set by three
/// numbers per point — tension T, continuity C and bias B (D. Kochanek and R. Bartels,
/// "Interpolating splines with local tension, continuity, and bias control", SIGGRAPH 1984).
///
/// With Δ₋ = P_i − P_{i−1} and Δ₊ = P_{i+1} − P_i, point P_i has two tangents:
///     in_i  = (1−T)/2 · [ (1+B)(1−C) Δ₋ + (1−B)(1+C) Δ₊ ]   (ending the segment into P_i)
///     out_i = (1−T)/2 · [ (1+B)(1+C) Δ₋ + (1−B)(1−C) Δ₊ ]   (starting the segment out of P_i)
/// and segment i is the Hermite segment (P_i, P_{i+1}, out_i, in_{i+1}). So:
///  - T, C, B = 0 is Catmull-Rom with τ = 1/2 (both tangents (Δ₋ + Δ₊)/2 = (P_{i+1} − P_{i−1})/2),
///    and T alone is τ = (1 − T)/2 (the cardinal spline, cardinal_spline.h); T = 1 zero tangents.
///  - C ≠ 0 makes in_i ≠ out_i: the curve is no longer C¹ there (Prop 2.3 fails); C = −1 gives
///    each segment its own chord at both ends (in_i ∝ Δ₋, out_i ∝ Δ₊: corners).
///  - B > 0 leans both tangents towards Δ₋ (overshoot after P_i), B < 0 towards Δ₊.
/// The ends follow Def 2.10 as Catmull-Rom does (catmull_rom.h): open repeats the end points
/// (Δ₋ = 0 at P_0, Δ₊ = 0 at P_n), cyclic and closed wrap around.
///
/// Non-uniform parameters (α > 0): segment i covers h_i = |P_{i+1} − P_i|^α of the global
/// parameter (catmullRomIntervals() gives the same h_i). The paper's adjustment for unequal
/// parameter steps (§5 of the paper, also VTK's vtkKochanekSpline) scales the tangents at an
/// interior point P_i by
///     in_i · 2h_{i−1}/(h_{i−1} + h_i),   out_i · 2h_i/(h_{i−1} + h_i)
/// (both 0 when h_{i−1} + h_i = 0), so that with C = 0 the derivatives in the global parameter,
/// in_i/h_{i−1} and out_i/h_i, are equal: C¹ in that parameter, G¹ in the local one. The ends of
/// an open curve keep their uniform tangents, as the non-uniform Catmull-Rom curve does. This
/// is not the non-uniform Catmull-Rom curve of catmull_rom.h (there the tangent is the
/// spacing-weighted mean of difference quotients): the two agree for α = 0 only.
///
/// Range: T may be any finite number (it is a Catmull-Rom tension, τ = (1 − T)/2; T > 1 turns
/// the tangents round, T < −1 lengthens them beyond τ = 1), C and B must lie in [−1, 1]: they
/// weigh the two chords Δ₋ and Δ₊, and outside that range a weight (1 ± B)(1 ± C) turns
/// negative, a tangent pointing against the chord it leans on.
///
/// Exact for Rational with α = 0.

#include "core/base/expected.h"
#include "core/base/vec2.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/hermite_segment.h"
#include "core/exact/rational.h"

#include <vector>

namespace granota {

/// Tension, continuity and bias at one point (all 0: Catmull-Rom with τ = 1/2).
template <class S> struct TcbKnot {
    S tension{0};    ///< T: τ = (1 − T)/2; 1 gives zero tangents, any finite value
    S continuity{0}; ///< C ∈ [−1, 1]: 0 smooth (C¹), −1 each segment's own chord (corners)
    S bias{0};       ///< B ∈ [−1, 1]: > 0 towards the incoming chord, < 0 the outgoing one
};

/// The two tangents at one point, in the local parameter of the segments they belong to.
template <class S> struct KbTangents {
    Vec2<S> in;  ///< p′(1) of the segment ending at this point
    Vec2<S> out; ///< p′(0) of the segment starting at this point
};

template <class S> struct KochanekBartelsCurve {
    std::vector<HermiteSegment<S>> segments; ///< in Def 2.10's order (a closed curve's closing segment last)
    std::vector<KbTangents<S>> tangents;     ///< one per point (an open curve's in_0 and out_n belong to no segment)
};

/// The curve through `points` with `perPoint` TCB values (one per point, or a single one for
/// all), in Def 2.10's mode, with knot spacing |P_{i+1} − P_i|^α (0 uniform, 1/2 centripetal,
/// 1 chordal). Errors: TooFewPoints (open needs 2 points, cyclic and closed 3); InvalidInput
/// (perPoint neither 1 nor one per point, a point or a TCB value not finite); OutOfRange (C or
/// B outside [−1, 1], α outside [0, 1], an overflow in doubles); NotRational (Rational with
/// α ≠ 0: the spacing is a power of a distance).
template <class S>
Expected<KochanekBartelsCurve<S>> kochanekBartels(const std::vector<Vec2<S>>& points, const std::vector<TcbKnot<S>>& perPoint,
                                                  CatmullRomMode mode, double alpha = 0);

extern template Expected<KochanekBartelsCurve<double>> kochanekBartels(const std::vector<Point>&,
                                                                       const std::vector<TcbKnot<double>>&, CatmullRomMode,
                                                                       double);
extern template Expected<KochanekBartelsCurve<Rational>> kochanekBartels(const std::vector<RPoint>&,
                                                                         const std::vector<TcbKnot<Rational>>&, CatmullRomMode,
                                                                         double);

} // namespace granota
