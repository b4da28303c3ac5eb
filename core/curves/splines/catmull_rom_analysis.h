#pragma once
/// \file catmull_rom_analysis.h
/// The exact side of a Catmull-Rom comparison (§2.2–2.3), computed once per change of the
/// points or the settings: the segments of every tension τ in the chosen ends and, for
/// Ex 2.13, in the compared ends (Def 2.10, Lemma 2.3); the selected τ's curve as cubic Bézier
/// segments with its continuity knot by knot (§2.3, Prop 2.3); and the cubic spline of
/// Def 2.3 with its chosen ends, solved once, checked (Def 2.3's conditions) and as the Bézier
/// segments of its graph. Everything is exact (Rational): it exists when the points are
/// small fractions. The Catmull-Rom tab's side panel and `granota-cli catmull-rom --exact`
/// only format it.

#include "core/base/expected.h"
#include "core/curves/splines/bezier_segments.h"
#include "core/curves/splines/catmull_rom_ends.h"
#include "core/curves/splines/continuity_check.h"
#include "core/curves/splines/cubic_spline.h"
#include "core/curves/splines/knot_continuity.h"
#include "core/curves/splines/piecewise_polynomial.h"

#include <optional>
#include <vector>

namespace granota {

/// What to analyse besides the points.
struct CatmullRomQuestion {
    std::vector<Rational> taus;
    int selectedTau = -1; ///< the τ analysed knot by knot; −1: none
    CatmullRomEnds ends = CatmullRomEnds::Open;
    bool compareEnds = false; ///< also the curves in comparedEnds(ends) (Ex 2.13)
    bool uniform = true;      ///< uniform knot spacing: only then are the Catmull-Rom segments exact
    bool spline = false;      ///< the cubic spline of Def 2.3 too
    SplineEndConditions<Rational> splineEnds;
};

struct CatmullRomAnalysis {
    using Segments = std::vector<Vec2<Polynomial<Rational>>>;
    struct Curve {
        Rational tau;
        Expected<Segments> segments;
    };
    struct EndsCurves {
        CatmullRomEnds ends = CatmullRomEnds::Open;
        std::vector<Curve> curves; ///< one per τ, in the order asked
    };

    /// The points exactly; nullopt when they are not all fractions (then nothing below is set).
    std::optional<std::vector<RPoint>> points;
    /// The Catmull-Rom segments are exact: the points are fractions and the spacing uniform.
    bool exactCurves = false;
    /// The chosen ends, then the compared ends when asked; empty unless exactCurves.
    std::vector<EndsCurves> ends;
    /// The selected τ's curve in the chosen ends: its Bézier segments and knots (§2.3).
    std::vector<BezierSegment<Rational>> selectedBezier;
    std::vector<KnotContinuity<Rational>> selectedKnots;

    /// The cubic spline (Def 2.3) when asked; nullopt also when the points are not fractions.
    std::optional<Expected<PiecewisePolynomial<Rational>>> spline;
    ContinuityReport<Rational> splineCheck;            ///< s, s′, s″, s‴ at the knots and the data (when the spline exists)
    std::vector<BezierSegment<Rational>> splineBezier; ///< its graph (x, s(x)) as cubic Bézier segments
    std::vector<KnotContinuity<Rational>> splineKnots; ///< and knot by knot in x

    /// The selected τ's curve, when it exists exactly.
    const Curve* selected(int selectedTau) const;
    /// The lowest parametric order C^k over the selected curve's knots (2 without knots); −1 if none.
    int selectedOrder() const;
};

/// Derivatives compared by the spline's check: s, s′, s″ must match; s‴ shows that it is not more than C².
inline constexpr int kSplineCheckedOrder = 3;

/// `points`: the points as exact fractions, or nullopt when they are not (then the result is empty).
CatmullRomAnalysis analyseCatmullRom(const std::optional<std::vector<RPoint>>& points, const CatmullRomQuestion& question);

} // namespace granota
