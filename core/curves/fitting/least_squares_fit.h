#pragma once
/// \file least_squares_fit.h
/// Least-squares Bézier fitting (§2.1.3): given points Q_0..Q_k, a degree n ≤ k and
/// parameters t_0..t_k, the control points P_0..P_n minimising Σ‖Q_i − α(t_i)‖² (Prop 2.2)
/// solve MᵀM P = MᵀQ, where M is the (k+1)×(n+1) matrix of B_j^n(t_i) (Lemma 2.2), i.e.
/// P = M⁺Q (Nota 2.2). The thesis solves the normal equations; Granota defaults to a
/// numerically stable orthogonal factorisation and keeps the normal equations selectable
/// to show where they break. Beyond the thesis: centripetal parameters, iterative
/// parameter correction, condition numbers, and the exact rational version that
/// reproduces the matrices of Ex 2.7 and Ex 2.8.

#include "core/base/expected.h"
#include "core/curves/fitting/fit_warning.h"
#include "core/curves/fitting/parametrization.h"
#include "core/exact/exact_cost.h"
#include "core/exact/rational.h"
#include "core/exact/rational_matrix.h"
#include "core/base/vec2.h"

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace granota {

enum class LeastSquaresSolver {
    Qr,     ///< Householder QR of M, then a complete orthogonal decomposition of R (the default)
    Normal, ///< the thesis: P = (MᵀM)⁻¹MᵀQ, by Cholesky of MᵀM; squares the condition number
    Svd,    ///< singular value decomposition (of the R factor of M, i.e. Chan's R-SVD)
};

/// "qr", "normal", "svd" (case-insensitive); nullopt for anything else.
std::optional<LeastSquaresSolver> parseLeastSquaresSolver(std::string_view text);
/// The name parseLeastSquaresSolver() reads back.
std::string toString(LeastSquaresSolver s);

struct FitOptions {
    /// n: the curve has n + 1 control points; 0 ≤ n ≤ k (k + 1 data points) and n ≤ 100.
    int degree = 3;
    /// How the t_i are chosen (§2.1.3).
    Parametrization parametrization = Parametrization::Uniform;
    /// How MP = Q is solved in the least-squares sense.
    LeastSquaresSolver solver = LeastSquaresSolver::Qr;
    /// Re-project each Q_i onto the fitted curve and refit while the error drops.
    bool correctParameters = false;
    /// At most this many refits when correcting (0: none).
    int maxCorrections = 50;
    /// Asked between parameter corrections, and every few thousand points within one, with
    /// the corrections made so far: false stops correcting there, and the fit returned is
    /// the best one so far, with FitResult::cancelled set. The window runs long fits on a
    /// worker thread and answers from its Cancel button and from newer requests (ui/fit);
    /// empty (the default) is never asked. Called on the fitting thread.
    std::function<bool(int corrections)> keepGoing;
};

struct FitResult {
    std::vector<Point> controlPoints;     ///< P_0..P_n
    std::vector<double> params;           ///< the t_i finally used (after any correction)
    std::vector<Point> residuals;         ///< Q_i − α(t_i)
    double sse = 0;                       ///< Σ‖Q_i − α(t_i)‖² (the error of Prop 2.2)
    double rms = 0;                       ///< √(sse / (k + 1))
    double maxError = 0;                  ///< max ‖Q_i − α(t_i)‖
    double cond = 1;                      ///< cond₂(M) = σ_max/σ_min (DBL_MAX when M is exactly singular)
    int corrections = 0;                  ///< parameter corrections that lowered the error
    bool cancelled = false;               ///< FitOptions::keepGoing stopped the corrections
    std::vector<FitWarning> warningCodes; ///< ill-conditioning, rank deficiency, fallbacks (fit_warning.h)
    std::vector<std::string> warnings;    ///< their English text, fitWarningText(), as the CLI prints it
};

/// The highest degree fitBezier and fitBezierExact accept: beyond it the Bernstein basis
/// at the data's parameters is too ill-conditioned for any solver (cond₂(M) grows like 2ⁿ).
constexpr int kMaxFitDegree = 100;

/// The work of a fit of `points` points at degree n in units of (k + 1)(n + 1)², about one
/// least-squares solve (the QR factorisation of M, and a projection of every point onto the
/// curve, are each a few of them): the first solve and, when correcting, `corrections` more
/// solves and projections (an upper bound: the correction stops once the error stops
/// dropping). One unit is 4 to 12 ns on the reference machine (2 cores, 2026; idle to
/// loaded): 2 000 points at degree 100 with 1 000 corrections are 2·10¹⁰ units, some 90 s.
double fitWork(std::size_t points, int degree, bool correctParameters, int corrections);
/// The most work granota-cli's `fit --iterate` takes on (4 to 12 s); beyond it refuses, and
/// says what to lower (docs/cli.md). The window has no such bound: it fits on a worker
/// thread with a Cancel button (ui/fit/background_fit.h).
constexpr double kMaxCliFitWork = 1e9;

/// M of Lemma 2.2: row i holds B_0^n(t_i)..B_n^n(t_i) (via the recursion of Lemma 2.1).
Eigen::MatrixXd bernsteinMatrix(const std::vector<double>& t, int n);

/// Fits a degree-n Bézier curve to q. Errors: InvalidInput (a NaN/inf point, naming its
/// index), TooFewPoints (fewer than 2), OutOfRange (degree < 0 or > kMaxFitDegree, or a result that
/// does not fit in a double), DegreeTooHigh (n > k: degree n needs n + 1 points),
/// Singular (normal equations with fewer than n + 1 distinct parameters, or whose
/// Cholesky factorisation fails). Qr and Svd return the minimum-norm least-squares
/// solution, with a warning, when M is rank deficient. The fit is computed in a centred,
/// scaled frame (it is affine-invariant) so coordinates from 1e−9 to 1e9 keep their
/// relative accuracy. Every number returned is finite.
Expected<FitResult> fitBezier(const std::vector<Point>& q, const FitOptions& options);

/// The exact least-squares fit of rational data: every matrix of Ex 2.7 and Ex 2.8.
struct ExactFit {
    RationalMatrix M;             ///< (k+1)×(n+1), M(i, j) = B_j^n(t_i) (Lemma 2.2)
    RationalMatrix MtM;           ///< MᵀM
    RationalMatrix MtMinv;        ///< (MᵀM)⁻¹
    RationalMatrix Mplus;         ///< M⁺ = (MᵀM)⁻¹Mᵀ (Nota 2.2)
    RationalMatrix P;             ///< (n+1)×2: row j is the control point P_j = (M⁺Q)_j
    std::vector<Rational> params; ///< t_0..t_k
    Rational sse;                 ///< Σ‖Q_i − α(t_i)‖²
};

/// Errors as fitBezier (no OutOfRange for results), plus NotRational when the chosen
/// parameters are irrational (chord length or centripetal with a distance whose square
/// root is not rational, as in Ex 2.9), Singular when fewer than n + 1 parameters are
/// distinct (MᵀM is then singular, see Lemma 2.2), and OutOfRange, before any matrix is
/// built, when fitExactWork() (core/exact/exact_cost.h) is beyond `budget`.
Expected<ExactFit> fitBezierExact(const std::vector<RPoint>& q, int degree, Parametrization p, double budget = kMaxExactWork);

} // namespace granota
