// Granota's B-spline evaluation (de_boor.h) against a peer, scipy's BSpline (python3-scipy), on
// random floating-point curves (issue 36, "What it must show"; docs/peer-comparison.md#b-splines).
// The curves come from tests/benchmarks/peer/bspline_cases.py (seeded: degrees 1–5, clamped and
// unclamped knot vectors with repeated interior knots, polynomial and rational), scipy evaluates
// them in tests/benchmarks/peer/scipy_bspline_eval.py (a rational curve as its homogeneous
// B-spline divided by w), Granota here with bsplinePoint; every coordinate must agree to 1e-12
// (the control points lie in [−1, 1]², so both are within a few ulps of the exact value: the
// peer script bspline_compare.sh measures each against exact fractions, about 2e-16). Skipped
// when no python3 with scipy is installed (.ci/deps.sh installs python3-scipy).
#include "core/curves/bsplines/de_boor.h"

#include <QProcess>
#include <QTest>
#include "tests/test_main.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

using namespace granota;

namespace {

const QString kPeerDir = QStringLiteral(GRANOTA_SOURCE_DIR "/tests/benchmarks/peer/");

/// Runs `python` on a script of the peer folder with `arguments`; its standard output, or a
/// failure message in `error`.
QByteArray runPython(const QString& python, const QStringList& arguments, QString* error)
{
    QProcess process;
    process.start(python, arguments);
    // A hang guard only: the scripts take about a second.
    if (!process.waitForFinished(300000) || process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0) {
        *error = python + QLatin1Char(' ') + arguments.join(QLatin1Char(' ')) + QStringLiteral(" failed: ") +
                 QString::fromLocal8Bit(process.readAllStandardError());
        return {};
    }
    return process.readAllStandardOutput();
}

/// The first of `python3` (PATH) and Debian's /usr/bin/python3 that can import scipy, or empty.
QString pythonWithScipy()
{
    for (const QString& candidate : {QStringLiteral("python3"), QStringLiteral("/usr/bin/python3")}) {
        QProcess process;
        process.start(candidate, {QStringLiteral("-c"), QStringLiteral("import scipy.interpolate")});
        if (process.waitForFinished(120000) && process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0)
            return candidate;
    }
    return {};
}

BSplineCurve<double> curveOf(const nlohmann::json& c)
{
    BSplineCurve<double> curve;
    curve.degree = c.at("degree").get<int>();
    for (const auto& p : c.at("points"))
        curve.points.emplace_back(p.at(0).get<double>(), p.at(1).get<double>());
    curve.knots = c.at("knots").get<std::vector<double>>();
    if (c.contains("weights"))
        curve.weights = c.at("weights").get<std::vector<double>>();
    return curve;
}

} // namespace

class TestBSplinePeers : public QObject {
    Q_OBJECT

private slots:
    void agreesWithScipy_data()
    {
        QTest::addColumn<int>("seed");
        // 20 curves a seed (5 degrees × clamped/unclamped × polynomial/rational), 24 random
        // parameters each besides both ends and every interior knot.
        for (int seed : {1, 2, 3, 36})
            QTest::newRow(qPrintable(QStringLiteral("seed %1").arg(seed))) << seed;
    }
    void agreesWithScipy()
    {
        QFETCH(int, seed);
        static const QString python = pythonWithScipy();
        if (python.isEmpty())
            QSKIP("no python3 with scipy (apt-get install python3-scipy)");
        QString error;
        const QByteArray casesText = runPython(
            python, {kPeerDir + QStringLiteral("bspline_cases.py"), QString::number(seed), QStringLiteral("24")}, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const auto cases = nlohmann::json::parse(casesText.toStdString()).at("cases");
        QCOMPARE(cases.size(), std::size_t(20));

        QProcess scipy;
        scipy.start(python, {kPeerDir + QStringLiteral("scipy_bspline_eval.py"), QStringLiteral("-")});
        scipy.write(casesText);
        scipy.closeWriteChannel();
        QVERIFY(scipy.waitForFinished(300000));
        QVERIFY2(scipy.exitCode() == 0, scipy.readAllStandardError().constData());
        const auto values = nlohmann::json::parse(scipy.readAllStandardOutput().toStdString()).at("values");
        QCOMPARE(values.size(), cases.size());

        double worst = 0;
        int compared = 0;
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const auto& c = cases[i];
            const BSplineCurve<double> curve = curveOf(c);
            const auto valid = checkBSpline(curve);
            QVERIFY2(valid.ok(), valid ? "" : valid.error().message.c_str());
            const auto& us = c.at("u");
            QCOMPARE(values[i].size(), us.size());
            for (std::size_t j = 0; j < us.size(); ++j) {
                const double u = us[j].get<double>();
                const Point ours = bsplinePoint(curve, u);
                const double x = values[i][j].at(0).get<double>(), y = values[i][j].at(1).get<double>();
                const double d = std::max(std::abs(ours.x - x), std::abs(ours.y - y));
                worst = std::max(worst, d);
                ++compared;
                if (!(d <= 1e-12))
                    QFAIL(qPrintable(QStringLiteral("%1 at u = %2: Granota (%3, %4), scipy (%5, %6)")
                                         .arg(QString::fromStdString(c.at("name").get<std::string>()))
                                         .arg(u, 0, 'g', 17)
                                         .arg(ours.x, 0, 'g', 17)
                                         .arg(ours.y, 0, 'g', 17)
                                         .arg(x, 0, 'g', 17)
                                         .arg(y, 0, 'g', 17)));
            }
        }
        QVERIFY(compared >= 20 * 26);
        qInfo("seed %d: %d points, largest difference from scipy %.2g", seed, compared, worst);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestBSplinePeers)
#include "test_bspline_peers.moc"
