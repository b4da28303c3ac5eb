#pragma once
/// \file exact_cost.h
/// How much work an exact computation (GMP rationals) would be, estimated before it is
/// done, so that the CLI's --exact and the GUI's exact panels refuse, or fall back to
/// decimals, rather than run for minutes with memory growing. The estimate is in bit
/// operations: the number of rational operations times the bits (numerator plus
/// denominator) of the numbers they work on, which grow as the algorithm goes:
///
/// - De Casteljau (Def 2.4) of degree n at t: level r holds n − r + 1 points whose
///   coordinates have about b_P + r·b_t bits (each level multiplies by t and 1 − t once),
///   so Σ_r 2(n − r + 1)(b_P + r·b_t) ≈ n²·b_P + n³·b_t/3. With weights (a rational
///   Bézier curve), the same triangle on three homogeneous coordinates of b_P + b_w bits, and
///   the division of each level by its weights, which doubles the bits written: about three
///   times the work.
/// - The Bernstein values B_i^n(t) by Lemma 2.1: the same triangle, one coordinate, b_P = 0.
/// - The exact least-squares fit (Lemma 2.2, Nota 2.2) of m points at degree n: the t_i
///   written over one denominator L; an entry of M has about E_M = n·(b_L + 1) bits, one
///   of MᵀM E = 2E_M + log₂ m; Gauss–Jordan on the (n + 1)² matrix MᵀM does (n + 1)³
///   operations on numbers of up to (n + 1)·E bits, and M⁺ = (MᵀM)⁻¹Mᵀ another
///   m(n + 1)² on those: m(n + 1)²E + (n + 1)⁴E + m(n + 1)³E, plus the points' bits b_Q.
/// - A Catmull-Rom segment (Lemma 2.3) with tension τ: its coefficients M(τ)·[p_0 … p_3]
///   and its Bézier control points are 64 operations on numbers of b_c = b_P + b_τ bits,
///   and each of its S samples at s = j/(S − 1) (b_s = 2 log₂ S bits) two Horner schemes of
///   three steps on numbers growing to b_c + 3 b_s bits: 64 b_c + 6S(b_c + 3 b_s).
///
/// GMP multiplies and reduces b-bit numbers in more than b steps (b log b, and gcds
/// b log² b), so the estimate is a lower bound that grows more slowly than the time; the
/// budget kMaxExactWork is set where the measured time reaches a few seconds on the
/// reference machine (see docs/exact-cost.md for the measurements).

#include "core/exact/rational.h"

#include <cstddef>
#include <string>
#include <vector>

namespace granota {

/// The most estimated bit operations an exact computation may take: a few seconds on the
/// reference machine (2 cores, 2026); beyond it the CLI refuses and the GUI shows decimals.
constexpr double kMaxExactWork = 1e9;

/// Parameters t_i in radicals (radical_sum.h, parametrization.h) are written for at most
/// this many data points: beyond, each t_i is a sum of dozens of roots that no one reads.
constexpr std::size_t kMaxRadicalPoints = 40;
/// A quotient of sums of square roots is rationalised when its denominator's radicands have
/// at most this many pairwise coprime factors: each factor can double the numerator's terms
/// (2⁴ = 16 at most); beyond, the quotient is written as it stands.
constexpr int kMaxRadicalGenerators = 4;

/// Bits of |numerator| plus bits of the denominator (1/2: 1 + 2 = 3).
long bitLength(const Rational& q);
/// The largest bitLength of any coordinate of the points (0 for none).
long maxBitLength(const std::vector<RPoint>& points);

/// De Casteljau's triangle of degree n at t, exactly, points of up to pointBits bits.
double deCasteljauExactWork(int degree, long pointBits, long tBits);
/// De Casteljau with weights (rational_bezier.h) of degree n at t: the homogeneous points
/// (w_i x_i, w_i y_i, w_i) of up to pointBits + weightBits bits run through the triangle of
/// Def 2.4 (three coordinates instead of two), and each level is divided by its weights.
double rationalDeCasteljauExactWork(int degree, long pointBits, long weightBits, long tBits);
/// Every B_i^n(t) by Lemma 2.1, exactly.
double bernsteinExactWork(int degree, long tBits);
/// The exact fit of Lemma 2.2 at degree n with these parameters t_i and points of up to
/// pointBits bits.
double fitExactWork(int degree, const std::vector<Rational>& params, long pointBits);

/// The exact cubic spline of Def 2.3 with `pieces` pieces (cubic_spline.h), abscissae of up
/// to xBits bits and ordinates (and end slopes) of up to yBits: the elimination's numbers
/// grow by the abscissae's bits at every row.
double cubicSplineExactWork(int pieces, long xBits, long yBits);

/// The exact Catmull-Rom curve of `segments` segments (Lemma 2.3, Def 2.10) with tension
/// of tauBits bits and points of up to pointBits bits, and `samples` samples per segment
/// (0 when none are computed), each computed and written.
double catmullRomExactWork(std::size_t segments, long pointBits, long tauBits, int samples);

/// Whether an exact computation of this estimated work is done.
inline bool exactWorkAllowed(double work, double budget = kMaxExactWork) { return work <= budget; }

/// "the exact <what> would take about 3.2e+11 bit operations, more than 4e+09 (minutes,
/// and memory growing): lower <lower>, or leave out --exact" — the CLI's refusal.
std::string exactWorkRefusal(const std::string& what, double work, const std::string& lower);

} // namespace granota
