#pragma once
/// \file monotone_spline.h
/// Monotone cubic interpolation of function data (x_i, y_i), x strictly increasing: a C¹
/// piecewise cubic (cubic Hermite pieces, Def 2.8's form with free tangents) that rises
/// where the data rise, falls where they fall, and is flat where two data values are equal
/// — it never overshoots the data, which the C² spline of Def 2.3 does (d3-shape #38:
/// on [[0,224],[100,200],[107,180],[502,300],[580,120],[607,148],[900,400]] the natural
/// spline dips about 98 below the data's minimum). The price is C²: the slopes are chosen
/// by a rule, not by a linear system.
///
/// With h_i = x_{i+1} − x_i and Δ_i = (y_{i+1} − y_i)/h_i, piece i is the Hermite cubic
/// with values y_i, y_{i+1} and slopes m_i, m_{i+1}. The two rules:
///  - Fritsch & Carlson, "Monotone piecewise cubic interpolation", SIAM J. Numer. Anal. 17
///    (1980): m_i from the three-point formula (the slope of the parabola through
///    neighbouring points), set to 0 at a local extremum of the data (Δ_{i−1}Δ_i ≤ 0) and on
///    both sides of a flat step (Δ_i = 0); then on each piece with α = m_i/Δ_i,
///    β = m_{i+1}/Δ_i outside the circle α² + β² ≤ 9 (a part of FC's monotonicity region),
///    both slopes are scaled by 3/√(α² + β²) onto it.
///  - Steffen, "A simple method for monotonic interpolation in one dimension", Astron.
///    Astrophys. 239 (1990): with p_i = (Δ_{i−1}h_i + Δ_i h_{i−1})/(h_{i−1} + h_i),
///    m_i = (sign Δ_{i−1} + sign Δ_i) · min(|Δ_{i−1}|, |Δ_i|, |p_i|/2) (eq. 11), and at the
///    ends the one-sided parabola's slope p_0 = Δ_0(1 + h_0/(h_0 + h_1)) − Δ_1 h_0/(h_0 + h_1),
///    taken as 0 when p_0Δ_0 ≤ 0 and as 2Δ_0 when |p_0| > 2|Δ_0| (eq. 26–27; likewise at the
///    last point). d3-shape's curveMonotoneX is Steffen's rule inside (its ends differ).
///
/// The proof, per piece and without sampling: on [x_i, x_{i+1}] the cubic has the Bernstein
/// coefficients b_0 = y_i, b_1 = y_i + h m_i/3, b_2 = y_{i+1} − h m_{i+1}/3, b_3 = y_{i+1},
/// and its derivative (times h) the quadratic Bernstein coefficients d_j = 3(b_{j+1} − b_j).
/// A quadratic Σ d_j B_j²(t) with d_0, d_2 ≥ 0 is ≥ 0 on [0, 1] exactly when d_1 ≥ 0 or
/// d_1² ≤ d_0 d_2 (its minimum inside is (d_0 d_2 − d_1²)/(d_0 − 2d_1 + d_2)); so the piece
/// is increasing (and the sign-reversed test: decreasing). Computed in exact rationals from
/// the doubles the pieces are made of, so the verdict is a proof about those numbers.
/// Bounds: when every b_j lies between y_i and y_{i+1}, so does the piece (convex hull).

#include "core/base/expected.h"
#include "core/base/vec2.h"
#include "core/curves/splines/piecewise_polynomial.h"
#include "core/exact/rational.h"

#include <array>
#include <optional>
#include <string_view>
#include <vector>

namespace granota {

/// The two slope rules (see the file's comment).
enum class MonotoneMethod { FritschCarlson, Steffen };
/// "fritsch-carlson", "steffen": as the CLI's --monotone writes them.
std::string_view monotoneMethodName(MonotoneMethod method);
std::optional<MonotoneMethod> parseMonotoneMethod(std::string_view name);

/// The slopes m_i = s′(x_i) the rule picks, one per data point. Errors: TooFewPoints (fewer
/// than 2), NotIncreasing, InvalidInput (NaN or infinity), OutOfRange (an overflow).
Expected<std::vector<double>> monotoneSlopes(const std::vector<Vec2<double>>& data, MonotoneMethod method);

/// The C¹ piecewise cubic through the data with the rule's slopes, pieces in powers of
/// (x − x_i) (localOrigin). Two points give the line. Errors as monotoneSlopes().
Expected<PiecewisePolynomial<double>> monotoneSpline(const std::vector<Vec2<double>>& data, MonotoneMethod method);

/// How a piece behaves on its interval, proven from its Bernstein coefficients.
enum class PieceMonotonicity { Constant, Increasing, Decreasing, NotMonotone };

/// The proof for one piece (see the file's comment), exact in rationals.
struct MonotonePieceProof {
    std::array<Rational, 4> bernstein;           ///< b_0..b_3 of the Hermite cubic on its interval
    std::array<Rational, 3> derivativeBernstein; ///< d_j = 3(b_{j+1} − b_j): h·s′ = Σ d_j B_j²
    PieceMonotonicity verdict = PieceMonotonicity::NotMonotone;
    bool byControlPolygon = false; ///< the d_j share a sign; otherwise d_1² ≤ d_0 d_2 decided it
    bool withinData = false;       ///< every b_j between y_i and y_{i+1}: the piece stays between them
};

/// The proof for the Hermite cubic with values y0, y1 and slopes m0, m1 on an interval of
/// length h > 0 (all finite).
MonotonePieceProof proveMonotonePiece(double y0, double y1, double m0, double m1, double h);

/// One proof per piece of the Hermite spline with these slopes through the data (the
/// pieces monotoneSpline() builds), in order. Sizes agree; x increases.
std::vector<MonotonePieceProof> proveMonotone(const std::vector<Vec2<double>>& data, const std::vector<double>& slopes);

} // namespace granota
