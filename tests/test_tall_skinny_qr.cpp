// Fitting a million points (issue: speed): the blocked QR of [M | Q] and the block-wise
// Bernstein matrix must give what the plain constructions give — same normal matrix, same
// error, the known control points back — only faster.
#include "core/curves/bezier/bernstein.h"
#include "core/curves/fitting/bernstein_block.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/fitting/least_squares_fit.h"
#include "core/curves/fitting/tall_skinny_qr.h"

#include <QTest>
#include "tests/test_main.h"

#include <cmath>
#include <random>

using namespace granota;

namespace {

std::vector<double> uniformT(int k)
{
    std::vector<double> t(static_cast<std::size_t>(k));
    for (int i = 0; i < k; ++i)
        t[static_cast<std::size_t>(i)] = i / double(k - 1);
    return t;
}

std::vector<Point> curvePoints(const std::vector<Point>& control, const std::vector<double>& t, double noise)
{
    std::vector<Point> q;
    std::vector<Point> work(control.size());
    std::mt19937 random(17);
    std::uniform_real_distribution<double> uniform(-0.5, 0.5);
    for (double ti : t) {
        std::copy(control.begin(), control.end(), work.begin());
        Point p = deCasteljauInPlace(work, ti);
        p.x += noise * uniform(random);
        p.y += noise * uniform(random);
        q.push_back(p);
    }
    return q;
}

Eigen::MatrixX2d asMatrix(const std::vector<Point>& q)
{
    Eigen::MatrixX2d Q(static_cast<Eigen::Index>(q.size()), 2);
    for (std::size_t i = 0; i < q.size(); ++i)
        Q.row(static_cast<Eigen::Index>(i)) << q[i].x, q[i].y;
    return Q;
}

/// The points as they are: centre 0 and scale 1 read each coordinate exactly.
ScaledPoints asIs(const std::vector<Point>& q) { return ScaledPoints{q.data(), q.size(), Point(0, 0), 1}; }

/// ‖RᵀR − AᵀA‖/‖AᵀA‖: zero when R is the R of a QR of A, whatever the signs of its rows.
double gramError(const Eigen::MatrixXd& r, const Eigen::MatrixXd& A)
{
    const Eigen::MatrixXd gram = A.transpose() * A;
    return (r.transpose() * r - gram).norm() / gram.norm();
}

const std::vector<Point> kControl = {{0, 0}, {1, 3}, {4, 2}, {8, -2}, {1, 5}, {-3, 1}};

} // namespace

class TestTallSkinnyQr : public QObject {
    Q_OBJECT

private slots:
    void bernsteinBlockMatchesLemma21_data()
    {
        QTest::addColumn<int>("n");
        for (int n : {0, 1, 3, 10, 30, 60})
            QTest::newRow(qPrintable(QString::number(n))) << n;
    }
    void bernsteinBlockMatchesLemma21()
    {
        QFETCH(int, n);
        const auto t = uniformT(257);
        BernsteinBlock block(n, 300);
        std::vector<double> values(static_cast<std::size_t>(300 * (n + 1)));
        block.fillInto(t.data(), 257, values.data(), 300);
        const auto b = [&values](int i, int j) { return values[static_cast<std::size_t>(j * 300 + i)]; };
        for (int i = 0; i < 257; ++i) {
            const auto expected = bernsteinAll(n, t[static_cast<std::size_t>(i)]);
            double sum = 0;
            for (int j = 0; j <= n; ++j) {
                const double e = expected[static_cast<std::size_t>(j)];
                QVERIFY2(std::fabs(b(i, j) - e) <= 1e-14 * std::max(1.0, std::fabs(e)) + 1e-300,
                         qPrintable(QStringLiteral("i=%1 j=%2").arg(i).arg(j)));
                sum += b(i, j);
            }
            QVERIFY(std::fabs(sum - 1) < 1e-13); // partition of unity (Prop 2.1)
        }
    }

    void blockedQrHasTheSameNormalMatrix()
    {
        // RᵀR = [M | Q]ᵀ[M | Q] whatever the signs of R's rows: the two factorisations agree.
        for (int k : {500, 250000}) { // one thread, and the two-half split
            const auto t = uniformT(k);
            const auto q = curvePoints(kControl, t, 0.1);
            const Eigen::MatrixX2d Q = asMatrix(q);
            const int n = 5;
            const Eigen::MatrixXd r = tallSkinnyQr(t, asIs(q), n);
            Eigen::MatrixXd A(k, n + 3);
            A << bernsteinMatrix(t, n), Q;
            const double error = gramError(r, A);
            QVERIFY2(error < 1e-12, qPrintable(QString::number(error)));
            QVERIFY(r.isUpperTriangular(0));
        }
    }

