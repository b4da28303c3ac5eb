// The work-precision reports of docs/work-precision.md teach what theory says: the numbers are checked
// here (orders of convergence, who loses digits where), never the times.
#include "core/curves/bezier/arc_length.h"
#include "core/reports/work_precision.h"
#include "core/softbody/integrators.h"
#include "core/reports/work_precision_reports.h"

#include <QTest>
#include "tests/test_main.h"

#include <array>
#include <cmath>

using namespace granota;

namespace {

WorkPrecisionReport quickReport(const char* name)
{
    WorkPrecisionOptions options;
    options.quick = true;
    options.minSecondsPerPoint = 1e-6; // one call per point: the errors, not the times
    auto report = runWorkPrecisionReport(name, options);
    if (!report)
        qFatal("%s: %s", name, report.error().message.c_str());
    return *report;
}

/// The series of `report` for each of `methods`, in that order; nullptr for one it lacks.
template <typename... Names>
std::array<const WorkPrecisionSeries*, sizeof...(Names)> seriesOf(const WorkPrecisionReport& report, Names... methods)
{
    return {report.find(methods)...};
}

double errorAt(const WorkPrecisionSeries& s, double knob)
{
    for (const auto& p : s.samples)
        if (p.knob == knob)
            return p.error;
    qFatal("no sample at knob %g in %s", knob, s.method.c_str());
}

} // namespace

class TestWorkPrecision : public QObject {
    Q_OBJECT

private slots:
    void everyReportHasFiniteSamples_data()
    {
        QTest::addColumn<QString>("name");
        for (const auto& n : workPrecisionReportNames())
            QTest::newRow(n.c_str()) << QString::fromStdString(n);
    }
    void everyReportHasFiniteSamples()
    {
        QFETCH(QString, name);
        const auto r = quickReport(name.toStdString().c_str());
        QCOMPARE(QString::fromStdString(r.name), name);
        QVERIFY(r.series.size() >= 2);
        QVERIFY(!r.lesson.empty() && !r.knob.empty() && !r.reference.empty());
        for (const auto& s : r.series) {
            QVERIFY(!s.samples.empty());
            for (const auto& p : s.samples) {
                QVERIFY(std::isfinite(p.knob) && p.knob > 0);
                if (!r.timed) { // energy-drift: a signed E/E0 − 1 step by step, no clock
                    QVERIFY(std::isfinite(p.error) && p.seconds == 0);
                    continue;
                }
                QVERIFY(std::isfinite(p.error) && p.error > 0);
                QVERIFY(std::isfinite(p.seconds) && p.seconds > 0);
            }
        }
    }

