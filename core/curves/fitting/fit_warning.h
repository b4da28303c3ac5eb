#pragma once
/// \file fit_warning.h
/// What a least-squares fit (§2.1.3) warns about, as codes with the numbers a message
/// needs, so that every reader words the same facts: fitBezier() reports the solver's
/// warnings (FitResult::warningCodes, and their English in FitResult::warnings for the
/// CLI); fitWarnings() lists what the fitting tab shows for a fit and its data, which the
/// tab translates. The thresholds are defined here and nowhere else.

#include "core/base/vec2.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace granota {

struct FitOptions;
struct FitResult;

/// cond₂(M) above this: the control points are very sensitive to the data
/// (docs/extreme-cases.md).
inline constexpr double kIllConditionedCond = 1e10;
/// With the normal equations (Prop 2.2), cond₂(M) above this: cond₂(MᵀM) = cond₂(M)²
/// costs digits worth mentioning.
inline constexpr double kNormalEquationsCond = 1e5;
/// Degrees above this get a warning even when M is still well conditioned: the
/// Bernstein basis grows ill-conditioned.
inline constexpr int kHighFitDegree = 20;

enum class FitWarningCode {
    // Reported by fitBezier():
    CoincidentFallback,    ///< all points coincide: `parametrization` is undefined, uniform is used
    CorrectionStopped,     ///< a parameter correction failed (`reason`); the last good fit is kept
    NormalEquationsSquare, ///< the normal equations and cond₂(M) > kNormalEquationsCond (`cond`)
    RankDeficient,         ///< rank(M) = `rank` < n + 1; `repeated`: because of repeated t_i (`distinct`)
    IllConditioned,        ///< cond₂(M) > kIllConditionedCond (`cond`)
    // Listed by fitWarnings() only:
    HighDegree,         ///< n = `degree` > kHighFitDegree (and `cond`)
    RepeatedParameters, ///< only `distinct` distinct t_i for n + 1 = `degree` + 1 control points
    AllCoincide,        ///< every data point is the same; `byDistance`: chord/centripetal asked for
    ZeroChords,         ///< `pairs` consecutive points coincide, the first Q_{`first`−1} = Q_`first`
    Collinear,          ///< the data points lie on one line
};

struct FitWarning {
    FitWarningCode code = FitWarningCode::IllConditioned;
    double cond = 0;             ///< cond₂(M)
    int degree = 0;              ///< n
    int rank = 0;                ///< RankDeficient: the rank of M
    int distinct = 0;            ///< how many of the parameters t_i differ
    bool repeated = false;       ///< RankDeficient: repeated t_i (else only numerically deficient)
    int pairs = 0;               ///< ZeroChords: how many consecutive pairs coincide
    int first = -1;              ///< ZeroChords: the smallest i with Q_{i−1} = Q_i
    bool byDistance = false;     ///< AllCoincide: the parametrization asked for is not uniform
    std::string parametrization; ///< CoincidentFallback: the name of the one asked for
    std::string reason;          ///< CorrectionStopped: the error of the failed correction
};

/// About how many of the 16 significant digits the normal equations may lose:
/// log₁₀ cond₂(MᵀM) = log₁₀ cond₂(M)², at most 16.
inline int normalEquationsDigitsLost(double cond) { return std::min(16, static_cast<int>(std::log10(cond * cond))); }

/// The English text of a warning, as the CLI prints it (FitResult::warnings).
std::string fitWarningText(const FitWarning& w);

/// The warnings the fitting tab shows, in order: for `fit` (nullptr when there is none)
/// of degree options.degree with options.solver, and for the shape of the data `q`
/// (data_shape.h) with options.parametrization.
std::vector<FitWarning> fitWarnings(const FitResult* fit, const std::vector<Point>& q, const FitOptions& options);

} // namespace granota
