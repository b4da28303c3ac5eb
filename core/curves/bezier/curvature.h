#pragma once
/// \file curvature.h
/// The differential geometry of a Bézier curve at one parameter (beyond the thesis, which
/// compares curves by continuity, §2.3; Farin, "Curves and Surfaces for CAGD", §10.2;
/// Pomax, "A Primer on Bézier Curves", §"Curvature"):
///   signed curvature κ = (x′y″ − y′x″) / |c′|³ (y up: κ > 0 where the curve turns left),
///   the unit normal n = (−y′, x′)/|c′| (left of the tangent), the osculating circle of
///   radius 1/|κ| and centre c + n/κ.
/// c′ and c″ come from the hodograph (hodograph.h), applied once and twice.
///
/// Where c′ = 0 (a cusp, or coincident end control points at t = 0 or 1) κ is undefined and
/// is nullopt, never 0 and never NaN. "c′ = 0" is decided relative to the curve's size:
/// |c′(t)| ≤ 1e-12 · n · h, with h the largest coordinate difference between control points
/// (so a curve and the same curve scaled by 10^k agree; a single repeated point has h = 0
/// and c′ ≡ 0). Where that test says c′ = 0, the control points and t taken exactly (every
/// double is a rational) decide, within kMaxExactWork (exact_hodograph.h): control points
/// near ±1e308 round c′ by about 1e292, and an exact c′ of (21/4, 0) is then no cusp, with
/// its κ computed from the exact c′ and c″. On a straight piece κ = 0 exactly — when x′y″ − y′x″ is below its own
/// rounding error, 4(n+1)ε|c′||c″| — and the radius and centre are nullopt (infinite).
/// The computation is scaled by a power of two, so coordinates from 1e-150 to 1e150 give
/// finite κ where |c′|³ alone would overflow or underflow.

#include "core/base/vec2.h"
#include "core/exact/rational.h"

#include <optional>
#include <string>
#include <vector>

namespace granota {

struct CurvatureAt {
    double t = 0;
    Point point;                     ///< c(t)
    Point tangent;                   ///< c′(t) (not normalised)
    std::optional<Point> normal;     ///< unit, left of the tangent; nullopt where c′ = 0
    std::optional<double> curvature; ///< signed κ; nullopt where c′ = 0
    std::optional<double> radius;    ///< 1/|κ|; nullopt where κ = 0 or undefined
    std::optional<Point> center;     ///< point + normal/κ; nullopt likewise
    /// c′ and c″ came from the control points taken exactly (exact_hodograph.h): the doubles
    /// could not tell c′ from 0, and tangent is the exact c′ rounded (De Casteljau's triangle
    /// in doubles gives rounding noise there).
    bool exact = false;
};

/// Everything above at t (t is clamped to [0, 1]). P must not be empty.
CurvatureAt curvatureAt(const std::vector<Point>& P, double t);

/// κ exactly for rational points and t: κ = numerator / (speedSquared · √speedSquared), with
/// numerator = x′y″ − y′x″ and speedSquared = |c′|² both rational. speedSquared = 0 where κ is
/// undefined (c′ = 0; here exactly 0, no tolerance).
struct ExactCurvature {
    Rational numerator;
    Rational speedSquared;
};

ExactCurvature exactCurvatureAt(const std::vector<RPoint>& P, const Rational& t);

/// κ as text in simplest radical form: "-2/3", "4√5/25", "-√2/4"; nullopt where κ is undefined.
/// When |c′|² is too large to simplify quickly, "N/D^(3/2)" with N and D in lowest terms.
std::optional<std::string> exactCurvatureText(const ExactCurvature& k);

} // namespace granota