    // Ch. 3: explicit and semi-implicit Euler are first order, Verlet second, RK4 fourth.
    void integratorsConvergeAtTheirOrder_data()
    {
        QTest::addColumn<QString>("method");
        QTest::addColumn<double>("order");
        QTest::addColumn<double>("hMax");
        QTest::newRow("explicit Euler") << QStringLiteral("explicit Euler") << 1.0 << 1.0 / 32;
        QTest::newRow("semi-implicit Euler") << QStringLiteral("semi-implicit Euler") << 1.0 << 1.0 / 32;
        QTest::newRow("Verlet") << QStringLiteral("Verlet") << 2.0 << 1.0 / 8;
        // Annex II's start x_-1 = x_0 - h v_0 makes Def 3.1 semi-implicit Euler: first order.
        QTest::newRow("Verlet (Annex II start)") << QStringLiteral("Verlet (Annex II start)") << 1.0 << 1.0 / 32;
        QTest::newRow("RK4") << QStringLiteral("RK4") << 4.0 << 1.0 / 4;
    }
    void integratorsConvergeAtTheirOrder()
    {
        QFETCH(QString, method);
        QFETCH(double, order);
        QFETCH(double, hMax);
        const auto r = quickReport("integrators");
        const auto* s = r.find(method.toStdString());
        QVERIFY(s);
        // RK4 reaches rounding level quickly: fit its slope before that.
        const double hMin = order == 4.0 ? 1.0 / 64 : 1.0 / 1024;
        const double p = observedOrder(*s, hMin, hMax);
        QVERIFY2(std::fabs(p - order) < 0.25, qPrintable(QStringLiteral("%1: observed order %2").arg(method).arg(p)));
    }
    // Issue 33, part 5: with Annex II's start Def 3.1 gives the positions of semi-implicit
    // Euler (x_1 = x_0 + h v_0 + h² a_0 for both, the same recurrence after), so the two
    // series agree to rounding; the figures, computed apart (x'' = −x, T = 10): the
    // Annex II start 3.85e-2 at h = 2⁻³ and 1.33e-4 at 2⁻¹¹, the Taylor start 7.45e-3 and
    // 1.13e-7.
    void verletWithAnnexIIStartIsSemiImplicitEuler()
    {
        const auto r = quickReport("integrators");
        const auto [annex, semi, taylor] = seriesOf(r, "Verlet (Annex II start)", "semi-implicit Euler", "Verlet");
        QVERIFY(annex && semi && taylor);
        for (const auto& p : semi->samples)
            QVERIFY2(std::fabs(errorAt(*annex, p.knob) - p.error) <= 1e-6 * p.error, qPrintable(QString::number(p.knob)));
        const auto near = [](double a, double b) { return std::fabs(a - b) <= 0.005 * b; };
        QVERIFY2(near(errorAt(*annex, 1.0 / 8), 3.85e-2), qPrintable(QString::number(errorAt(*annex, 1.0 / 8))));
        QVERIFY2(near(errorAt(*taylor, 1.0 / 8), 7.45e-3), qPrintable(QString::number(errorAt(*taylor, 1.0 / 8))));
        // h = 2⁻¹¹ is past the quick report's finest step: the same run, by hand.
        const auto errorAtEnd = [](bool annexII) {
            const double h = 1.0 / 2048;
            auto a = [](Point x, Point) { return Point(-x.x, -x.y); };
            ParticleState s = annexII ? startParticleAnnexII(Point(1, 0), Point(0, 1), h, a)
                                      : startParticle(Point(1, 0), Point(0, 1), h, a);
            for (long i = 0; i < 10 * 2048; ++i)
                integrate(Integrator::Verlet, s, h, a);
            return std::hypot(s.position.x - std::cos(10.0), s.position.y - std::sin(10.0));
        };
        QVERIFY2(near(errorAtEnd(true), 1.33e-4), qPrintable(QString::number(errorAtEnd(true))));
        QVERIFY2(near(errorAtEnd(false), 1.13e-7), qPrintable(QString::number(errorAtEnd(false))));
    }
    void verletBeatsEulerAtEqualCost()
    {
        // Both cost one evaluation of the acceleration per step: compare at equal h.
        const auto r = quickReport("integrators");
        const auto [euler, verlet] = seriesOf(r, "explicit Euler", "Verlet");
        for (const auto& p : euler->samples)
            if (p.knob <= 0.25)
                QVERIFY2(errorAt(*verlet, p.knob) * 10 < p.error, qPrintable(QString::number(p.knob)));
    }

    void hornerLosesDigitsWhereDeCasteljauDoesNot()
    {
        const auto r = quickReport("bezier-evaluation");
        const auto [casteljau, bernstein, horner] = seriesOf(r, "De Casteljau", "Bernstein sum", "Horner (power basis)");
        QVERIFY(casteljau && bernstein && horner);
        for (const auto& p : casteljau->samples) {
            QVERIFY2(p.error < 1e-13, qPrintable(QString::number(p.knob)));
            QVERIFY(errorAt(*bernstein, p.knob) < 1e-13);
        }
        QVERIFY(errorAt(*horner, 2) < 1e-13); // low degree: fine
        QVERIFY(errorAt(*horner, 30) > 1e-8); // degree 30: digits gone
        QVERIFY(errorAt(*horner, 30) > 1e4 * errorAt(*casteljau, 30));
        QVERIFY(errorAt(*horner, 30) > errorAt(*horner, 10));
    }

    void normalEquationsBreakWhereQrHolds()
    {
        const auto r = quickReport("least-squares");
        const auto [normal, qr, svd] = seriesOf(r, "normal equations", "QR", "SVD");
        QVERIFY(normal && qr && svd);
        for (double n : {2.0, 6.0})
            QVERIFY(errorAt(*normal, n) < 1e-10 && errorAt(*qr, n) < 1e-12);
        // Near degree 25 the normal equations have lost almost every digit (cond(M)² ≈ 1e16)…
        QVERIFY2(errorAt(*normal, 26) > 1e-3, qPrintable(QString::number(errorAt(*normal, 26))));
        QVERIFY(errorAt(*normal, 26) > 1e5 * errorAt(*qr, 26));
        // …and by degree 30 the answer is wrong, while QR and SVD keep about seven digits.
        QVERIFY2(errorAt(*normal, 30) > 0.1, qPrintable(QString::number(errorAt(*normal, 30))));
        QVERIFY2(errorAt(*qr, 30) < 1e-6, qPrintable(QString::number(errorAt(*qr, 30))));
        QVERIFY(errorAt(*svd, 30) < 1e-6);
    }

