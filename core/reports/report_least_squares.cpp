// docs/work-precision.md, least squares (§2.1.3): the thesis's normal equations MᵀMP = MᵀQ (Prop 2.2)
// against QR and SVD, on data that lie exactly on a known Bézier curve, so the exact
// answer is known: its control points.
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/fitting/least_squares_fit.h"
#include "core/base/stopwatch.h"
#include "core/reports/work_precision_reports.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace granota::reports {

namespace {
/// A solver that returns garbage or nothing is plotted at this error (100 000 %).
constexpr double kBreakdown = 1e3;
constexpr int kDataPoints = 200; ///< k + 1
} // namespace

Expected<WorkPrecisionReport> leastSquares(const WorkPrecisionOptions& options)
{
    WorkPrecisionReport r;
    r.name = "least-squares";
    r.title = "Least-squares Bézier fit: normal equations, QR, SVD";
    r.knob = "degree";
    r.error = "max |P_j - P_j(true)| / max |P_j(true)|";
    r.reference = "data sampled (in long double) from a Bézier curve with known control points";
    r.lesson = "The normal equations square the condition number of M: near degree 25 they have lost "
               "almost every digit and by degree 30 the curve is wrong, while QR and SVD still hold "
               "about seven digits.";
    const Progress progress(options);
    const int maxDegree = options.quick ? 30 : 40;
    const int step = options.quick ? 4 : 2;
    std::vector<double> t(kDataPoints);
    for (int i = 0; i < kDataPoints; ++i)
        t[static_cast<std::size_t>(i)] = i / double(kDataPoints - 1);
    WorkPrecisionSeries normal{"normal equations", {}}, qr{"QR", {}}, svd{"SVD", {}};
    double sink = 0;
    for (int n = 2; n <= maxDegree; n += step) {
        const std::vector<Point> truth = reportControlPoints(n + 1, 777u + static_cast<unsigned>(n));
        std::vector<Vec2<long double>> truthL, work(truth.size());
        for (const Point& p : truth)
            truthL.emplace_back(p.x, p.y);
        Eigen::MatrixXd q(kDataPoints, 2);
        for (int i = 0; i < kDataPoints; ++i) {
            std::copy(truthL.begin(), truthL.end(), work.begin());
            const auto c = deCasteljauInPlace(work, static_cast<long double>(t[static_cast<std::size_t>(i)]));
            q(i, 0) = static_cast<double>(c.x);
            q(i, 1) = static_cast<double>(c.y);
        }
        const Eigen::MatrixXd m = bernsteinMatrix(t, n);
        double scale = 0;
        for (const Point& p : truth)
            scale = std::max(scale, norm(p));
        auto errorOf = [&](const Eigen::MatrixXd& p) {
            if (!p.allFinite())
                return kBreakdown;
            double e = 0;
            for (int j = 0; j <= n; ++j)
                e = std::max(e, std::hypot(p(j, 0) - truth[std::size_t(j)].x, p(j, 1) - truth[std::size_t(j)].y));
            return std::clamp(e / scale, 1e-18, kBreakdown);
        };
        auto solveNormal = [&] { return Eigen::MatrixXd((m.transpose() * m).ldlt().solve(m.transpose() * q)); };
        auto solveQr = [&] { return Eigen::MatrixXd(m.colPivHouseholderQr().solve(q)); };
        auto solveSvd = [&] {
            return Eigen::MatrixXd(Eigen::BDCSVD<Eigen::MatrixXd>(m, Eigen::ComputeThinU | Eigen::ComputeThinV).solve(q));
        };
        auto timeOf = [&](auto&& solve) {
            return secondsPerCall([&] { return solve()(0, 0); }, options.minSecondsPerPoint, &sink);
        };
        normal.samples.push_back({double(n), errorOf(solveNormal()), timeOf(solveNormal)});
        qr.samples.push_back({double(n), errorOf(solveQr()), timeOf(solveQr)});
        svd.samples.push_back({double(n), errorOf(solveSvd()), timeOf(solveSvd)});
        if (!progress.tick(n, maxDegree))
            return cancelled();
    }
    r.series = {std::move(normal), std::move(qr), std::move(svd)};
    return r;
}

} // namespace granota::reports
