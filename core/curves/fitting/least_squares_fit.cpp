#include "core/curves/fitting/least_squares_fit.h"

#include "core/curves/fitting/bernstein_block.h"
#include "core/base/aabb.h"
#include "core/base/enum_names.h"
#include "core/base/number_format.h"
#include "core/curves/bezier/bernstein.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bezier/hodograph.h"
#include "core/curves/fitting/tall_skinny_qr.h"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <thread>
#include <utility>

namespace granota {

namespace {

/// c(t) of the control points P (De Casteljau, Def 2.4), with scratch space.
Point evaluateBezier(const std::vector<Point>& P, double t, std::vector<Point>& work)
{
    if (P.empty())
        return Point();
    work.assign(P.begin(), P.end());
    return deCasteljauInPlace(work, t);
}

template <class S> int countDistinct(const std::vector<S>& t)
{
    // Parameters are usually increasing already (uniform, chord, centripetal): counted
    // where they change, without a copy.
    if (std::is_sorted(t.begin(), t.end())) {
        int count = t.empty() ? 0 : 1;
        for (std::size_t i = 1; i < t.size(); ++i)
            count += t[i] != t[i - 1] ? 1 : 0;
        return count;
    }
    std::vector<S> sorted = t;
    std::sort(sorted.begin(), sorted.end());
    return static_cast<int>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
}

std::string pointsNeeded(int degree)
{
    return "degree " + std::to_string(degree) + " has " + std::to_string(degree + 1) + " control points and needs at least " +
           std::to_string(degree + 1) + " data points";
}

/// Checks shared by the floating-point and the exact fit.
std::optional<Error> validateShape(std::size_t count, int degree)
{
    if (count < 2)
        return makeError(ErrorCode::TooFewPoints, "a least-squares fit needs at least 2 points, got " + std::to_string(count));
    if (degree < 0)
        return makeError(ErrorCode::OutOfRange, "the degree must be 0 or more, got " + std::to_string(degree));
    if (degree > kMaxFitDegree)
        return makeError(ErrorCode::OutOfRange, "degree " + std::to_string(degree) + " is beyond the supported maximum of " +
                                                    std::to_string(kMaxFitDegree));
    if (static_cast<std::size_t>(degree) + 1 > count)
        return makeError(ErrorCode::DegreeTooHigh, pointsNeeded(degree) + " (n + 1 ≤ k + 1); there are only " +
                                                       std::to_string(count) + ", so the degree can be at most " +
                                                       std::to_string(count - 1));
    return std::nullopt;
}

/// From this many points on, the residuals are computed on two threads.
constexpr std::size_t kParallelResiduals = 200000;

/// The least-squares solution in the working frame.
struct Solution {
    std::vector<Point> P;
    double cond = 1;
    double sse = -1; ///< Σ‖Q_i − α(t_i)‖² in the working frame, or −1 when not computed
    std::vector<FitWarning> warnings;
};

/// Solves min ‖MP − Q‖ for M = bernsteinMatrix(t, n) with the chosen solver.
Expected<Solution> solve(const ScaledPoints& data, const std::vector<double>& t, int n, LeastSquaresSolver solver)
{
    const Eigen::Index m = n + 1;
    // How many t_i differ: only needed to explain a singular or rank-deficient M.
    std::optional<int> distinctCount;
    const auto distinct = [&] {
        if (!distinctCount)
            distinctCount = countDistinct(t);
        return *distinctCount;
    };

    Eigen::MatrixXd R; // upper triangular, M = QR (so cond₂(M) = cond₂(R))
    Eigen::MatrixXd c; // (QᵀQ_data) rows 0..n: the least-squares problem is R P = c
    double sse = -1;   // Σ‖Q_i − α(t_i)‖² when the factorisation gives it for free
    Eigen::MatrixXd MtM, MtQ;
    if (solver != LeastSquaresSolver::Normal && t.size() >= kTallSkinnyRows) {
        // Many points: QR of [M | Q] a block at a time, M never formed (tall_skinny_qr.h).
        const Eigen::MatrixXd r = tallSkinnyQr(t, data, n);
        R = r.topLeftCorner(m, m);
        c = r.topRightCorner(m, 2);
        sse = r.bottomRightCorner(2, 2).squaredNorm();
    } else {
        Eigen::MatrixX2d Q(static_cast<Eigen::Index>(data.count), 2);
        for (std::size_t i = 0; i < data.count; ++i)
            Q.row(static_cast<Eigen::Index>(i)) << data.x(i), data.y(i);
        Eigen::MatrixXd M = bernsteinMatrix(t, n);
        // The thesis's normal equations MᵀM P = MᵀQ (Prop 2.2) need M before it is factorised.
        if (solver == LeastSquaresSolver::Normal) {
            if (distinct() < m)
                return makeError(ErrorCode::Singular,
                                 "the normal equations MᵀM P = MᵀQ have no unique solution: only " + std::to_string(distinct()) +
                                     " of the parameters t_i are distinct and Lemma 2.2 needs n + 1 = " + std::to_string(m) +
                                     " (coincident points?). Lower the degree or use the qr or svd solver.");
            MtM = M.transpose() * M;
            MtQ = M.transpose() * Q;
        }
        // cond₂(M) from the singular values of R in M = QR (Householder, in place).
        Eigen::HouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr(M);
        R = qr.matrixQR().topRows(m).triangularView<Eigen::Upper>();
        // Qᵀ applied as Householder reflections.
        if (solver != LeastSquaresSolver::Normal)
            c = (qr.householderQ().transpose() * Q).topRows(m);
    }
    const unsigned options = solver == LeastSquaresSolver::Svd ? (Eigen::ComputeFullU | Eigen::ComputeFullV) : 0u;
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(R, options);
    const Eigen::VectorXd sigma = svd.singularValues();
    Solution s;
    s.cond = sigma(m - 1) > 0 ? sigma(0) / sigma(m - 1) : std::numeric_limits<double>::max();
    if (!std::isfinite(s.cond))
        s.cond = std::numeric_limits<double>::max();

    Eigen::MatrixXd P;
    Eigen::Index rank = m;
    if (solver == LeastSquaresSolver::Normal) {
        // P = (MᵀM)⁻¹MᵀQ (Prop 2.2) by Cholesky: cond₂(MᵀM) = cond₂(M)².
        const Eigen::LLT<Eigen::MatrixXd> llt(MtM);
        if (llt.info() != Eigen::Success)
            return makeError(ErrorCode::Singular,
                             "the Cholesky factorisation of MᵀM failed: MᵀM is numerically singular (cond₂(M) ≈ " +
                                 formatSignificant(s.cond, 2) + ", so cond₂(MᵀM) ≈ " + formatSignificant(s.cond * s.cond, 2) +
                                 "). Use the qr or svd solver.");
        P = llt.solve(MtQ);
        if (!P.allFinite())
            return makeError(ErrorCode::Singular, "the normal equations gave a non-finite solution (cond₂(MᵀM) ≈ " +
                                                      formatSignificant(s.cond * s.cond, 2) + "). Use the qr or svd solver.");
        if (s.cond > kNormalEquationsCond) {
            FitWarning w;
            w.code = FitWarningCode::NormalEquationsSquare;
            w.cond = s.cond;
            s.warnings.push_back(w);
        }
    } else {
        // R P = c, from Householder or from the blocked factorisation.
        if (solver == LeastSquaresSolver::Qr) {
            const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(R);
            P = cod.solve(c);
            rank = cod.rank();
        } else {
            P = svd.solve(c);
            rank = svd.rank();
        }
        if (rank < m) {
            FitWarning w;
            w.code = FitWarningCode::RankDeficient;
            w.degree = n;
            w.rank = static_cast<int>(rank);
            w.repeated = distinct() < m;
            if (w.repeated)
                w.distinct = distinct();
            w.cond = s.cond;
            s.warnings.push_back(w);
        }
    }
    if (s.cond > kIllConditionedCond) {
        FitWarning w;
        w.code = FitWarningCode::IllConditioned;
        w.cond = s.cond;
        s.warnings.push_back(w);
    }
    if (!P.allFinite())
        return makeError(ErrorCode::Singular, "the least-squares solve gave a non-finite result");
    if (rank == m)
        s.sse = sse; // the factorisation's residual is the fit's only at full rank
    s.P.resize(static_cast<std::size_t>(m));
    for (Eigen::Index j = 0; j < m; ++j)
        s.P[static_cast<std::size_t>(j)] = Point(P(j, 0), P(j, 1));
    return s;
}

/// FitOptions::keepGoing, asked at most every kAskEvery points; once it says stop, it stays stopped.
class Cancellation {
public:
    explicit Cancellation(const FitOptions& options) : m_keepGoing(options.keepGoing) {}
    /// How often the loops over the points ask (a few microseconds at degree 100).
    static constexpr std::size_t kAskEvery = 1024;
    /// Whether to go on, asked with `done` corrections made.
    bool keepGoing(int done)
    {
        if (!m_stopped && m_keepGoing && !m_keepGoing(done))
            m_stopped = true;
        return !m_stopped;
    }
    /// Within a loop over the points: asks at point 0, kAskEvery, 2 kAskEvery…
    bool keepGoingAt(std::size_t i, int done) { return i % kAskEvery != 0 || keepGoing(done); }
    bool stopped() const { return m_stopped; }

private:
    const std::function<bool(int)>& m_keepGoing;
    bool m_stopped = false;
};

double sumOfSquares(const std::vector<Point>& q, const std::vector<Point>& P, const std::vector<double>& t, Cancellation& cancel,
                    int done)
{
    std::vector<Point> work;
    double sse = 0;
    for (std::size_t i = 0; i < q.size() && cancel.keepGoingAt(i, done); ++i) {
        const Point r = q[i] - evaluateBezier(P, t[i], work);
        sse += dot(r, r);
    }
    return sse;
}

/// Projects every q_i onto the curve P by a few Newton steps on |α(t) − q_i|², starting at
/// t_i and clamped to [0, 1]; a point keeps its t_i unless the step brings it closer.
/// Stops early (the rest of the t_i as they were) when `cancel` says so.
std::vector<double> project(const std::vector<Point>& q, const std::vector<Point>& P, const std::vector<double>& t,
                            Cancellation& cancel, int done)
{
    const std::vector<Point> d1 = hodograph(P);
    const std::vector<Point> d2 = hodograph(d1);
    std::vector<Point> work;
    std::vector<double> out = t;
    for (std::size_t i = 0; i < q.size() && cancel.keepGoingAt(i, done); ++i) {
        const Point start = evaluateBezier(P, t[i], work) - q[i];
        const double startDistance = dot(start, start);
        double ti = t[i];
        for (int iteration = 0; iteration < 8; ++iteration) {
            const Point diff = evaluateBezier(P, ti, work) - q[i];
            const Point a1 = evaluateBezier(d1, ti, work);
            const Point a2 = evaluateBezier(d2, ti, work);
            const double g = dot(diff, a1);
            double h = dot(a1, a1) + dot(diff, a2);
            if (!(h > 0))
                h = dot(a1, a1); // Gauss–Newton when the curvature term makes h ≤ 0
            if (!(h > 0))
                break;
            const double next = std::clamp(ti - g / h, 0.0, 1.0);
            if (!std::isfinite(next) || next == ti)
                break;
            ti = next;
        }
        const Point end = evaluateBezier(P, ti, work) - q[i];
        if (dot(end, end) < startDistance)
            out[i] = ti;
    }
    // Stretch back to [0, 1]: an affine change of parameter keeps the space of curves of
    // degree ≤ n, so the best fit is no worse, and M stays better conditioned.
    const auto [lo, hi] = std::minmax_element(out.begin(), out.end());
    const double a = *lo, b = *hi;
    if (b > a)
        for (double& ti : out)
            ti = std::clamp((ti - a) / (b - a), 0.0, 1.0);
    return out;
}

constexpr std::array<EnumName<LeastSquaresSolver>, 3> kSolverNames{{
    {LeastSquaresSolver::Qr, "qr"},
    {LeastSquaresSolver::Normal, "normal"},
    {LeastSquaresSolver::Svd, "svd"},
}};

} // namespace

std::optional<LeastSquaresSolver> parseLeastSquaresSolver(std::string_view text)
{
    return parseName(kSolverNames, text, NameMatch::IgnoreCase);
}

std::string toString(LeastSquaresSolver s) { return std::string(nameOf(kSolverNames, s, "qr")); }

double fitWork(std::size_t points, int degree, bool correctParameters, int corrections)
{
    const double solve = static_cast<double>(points) * (degree + 1.0) * (degree + 1.0);
    return solve * (1.0 + (correctParameters && degree > 0 ? std::max(corrections, 0) : 0));
}

Eigen::MatrixXd bernsteinMatrix(const std::vector<double>& t, int n)
{
    n = std::max(n, 0);
    Eigen::MatrixXd M(static_cast<Eigen::Index>(t.size()), n + 1);
    std::vector<double> row(static_cast<std::size_t>(n + 1));
    for (std::size_t i = 0; i < t.size(); ++i) {
        bernsteinAllInto(n, t[i], row.data());
        for (int j = 0; j <= n; ++j)
            M(static_cast<Eigen::Index>(i), j) = row[static_cast<std::size_t>(j)];
    }
    return M;
}

Expected<FitResult> fitBezier(const std::vector<Point>& q, const FitOptions& options)
{
    for (std::size_t i = 0; i < q.size(); ++i)
        if (!isFinite(q[i]))
            return makeError(ErrorCode::InvalidInput, "point Q_" + std::to_string(i) + " (number " + std::to_string(i + 1) +
                                                          ") has a coordinate that is NaN or infinite");
    if (auto error = validateShape(q.size(), options.degree))
        return *error;
    const int n = options.degree;

    FitResult result;
    bool fellBack = false;
    std::vector<double> t = parameters(q, options.parametrization, &fellBack);
    if (fellBack) {
        FitWarning w;
        w.code = FitWarningCode::CoincidentFallback;
        w.parametrization = toString(options.parametrization);
        result.warningCodes.push_back(w);
    }

    // Work in a centred, scaled frame: the fit is affine-invariant (the rows of M sum to 1,
    // Prop 2.1), and data around 1e9 or 1e−9 keep their relative accuracy.
    const Aabb box = boundingBox(q.data(), static_cast<int>(q.size()));
    const Point centre(0.5 * box.minX + 0.5 * box.maxX, 0.5 * box.minY + 0.5 * box.maxY);
    const double halfSize = std::max(0.5 * box.maxX - 0.5 * box.minX, 0.5 * box.maxY - 0.5 * box.minY);
    const double scale = halfSize > 0 && std::isfinite(halfSize) ? halfSize : 1.0;
    const ScaledPoints data{q.data(), q.size(), centre, scale};

    Expected<Solution> first = solve(data, t, n, options.solver);
    if (!first)
        return first.error();
    Solution best = std::move(first).value();
    double bestSse = 0;

    // Iterative parameter correction (beyond the thesis, which fixes the t_i): project
    // each Q_i onto the current curve and refit while the error keeps dropping.
    if (options.correctParameters && n > 0) {
        std::vector<Point> local(q.size());
        for (std::size_t i = 0; i < q.size(); ++i)
            local[i] = Point(data.x(i), data.y(i));
        Cancellation cancel(options);
        bestSse = best.sse >= 0 ? best.sse : sumOfSquares(local, best.P, t, cancel, 0);
        for (int iteration = 0; iteration < options.maxCorrections && bestSse > 0; ++iteration) {
            if (!cancel.keepGoing(result.corrections))
                break;
            std::vector<double> corrected = project(local, best.P, t, cancel, result.corrections);
            if (cancel.stopped())
                break; // a correction half made: the best so far stands
            Expected<Solution> next = solve(data, corrected, n, options.solver);
            if (!next) {
                FitWarning w;
                w.code = FitWarningCode::CorrectionStopped;
                w.reason = next.error().message;
                result.warningCodes.push_back(w);
                break;
            }
            const double sse = sumOfSquares(local, next->P, corrected, cancel, result.corrections);
            if (cancel.stopped() || !(sse < bestSse))
                break;
            const double improvement = (bestSse - sse) / bestSse;
            best = std::move(next).value();
            bestSse = sse;
            t = std::move(corrected);
            ++result.corrections;
            if (improvement < 1e-12)
                break;
        }
        result.cancelled = cancel.stopped();
    }

    // Back to the user's frame.
    result.cond = best.cond;
    result.warningCodes.insert(result.warningCodes.end(), best.warnings.begin(), best.warnings.end());
    for (const FitWarning& w : result.warningCodes)
        result.warnings.push_back(fitWarningText(w));
    result.controlPoints.reserve(best.P.size());
    for (const Point& p : best.P)
        result.controlPoints.push_back(Point(centre.x + scale * p.x, centre.y + scale * p.y));
    // α(t_i) = Σ_j B_j^n(t_i) P_j (Def 2.6), a block of rows of M times P at a time
    // (bernstein_block.h). With many points the two halves run on two threads (a fixed
    // split: the same sums on one core).
    result.residuals.resize(q.size());
    struct Partial {
        double sse = 0, maxSquared = 0;
    };
    auto residuals = [&](std::size_t first, std::size_t last) {
        constexpr int kBlock = 512;
        const std::size_t m = best.P.size();
        BernsteinBlock bernstein(n, kBlock);
        std::vector<double> b(m * kBlock), alphaX(kBlock), alphaY(kBlock);
        Partial part;
        for (std::size_t s = first; s < last; s += kBlock) {
            const int rows = static_cast<int>(std::min<std::size_t>(kBlock, last - s));
            bernstein.fillInto(t.data() + s, rows, b.data(), kBlock);
            std::fill(alphaX.begin(), alphaX.begin() + rows, 0.0);
            std::fill(alphaY.begin(), alphaY.begin() + rows, 0.0);
            for (std::size_t j = 0; j < m; ++j) {
                const double* const bj = b.data() + j * kBlock;
                const double px = best.P[j].x, py = best.P[j].y;
                for (int i = 0; i < rows; ++i) {
                    alphaX[static_cast<std::size_t>(i)] += bj[i] * px;
                    alphaY[static_cast<std::size_t>(i)] += bj[i] * py;
                }
            }
            for (int i = 0; i < rows; ++i) {
                const std::size_t k = s + static_cast<std::size_t>(i);
                const Point r(data.x(k) - alphaX[static_cast<std::size_t>(i)], data.y(k) - alphaY[static_cast<std::size_t>(i)]);
                const double r2 = dot(r, r);
                part.sse += r2;
                part.maxSquared = std::max(part.maxSquared, r2);
                result.residuals[k] = scale * r;
            }
        }
        return part;
    };
    Partial total;
    if (q.size() >= kParallelResiduals) {
        const std::size_t half = q.size() / 2;
        Partial low;
        std::thread worker([&] { low = residuals(0, half); });
        const Partial high = residuals(half, q.size());
        worker.join();
        total = {low.sse + high.sse, std::max(low.maxSquared, high.maxSquared)};
    } else {
        total = residuals(0, q.size());
    }
    const double sse = total.sse, maxError = std::sqrt(total.maxSquared);
    result.sse = scale * scale * sse;
    result.rms = std::sqrt(result.sse / static_cast<double>(q.size()));
    result.maxError = scale * maxError;
    result.params = std::move(t);

    bool finite = std::isfinite(result.sse) && std::isfinite(result.rms) && std::isfinite(result.maxError) &&
                  std::isfinite(result.cond);
    for (const Point& p : result.controlPoints)
        finite = finite && isFinite(p);
    // Every residual is finite when their sum of squares is (checked above).
    if (!finite)
        return makeError(ErrorCode::OutOfRange, "the fitted curve does not fit in double precision "
                                                "(coordinates too large for this degree?)");
    return result;
}

Expected<ExactFit> fitBezierExact(const std::vector<RPoint>& q, int degree, Parametrization p, double budget)
{
    if (auto error = validateShape(q.size(), degree))
        return *error;
    const int n = degree;
    const int rows = static_cast<int>(q.size());

    std::optional<std::vector<Rational>> t = exactParameters(q, p);
    if (!t) {
        // Name the first distance that spoils it (Ex 2.9: d_1 = √10).
        std::string which;
        for (std::size_t j = 1; j < q.size() && which.empty(); ++j) {
            const bool annex = p == Parametrization::AnnexIII; // |Q_{j−1}|, as BezParamProp
            const Rational dx = annex ? q[j - 1].x : Rational(q[j].x - q[j - 1].x);
            const Rational dy = annex ? q[j - 1].y : Rational(q[j].y - q[j - 1].y);
            const Rational squared = Rational(dx * dx + dy * dy);
            const std::optional<Rational> d = exactSqrt(squared);
            if (!d)
                which = "d_" + std::to_string(j) + " = |Q_" + std::to_string(j - 1) + (annex ? "" : " − Q_" + std::to_string(j)) +
                        "| = √(" + toString(squared) + ")";
            else if (p == Parametrization::Centripetal && !exactSqrt(*d))
                which = "√d_" + std::to_string(j) + " = √(" + toString(*d) + ")";
        }
        return makeError(ErrorCode::NotRational, "the " + toString(p) + " parameters are irrational (" + which +
                                                     " is not a rational number), so the fit cannot be exact; "
                                                     "use uniform parameters or the floating-point fit");
    }
    const int distinct = countDistinct(*t);
    if (const double work = fitExactWork(n, *t, maxBitLength(q)); !exactWorkAllowed(work, budget))
        return makeError(ErrorCode::OutOfRange, exactWorkRefusal("fit", work, "--degree, the number of points or their digits"));
    if (distinct < n + 1)
        return makeError(ErrorCode::Singular, "MᵀM is singular: only " + std::to_string(distinct) +
                                                  " of the parameters t_i are distinct and Lemma 2.2 needs n + 1 = " +
                                                  std::to_string(n + 1) + " (coincident points?)");

    ExactFit fit;
    fit.params = *t;
    // M of Lemma 2.2, row by row (Lemma 2.1).
    fit.M = RationalMatrix(rows, n + 1);
    std::vector<Rational> row(static_cast<std::size_t>(n + 1));
    for (int i = 0; i < rows; ++i) {
        bernsteinAllInto(n, fit.params[static_cast<std::size_t>(i)], row.data());
        for (int j = 0; j <= n; ++j)
            fit.M(i, j) = row[static_cast<std::size_t>(j)];
    }
    const RationalMatrix Mt = fit.M.transpose();
    fit.MtM = Mt * fit.M;
    Expected<RationalMatrix> inverse = fit.MtM.inverse();
    if (!inverse)
        return makeError(ErrorCode::Singular, "MᵀM is singular: " + inverse.error().message);
    fit.MtMinv = std::move(inverse).value();
    fit.Mplus = fit.MtMinv * Mt; // Nota 2.2: M⁺ = (MᵀM)⁻¹Mᵀ
    RationalMatrix Q(rows, 2);
    for (int i = 0; i < rows; ++i) {
        Q(i, 0) = q[static_cast<std::size_t>(i)].x;
        Q(i, 1) = q[static_cast<std::size_t>(i)].y;
    }
    fit.P = fit.Mplus * Q;
    const RationalMatrix fitted = fit.M * fit.P;
    fit.sse = 0;
    for (int i = 0; i < rows; ++i)
        for (int c = 0; c < 2; ++c) {
            const Rational r = Rational(Q(i, c) - fitted(i, c));
            fit.sse += Rational(r * r);
        }
    return fit;
}

} // namespace granota