    void samplingErrorFallsLikeOneOverNSquared()
    {
        const auto r = quickReport("curve-sampling");
        const auto [uniform, adaptive] = seriesOf(r, "uniform", "adaptive");
        QVERIFY(uniform && adaptive);
        const double p = observedOrder(*uniform, 17, 1e9);
        QVERIFY2(std::fabs(p + 2) < 0.2, qPrintable(QString::number(p)));
        // Adaptive sampling reaches each of its errors with fewer points than uniform needs.
        for (const auto& a : adaptive->samples) {
            if (a.knob < 30)
                continue;
            double uniformPoints = 0;
            for (const auto& u : uniform->samples)
                if (u.error <= a.error) {
                    uniformPoints = u.knob;
                    break;
                }
            if (uniformPoints > 0)
                QVERIFY2(a.knob < uniformPoints, qPrintable(QStringLiteral("%1 vs %2").arg(a.knob).arg(uniformPoints)));
        }
    }

    // The sampling reports teach "fewer points for the same error": their plot is against the
    // number of points, and there adaptive's line lies left of uniform's at every error they share.
    void samplingReportsPlotAdaptiveLeftOfUniform_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("uniformMethod");
        QTest::newRow("curve-sampling") << QStringLiteral("curve-sampling") << QStringLiteral("uniform");
        QTest::newRow("catmull-rom-sampling")
            << QStringLiteral("catmull-rom-sampling") << QStringLiteral("uniform t per segment");
    }
    void samplingReportsPlotAdaptiveLeftOfUniform()
    {
        QFETCH(QString, name);
        QFETCH(QString, uniformMethod);
        const auto r = quickReport(name.toStdString().c_str());
        QVERIFY(r.xAxis == WorkPrecisionAxis::Knob);
        QCOMPARE(QString::fromStdString(r.knob), QStringLiteral("points"));
        const auto* uniform = r.find(uniformMethod.toStdString());
        const auto* adaptive = r.find("adaptive");
        QVERIFY(uniform && adaptive);
        int compared = 0;
        for (const auto& a : adaptive->samples) {
            // Uniform's points at adaptive's error, interpolated log–log between its markers.
            for (std::size_t i = 0; i + 1 < uniform->samples.size(); ++i) {
                const auto& u0 = uniform->samples[i];
                const auto& u1 = uniform->samples[i + 1];
                if (!(u0.error >= a.error && a.error > u1.error))
                    continue;
                const double s = std::log(u0.error / a.error) / std::log(u0.error / u1.error);
                const double uniformPoints = u0.knob * std::pow(u1.knob / u0.knob, s);
                QVERIFY2(
                    a.knob < uniformPoints,
                    qPrintable(
                        QStringLiteral("error %1: adaptive %2 points, uniform %3").arg(a.error).arg(a.knob).arg(uniformPoints)));
                ++compared;
            }
        }
        QVERIFY(compared >= 3);
        // The CSV says which column the plot's x axis is.
        const std::string csv = workPrecisionCsv(r, {});
        QVERIFY(csv.find("\n# x axis: knob\n") != std::string::npos);
        QVERIFY(workPrecisionCsv(quickReport("integrators"), {}).find("\n# x axis: seconds\n") != std::string::npos);
    }

    // The Catmull-Rom report: more points, smaller error, for both methods; uniform falls like 1/N².
    void catmullRomSamplingErrorFallsAsPointsGrow()
    {
        const auto r = quickReport("catmull-rom-sampling");
        QCOMPARE(r.series.size(), std::size_t(2));
        for (const auto& s : r.series) {
            QVERIFY(s.samples.size() >= 5);
            for (std::size_t i = 1; i < s.samples.size(); ++i) {
                QVERIFY2(s.samples[i].knob > s.samples[i - 1].knob, s.method.c_str());
                QVERIFY2(s.samples[i].error < s.samples[i - 1].error,
                         qPrintable(
                             QStringLiteral("%1 at %2 points").arg(QString::fromStdString(s.method)).arg(s.samples[i].knob)));
            }
        }
        const double p = observedOrder(*r.find("uniform t per segment"), 40, 1e9);
        QVERIFY2(std::fabs(p + 2) < 0.2, qPrintable(QString::number(p)));
    }

    void substepsTightenTheConstraints()
    {
        const auto r = quickReport("soft-body");
        const auto [area, edges, seed] = seriesOf(r, "XPBD area", "XPBD edge lengths", "seed area (Annex II)");
        QVERIFY(area && edges && seed);
        QVERIFY(errorAt(*area, 8) < errorAt(*area, 1));
        QVERIFY(errorAt(*edges, 8) < errorAt(*edges, 1) / 4);
        QVERIFY(errorAt(*area, 8) < seed->samples.front().error / 10);
    }

    void cancelling()
    {
        WorkPrecisionOptions options;
        options.quick = true;
        options.minSecondsPerPoint = 1e-6;
        int calls = 0;
        options.progress = [&calls](double) { return ++calls < 3; };
        for (const auto& name : workPrecisionReportNames()) {
            calls = 0;
            auto r = runWorkPrecisionReport(name, options);
            QVERIFY2(!r.ok(), name.c_str());
            QCOMPARE(r.error().code, ErrorCode::Cancelled);
        }
        QVERIFY(!runWorkPrecisionReport("nope").ok());
    }

    void csvHasContextAndOneRowPerSample()
    {
        const auto r = quickReport("integrators");
        const std::string csv = workPrecisionCsv(r, {"machine: test", "build: Release"});
        const QStringList lines = QString::fromStdString(csv).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QVERIFY(lines.contains(QStringLiteral("# machine: test")));
        QVERIFY(lines.contains(QStringLiteral("# build: Release")));
        const int header = static_cast<int>(lines.indexOf(QStringLiteral("method,knob,error,seconds")));
        QVERIFY(header > 0);
        std::size_t samples = 0;
        for (const auto& s : r.series)
            samples += s.samples.size();
        QCOMPARE(static_cast<std::size_t>(lines.size() - header - 1), samples);
        QVERIFY(lines.last().startsWith(QStringLiteral("RK4,")));
    }

    // arc-length: the adaptive rule meets its requested tolerance on every curve (and 1e-12 on
    // the cusp); one 24-point rule is off by far more than 1e-12 on the cusp curve; every
    // method's error falls from its coarsest to its finest setting.
    void arcLengthAdaptiveBeatsFixedRules()
    {
        const auto r = quickReport("arc-length");
        const auto* adaptive = r.find("adaptive Gauss–Legendre");
        QVERIFY(adaptive && adaptive->samples.size() >= 10);
        for (const auto& s : adaptive->samples)
            QVERIFY2(s.error <= std::max(10 * s.knob, 1e-14), qPrintable(QString::number(s.knob)));
        for (const char* m : {"adaptive Gauss–Legendre", "Gauss–Legendre 24 points", "Simpson", "polyline"}) {
            const auto* series = r.find(m);
            QVERIFY(series && series->samples.size() >= 5);
            QVERIFY2(series->samples.back().error < series->samples.front().error / 100, m);
        }
        // Polyline: O(1/m²), so the last doublings each gain about 4 (between 3 and 5).
        const auto* polyline = r.find("polyline");
        const auto& ps = polyline->samples;
        const double ratio = ps[ps.size() - 2].error / ps.back().error;
        QVERIFY2(ratio > 3 && ratio < 5, qPrintable(QString::number(ratio)));

        for (const auto& c : reports::arcLengthReportCurves()) {
            if (c.name != "cusp")
                continue;
            QCOMPARE(c.length, 2 * std::sqrt(2.0) - 1);
            QVERIFY(std::abs(arcLength(c.points) - c.length) <= 1e-12 * c.length);
            const double one = reports::gaussLegendre24Length(c.points, 1);
            QVERIFY(std::abs(one - c.length) > 1e-4 * c.length); // bezier-js's error, about 1e-3
            QVERIFY(std::abs(reports::gaussLegendre24Length(c.points, 15) - c.length) > 1e-12 * c.length);
        }
        // The adaptive rule at 1e-15 agrees with every reference: the exact lengths and the long
        // double one of the degree-10 curve.
        for (const auto& c : reports::arcLengthReportCurves())
            QVERIFY(std::abs(arcLength(c.points, 0, 1, 1e-15) - c.length) <= 1e-14 * c.length);
    }

    // bspline-evaluation: de Boor, the Bézier extraction with De Casteljau and the basis sum are
    // all convex combinations, so each stays within a few rounding errors of the exact value
    // (1e-14 of max |P_i|, some fifty ulps) at every degree from 1 to 10; an unstable method —
    // Horner's in bezier-evaluation loses that by degree 10 — would not.
    void bsplineEvaluationStaysAtRoundingLevel()
    {
        const auto r = quickReport("bspline-evaluation");
        for (const char* m : {"de Boor", "Bézier extraction + De Casteljau", "basis functions × points"}) {
            const auto* series = r.find(m);
            QVERIFY2(series && series->samples.size() == 10, m);
            for (int p = 1; p <= 10; ++p)
                QVERIFY2(errorAt(*series, p) <= 1e-14,
                         qPrintable(QStringLiteral("%1 at degree %2").arg(QString::fromUtf8(m)).arg(p)));
        }
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestWorkPrecision)
#include "test_work_precision.moc"
