#include "core/curves/fitting/fit_warning.h"

#include "core/base/number_format.h"
#include "core/curves/fitting/data_shape.h"
#include "core/curves/fitting/least_squares_fit.h"

namespace granota {

namespace {

std::string sci(double v) { return formatSignificant(v, 2); }

FitWarning warning(FitWarningCode code)
{
    FitWarning w;
    w.code = code;
    return w;
}

} // namespace

std::string fitWarningText(const FitWarning& w)
{
    const int m = w.degree + 1;
    switch (w.code) {
    case FitWarningCode::CoincidentFallback:
        return "all the points coincide: " + w.parametrization + " parameters are undefined, uniform ones are used";
    case FitWarningCode::CorrectionStopped: return "parameter correction stopped: " + w.reason;
    case FitWarningCode::NormalEquationsSquare:
        return "the normal equations square the condition number: cond₂(MᵀM) ≈ " + sci(w.cond * w.cond) + ", so about " +
               std::to_string(normalEquationsDigitsLost(w.cond)) + " of the 16 significant digits may be lost";
    case FitWarningCode::RankDeficient: {
        const std::string what = w.repeated ? "M is rank deficient (rank " : "M is numerically rank deficient (rank ";
        const std::string why = w.repeated ? "only " + std::to_string(w.distinct) +
                                                 " of the parameters t_i are distinct (coincident points?)"
                                           : "cond₂(M) ≈ " + sci(w.cond);
        return what + std::to_string(w.rank) + " < n + 1 = " + std::to_string(m) + ": " + why +
               "); the control points are the minimum-norm least-squares solution";
    }
    case FitWarningCode::IllConditioned:
        return "ill-conditioned: cond₂(M) ≈ " + sci(w.cond) +
               "; the control points are very sensitive to the data (lower the degree?)";
    case FitWarningCode::HighDegree:
        return "high degree n = " + std::to_string(w.degree) + ": the Bernstein basis grows ill-conditioned (cond₂(M) ≈ " +
               sci(w.cond) + ")";
    case FitWarningCode::RepeatedParameters:
        return "only " + std::to_string(w.distinct) + " distinct parameters t_i for " + std::to_string(m) +
               " control points: M is rank deficient";
    case FitWarningCode::AllCoincide: return "all the data points coincide";
    case FitWarningCode::ZeroChords:
        return std::to_string(w.pairs) + " pair(s) of consecutive data points coincide, the first Q" +
               std::to_string(w.first - 1) + " and Q" + std::to_string(w.first);
    case FitWarningCode::Collinear: return "the data points are collinear";
    }
    return {};
}

std::vector<FitWarning> fitWarnings(const FitResult* fit, const std::vector<Point>& q, const FitOptions& options)
{
    std::vector<FitWarning> out;
    const int n = options.degree;
    if (fit) {
        if (fit->cond > kIllConditionedCond) {
            FitWarning w = warning(FitWarningCode::IllConditioned);
            w.cond = fit->cond;
            out.push_back(w);
        } else if (n > kHighFitDegree) {
            FitWarning w = warning(FitWarningCode::HighDegree);
            w.degree = n;
            w.cond = fit->cond;
            out.push_back(w);
        }
        if (options.solver == LeastSquaresSolver::Normal && fit->cond > kNormalEquationsCond) {
            FitWarning w = warning(FitWarningCode::NormalEquationsSquare);
            w.cond = fit->cond;
            out.push_back(w);
        }
        std::vector<double> sorted = fit->params;
        std::sort(sorted.begin(), sorted.end());
        const auto distinct = std::unique(sorted.begin(), sorted.end()) - sorted.begin();
        if (distinct < n + 1) {
            FitWarning w = warning(FitWarningCode::RepeatedParameters);
            w.distinct = static_cast<int>(distinct);
            w.degree = n;
            out.push_back(w);
        }
    }
    // The shape of the data: explain degenerate input rather than draw something odd.
    const DataShape shape = analyseDataShape(q);
    const bool byDistance = options.parametrization != Parametrization::Uniform;
    if (q.size() >= 2 && shape.allCoincide) {
        FitWarning w = warning(FitWarningCode::AllCoincide);
        w.byDistance = byDistance;
        out.push_back(w);
    } else if (byDistance && shape.zeroChords > 0) {
        FitWarning w = warning(FitWarningCode::ZeroChords);
        w.pairs = shape.zeroChords;
        w.first = shape.firstZeroChord;
        out.push_back(w);
    }
    if (q.size() >= 2 && shape.collinear && !shape.allCoincide)
        out.push_back(warning(FitWarningCode::Collinear));
    return out;
}

} // namespace granota