    void blockedQrHandlesZeroColumnsAndRaggedBlocks()
    {
        // The first 600 parameters are 0, so whole blocks have B_j(0) = 0 for j ≥ 1 (no
        // reflector to apply in those columns), and 1003 rows end in a block whose row count
        // is not a multiple of four (padded with zero rows).
        const int k = 1003, n = 4;
        std::vector<double> t(static_cast<std::size_t>(k), 0.0);
        for (int i = 600; i < k; ++i)
            t[static_cast<std::size_t>(i)] = (i - 599) / double(k - 599);
        const auto q = curvePoints(kControl, t, 0.3);
        const Eigen::MatrixX2d Q = asMatrix(q);
        const Eigen::MatrixXd r = tallSkinnyQr(t, asIs(q), n);
        Eigen::MatrixXd A(k, n + 3);
        A << bernsteinMatrix(t, n), Q;
        const double error = gramError(r, A);
        QVERIFY2(error < 1e-13, qPrintable(QString::number(error)));
        QVERIFY(r.allFinite());
        QVERIFY(r.isUpperTriangular(0));
        // The same rows read from points through a centre and a scale give the R of the
        // transformed data, column by column.
        const ScaledPoints scaled{q.data(), q.size(), Point(2, -1), 4};
        const Eigen::MatrixXd rs = tallSkinnyQr(t, scaled, n);
        Eigen::MatrixXd As = A;
        for (int i = 0; i < k; ++i)
            As.row(i).tail(2) << scaled.x(static_cast<std::size_t>(i)), scaled.y(static_cast<std::size_t>(i));
        QVERIFY(gramError(rs, As) < 1e-13);
    }

    void manyPointsGiveTheKnownCurveBack()
    {
        const int k = 300000; // beyond kTallSkinnyRows and kParallel: every new path
        QVERIFY(static_cast<std::size_t>(k) > kTallSkinnyRows);
        const auto q = curvePoints(kControl, uniformT(k), 0.0);
        FitOptions options;
        options.degree = 5;
        const auto fit = fitBezier(q, options);
        QVERIFY(fit.ok());
        for (std::size_t j = 0; j < kControl.size(); ++j)
            QVERIFY2(distance(fit->controlPoints[j], kControl[j]) < 1e-9, qPrintable(QString::number(j)));
        QVERIFY(fit->sse < 1e-15);
        QCOMPARE(fit->residuals.size(), q.size());
    }

    void manyNoisyPointsReportTheTrueError()
    {
        const int k = 250000;
        const auto q = curvePoints(kControl, uniformT(k), 0.5);
        FitOptions options;
        options.degree = 5; // the curve's own degree: what is left is the noise
        const auto fit = fitBezier(q, options);
        QVERIFY(fit.ok());
        // The error and the residuals, recomputed independently by De Casteljau.
        double sse = 0, maxError = 0;
        std::vector<Point> work(fit->controlPoints.size());
        for (int i = 0; i < k; ++i) {
            std::copy(fit->controlPoints.begin(), fit->controlPoints.end(), work.begin());
            const Point r = q[static_cast<std::size_t>(i)] - deCasteljauInPlace(work, fit->params[static_cast<std::size_t>(i)]);
            sse += dot(r, r);
            maxError = std::max(maxError, norm(r));
            if (i % 9973 == 0)
                QVERIFY(distance(r, fit->residuals[static_cast<std::size_t>(i)]) < 1e-12);
        }
        QVERIFY2(std::fabs(fit->sse - sse) < 1e-9 * sse, qPrintable(QStringLiteral("%1 vs %2").arg(fit->sse).arg(sse)));
        QVERIFY(std::fabs(fit->maxError - maxError) < 1e-12);
        // Noise uniform in ±0.25 per coordinate: E‖r‖² ≈ 2 · 0.5²/12 per point.
        QVERIFY2(std::fabs(fit->sse / k - 2 * 0.25 / 12) < 0.03 * (2 * 0.25 / 12), qPrintable(QString::number(fit->sse / k)));
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestTallSkinnyQr)
#include "test_tall_skinny_qr.moc"
