// The plots over time (docs/plots-over-time.md): the energy bookkeeping of the stable
// solver, the series' rows, and the phase plot of the pendulums.
#include "core/base/math_constants.h"
#include "core/softbody/recorded_run.h"
#include "core/softbody/scenes/scene.h"
#include "core/softbody/simulation.h"
#include "core/softbody/simulation_series.h"
#include "core/softbody/xpbd/xpbd_world.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>

using namespace granota;

namespace {

std::unique_ptr<Simulation> make(const std::string& scene, SolverKind solver, std::initializer_list<const char*> settings = {},
                                 std::vector<double> chain = {})
{
    auto spec = loadScene(scene);
    if (!spec)
        qFatal("%s", spec.error().message.c_str());
    if (!chain.empty())
        spec->chain = chain;
    for (const char* s : settings) {
        auto ok = applySetting(*spec, s);
        if (!ok)
            qFatal("%s: %s", s, ok.error().message.c_str());
    }
    auto sim = Simulation::create(*spec, solver);
    if (!sim)
        qFatal("%s", sim.error().message.c_str());
    return std::move(sim).value();
}

/// The area of the frog's starting polygon (10 sides, r = 120): as target, the body starts
/// at its rest shape and the area constraint does nothing.
constexpr const char* kTargetIsThePolygon = "target_area=42320.53816505807";

/// Zero crossings of θ − mean(θ) going up: the period of an oscillation, in steps.
double meanPeriod(const std::vector<double>& theta)
{
    double mean = 0;
    for (double t : theta)
        mean += t;
    mean /= double(theta.size());
    std::vector<double> ups;
    for (std::size_t i = 1; i < theta.size(); ++i) {
        const double a = theta[i - 1] - mean, b = theta[i] - mean;
        if (a < 0 && b >= 0)
            ups.push_back(double(i - 1) + a / (a - b));
    }
    if (ups.size() < 2)
        return 0;
    return (ups.back() - ups.front()) / double(ups.size() - 1);
}

} // namespace

class TestEnergySeries : public QObject {
    Q_OBJECT
private slots:
    // A body gliding through empty space (no gravity, no contacts) with friction f per axis:
    // its kinetic energy falls by f² a step, and all of it must show as damping loss.
    void dampingAccountsForTheDrop_data()
    {
        QTest::addColumn<QString>("friction");
        QTest::newRow("f = 0.98") << QStringLiteral("friction=0.98,0.98");
        QTest::newRow("f = 0.98, 0.97 (per axis)") << QStringLiteral("friction=0.98,0.97");
        QTest::newRow("f = 0.9, 0.99") << QStringLiteral("friction=0.9,0.99");
    }
    void dampingAccountsForTheDrop()
    {
        QFETCH(QString, friction);
        const QByteArray f = friction.toLatin1();
        auto s = make("tuned", SolverKind::Stable, {"gravity=0,0", f.constData(), "v0=2,-1.5", kTargetIsThePolygon});
        SeriesRecorder series;
        const double e0 = series.record(*s).total;
        QCOMPARE(e0, 10 * 0.5 * (4 + 2.25)); // ten vertices of mass 1 at (2, −1.5) px/step
        for (int i = 0; i < 600; ++i) {
            s->step();
            const SeriesSample& x = series.record(*s);
            QCOMPARE(x.contacts, 0);
            QVERIFY2(std::abs(x.otherLoss.value()) <= 1e-9 * e0,
                     qPrintable(
                         QStringLiteral("step %1: damping %2, drop %3").arg(x.step).arg(*x.dampingLoss).arg(e0 - x.total)));
        }
        const SeriesSample& last = series.samples().back();
        // Per axis the speed after n steps is fⁿ v: the loss is known in closed form.
        const double fx = friction.section(QLatin1Char('='), 1).section(QLatin1Char(','), 0, 0).toDouble();
        const double fy = friction.section(QLatin1Char(','), 1).toDouble();
        const double expected = 10 * 0.5 * (4 * (1 - std::pow(fx, 1200)) + 2.25 * (1 - std::pow(fy, 1200)));
        QVERIFY2(std::abs(*last.dampingLoss - expected) <= 1e-9 * e0,
                 qPrintable(QStringLiteral("%1 against %2").arg(*last.dampingLoss, 0, 'g', 15).arg(expected, 0, 'g', 15)));
    }

    // Friction 1, no gravity: a body spinning as it drifts. The solver never makes energy,
    // and what it loses (XPBD's own dissipation, "other" in the plot) is bounded and falls
    // like 1/n with the substeps n: at most 6 % in 10 s at the default 8 substeps.
    void withoutFrictionOrGravityTheTotalHolds()
    {
        double lost[2] = {0, 0};
        const int substeps[2] = {8, 32};
        for (int k = 0; k < 2; ++k) {
            XpbdParams p;
            p.substeps = substeps[k];
            p.gravity = Point(0, 0);
            p.damping = Point(1, 1);
            XpbdWorld world = XpbdWorld::create(p).value();
            const int b = world.addRegularBody(Point(640, 360), 120, 10, 42320.53816505807, Point(0, 0)).value();
            std::vector<Point> v;
            for (const Point& q : world.bodyVertices(b)) // 0.02 rad/step about the centre, drifting
                v.push_back(Point(0.5 - 0.02 * (q.y - 360), -0.3 + 0.02 * (q.x - 640)));
            QVERIFY(world.setBodyVelocities(b, v).ok());
            const auto total = [&] { return world.kineticEnergy() + world.gravityEnergy() + world.elasticEnergy(); };
            const double e0 = total();
            for (int i = 0; i < 600; ++i) {
                world.step();
                QVERIFY2(total() <= e0 * (1 + 1e-12), qPrintable(QStringLiteral("step %1: %2 > %3").arg(i).arg(total()).arg(e0)));
                QCOMPARE(world.contactCount(), 0);
            }
            QCOMPARE(world.dampingLoss(), 0.0);
            lost[k] = (e0 - total()) / e0;
            qInfo("%d substeps: %.3f %% of the energy lost in 600 steps", substeps[k], 100 * lost[k]);
        }
        QVERIFY(lost[0] > 0 && lost[0] <= 0.06);
        QVERIFY(lost[1] <= lost[0] / 3);
    }

    // The series starts again when the run does (a reset), and keeps only its capacity.
    void seriesRestartsWithTheRun()
    {
        auto s = make("frog", SolverKind::Stable);
        SeriesRecorder series(50);
        for (int i = 0; i < 120; ++i) {
            series.record(*s);
            s->step();
        }
        QCOMPARE(series.samples().size(), std::size_t(50));
        QCOMPARE(series.samples().front().step, 70L);
        QVERIFY(*series.samples().back().dampingLoss > 0); // the frog falls through air of f = 0.95
        auto again = make("frog", SolverKind::Stable);
        series.record(*again);
        QCOMPARE(series.samples().size(), std::size_t(1));
        QCOMPARE(series.samples().front().dampingLoss.value(), 0.0);
        QCOMPARE(series.samples().front().otherLoss.value(), 0.0);
    }

    // Rewind (docs/rewind.md): a run gone back to step 120 drops the later samples, and
    // running on from there records the same rows again, losses and angular velocities
    // included (they follow from the samples kept).
    void seriesGoesBackWithTheRun_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<int>("solver");
        QTest::newRow("pendulum-limits, stable") << "pendulum-limits" << int(SolverKind::Stable);
        QTest::newRow("frog, stable") << "frog" << int(SolverKind::Stable);
        QTest::newRow("frog, seed") << "frog" << int(SolverKind::Seed);
    }
    void seriesGoesBackWithTheRun()
    {
        QFETCH(QString, scene);
        QFETCH(int, solver);
        auto run = RecordedRun::start(*loadScene(scene.toStdString()), SolverKind(solver), 50);
        SeriesRecorder series;
        series.record(run->simulation());
        for (int i = 0; i < 200; ++i) {
            if (i == 30)
                run->press(Point(640, 300));
            if (i == 30 || i == 60)
                run->move(Point(i == 30 ? 700 : 500, 250));
            if (i == 90)
                run->release();
            run->step();
            series.record(run->simulation());
        }
        std::vector<std::string> rows;
        for (const SeriesSample& s : series.samples())
            rows.push_back(seriesCsvRow(s, series.phaseLinks()));
        QCOMPARE(rows.size(), std::size_t(201));
        QVERIFY(run->seek(120).ok());
        series.truncateAfter(120);
        QCOMPARE(series.samples().size(), std::size_t(121));
        QCOMPARE(series.samples().back().step, 120L);
        while (run->stepCount() < 200) {
            run->step();
            series.record(run->simulation());
        }
        QCOMPARE(series.samples().size(), std::size_t(201));
        for (std::size_t k = 0; k < rows.size(); ++k)
            QCOMPARE(seriesCsvRow(series.samples()[k], series.phaseLinks()), rows[k]);
        series.truncateAfter(-1); // nothing kept: the series starts again
        QVERIFY(series.samples().empty());
        series.record(run->simulation());
        QCOMPARE(series.samples().size(), std::size_t(1));
    }

    // The plots per body: each body's readouts (its vertices, its constraints, the legs that
    // hang from it) add up to the scene's — energies and losses summed, contacts counted in
    // the same substep, the area error their mean, the stretch their largest — through a
    // run with a grab, collisions and the floor.
    void bodyReadoutsAddUpToTheScene_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<int>("solver");
        QTest::addColumn<QString>("setting");
        QTest::newRow("many-bodies, stable") << "many-bodies" << int(SolverKind::Stable) << "bodies=6";
        QTest::newRow("many-bodies, seed") << "many-bodies" << int(SolverKind::Seed) << "bodies=6";
        QTest::newRow("shapes, stable") << "shapes" << int(SolverKind::Stable) << "";
        QTest::newRow("frog, stable (legs are the body's)") << "frog" << int(SolverKind::Stable) << "";
        QTest::newRow("frog, seed") << "frog" << int(SolverKind::Seed) << "";
        QTest::newRow("springs, seed (a stage)") << "springs" << int(SolverKind::Seed) << "";
        QTest::newRow("pendulum-chain, stable (no bodies)") << "pendulum-chain" << int(SolverKind::Stable) << "";
    }
    void bodyReadoutsAddUpToTheScene()
    {
        QFETCH(QString, scene);
        QFETCH(int, solver);
        QFETCH(QString, setting);
        const QByteArray set = setting.toLatin1();
        auto s = make(scene.toStdString(), SolverKind(solver),
                      setting.isEmpty() ? std::initializer_list<const char*>{}
                                        : std::initializer_list<const char*>{set.constData()});
        const bool stable = SolverKind(solver) == SolverKind::Stable;
        const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-9 * (1 + std::abs(a) + std::abs(b)); };
        std::vector<Readouts> bodies;
        int touching = 0, differing = 0;
        for (int i = 0; i <= 300; ++i) {
            if (i == 30)
                s->press(Point(640, 300));
            if (i == 30 || i == 60)
                s->move(Point(i == 30 ? 700 : 500, 250));
            if (i == 90)
                s->release();
            s->step();
            if (i % 10 != 0)
                continue;
            const Readouts r = s->readouts();
            s->bodyReadouts(bodies);
            QCOMPARE(int(bodies.size()), s->bodyCount());
            if (bodies.empty())
                continue;
            Readouts sum;
            double stretch = 0;
            for (const Readouts& b : bodies) {
                sum.kineticEnergy += b.kineticEnergy;
                sum.potentialEnergy += b.potentialEnergy;
                sum.areaErrorPercent += b.areaErrorPercent / double(bodies.size());
                stretch = std::max(stretch, b.maxStretch);
                sum.contacts += b.contacts;
                QCOMPARE(b.elasticEnergy.has_value(), stable);
                QCOMPARE(b.dampingLoss.has_value(), stable);
                sum.elasticEnergy = sum.elasticEnergy.value_or(0) + b.elasticEnergy.value_or(0);
                sum.dampingLoss = sum.dampingLoss.value_or(0) + b.dampingLoss.value_or(0);
                touching += b.contacts > 0 && b.contacts < r.contacts;
            }
            const QString at = QStringLiteral("step %1").arg(s->stepCount());
            QVERIFY2(near(sum.kineticEnergy, r.kineticEnergy), qPrintable(at));
            QVERIFY2(near(sum.potentialEnergy, r.potentialEnergy), qPrintable(at));
            QVERIFY2(near(sum.areaErrorPercent, r.areaErrorPercent), qPrintable(at));
            QCOMPARE(stretch, r.maxStretch);
            QCOMPARE(sum.contacts, r.contacts);
            if (stable) {
                QVERIFY2(near(*sum.elasticEnergy, *r.elasticEnergy), qPrintable(at));
                QVERIFY2(near(*sum.dampingLoss, *r.dampingLoss), qPrintable(at));
            }
            differing += bodies.size() > 1 && bodies.front().kineticEnergy != bodies.back().kineticEnergy;
        }
        if (scene == "many-bodies") {
            QVERIFY(differing > 10);               // each body has its own values, not a share of the sum
            QVERIFY(stable ? touching > 0 : true); // the pile: some bodies touch, not all of them
        }
    }

    // Each body glides alone through empty space with friction f: what it loses is what
    // damping took from it, body by body.
    void dampingAccountsForEachBodysDrop()
    {
        const double polygon = 0.5 * 10 * 40 * 40 * std::sin(2 * kPi / 10); // r = 40, at its rest shape
        const QByteArray target = "target_area=" + QByteArray::number(polygon, 'g', 17);
        auto s = make("many-bodies", SolverKind::Stable,
                      {"bodies=4", "gravity=0,0", "friction=0.98,0.97", "v0=2,-1.5", target.constData()});
        SeriesRecorder series;
        series.record(*s);
        QCOMPARE(series.bodies(), 4);
        for (int i = 0; i < 60; ++i) {
            s->step();
            const SeriesSample& x = series.record(*s);
            QCOMPARE(x.contacts, 0);
            QCOMPARE(x.bodies.size(), std::size_t(4));
            double damping = 0;
            for (const SeriesValues& b : x.bodies) {
                QVERIFY2(std::abs(*b.otherLoss) <= 1e-9 * (x.total + *x.dampingLoss),
                         qPrintable(QStringLiteral("step %1: %2").arg(x.step).arg(*b.otherLoss)));
                damping += *b.dampingLoss;
            }
            QVERIFY(*x.dampingLoss > 0);
            QVERIFY(std::abs(damping - *x.dampingLoss) <= 1e-12 * *x.dampingLoss);
        }
    }

    // Every body's values are kept in the last samples only (SeriesRecorder's budget), and
    // the CSV row of a body holds that body's values in the scene's columns.
    void seriesKeepsEachBodyInTheLastSamples()
    {
        auto s = make("many-bodies", SolverKind::Stable, {"bodies=4"});
        SeriesRecorder series(300, 4 * 100);
        for (int i = 0; i < 250; ++i) {
            series.record(*s);
            s->step();
        }
        const SeriesSample& last = series.record(*s);
        QCOMPARE(series.bodies(), 4);
        QCOMPARE(series.bodySamplesKept(), std::size_t(100));
        const auto& samples = series.samples();
        QCOMPARE(samples.size(), std::size_t(251));
        for (std::size_t k = 0; k < samples.size(); ++k)
            QCOMPARE(samples[k].bodies.size(), k + 100 >= samples.size() ? std::size_t(4) : std::size_t(0));
        std::vector<Readouts> bodies;
        s->bodyReadouts(bodies);
        QCOMPARE(last.bodies[2].kinetic, bodies[2].kineticEnergy);
        QCOMPARE(last.bodies[2].contacts, bodies[2].contacts);
        QVERIFY(last.bodies[2].kinetic != last.bodies[0].kinetic);
        const QList<QByteArray> fields = QByteArray::fromStdString(seriesCsvRow(last, 0, 2)).split(',');
        QCOMPARE(fields.size(), 11);
        QCOMPARE(fields[0].toLong(), last.step);
        QCOMPARE(fields[2].toDouble(), last.bodies[2].kinetic);
        QCOMPARE(fields[5].toDouble(), last.bodies[2].total);
        QCOMPARE(QByteArray::fromStdString(seriesCsvRow(last, 0, -1)), QByteArray::fromStdString(seriesCsvRow(last, 0)));
        QCOMPARE(seriesValuesOf(samples.front(), 2), nullptr); // let go: too old
        QCOMPARE(seriesValuesOf(last, 4), nullptr);            // no such body
        QCOMPARE(seriesValuesOf(last, -1), static_cast<const SeriesValues*>(&last));

        SeriesRecorder sums(300, 0); // no values per body
        sums.setBodiesAsked(true);
        sums.record(*s);
        QCOMPARE(sums.bodies(), 4);
        QVERIFY(!sums.keepsBodies() && !sums.bodiesAsked());
        QVERIFY(sums.samples().back().bodies.empty());
    }

    // A scene of more bodies than kBodiesKeptUnasked keeps each body's values only from when
    // they are asked for, each body's losses counted from there; asked, a new run of it keeps
    // them from its start.
    void manyBodiesAreKeptOnceAsked()
    {
        const int many = SeriesRecorder::kBodiesKeptUnasked + 1;
        const QByteArray bodies = "bodies=" + QByteArray::number(many);
        auto s = make("many-bodies", SolverKind::Stable, {bodies.constData()});
        SeriesRecorder series;
        for (int i = 0; i < 20; ++i) {
            series.record(*s);
            s->step();
        }
        QCOMPARE(series.bodies(), many);
        QVERIFY(!series.keepsBodies());
        QVERIFY(series.samples().back().bodies.empty());
        series.setBodiesAsked(true);
        const SeriesSample& asked = series.record(*s);
        QVERIFY(series.keepsBodies());
        QCOMPARE(series.bodiesKeptFrom(), 20L);
        QCOMPARE(asked.bodies.size(), std::size_t(many));
        QCOMPARE(*asked.bodies[7].dampingLoss, 0.0); // from the moment asked
        QCOMPARE(*asked.bodies[7].otherLoss, 0.0);
        QVERIFY(*asked.dampingLoss > 0); // the scene's, from the series' start
        for (int i = 0; i < 30; ++i) {
            s->step();
            series.record(*s);
        }
        QVERIFY(*series.samples().back().bodies[7].dampingLoss > 0);
        QVERIFY(series.samples()[19].bodies.empty());
        auto again = make("many-bodies", SolverKind::Stable, {bodies.constData()});
        series.record(*again); // a new run: asked, kept from its start
        QVERIFY(series.keepsBodies());
        QCOMPARE(series.bodiesKeptFrom(), 0L);
        QCOMPARE(series.samples().back().bodies.size(), std::size_t(many));
        SeriesRecorder fresh;
        fresh.record(*again);
        QVERIFY(!fresh.keepsBodies());
    }

    // The seed's springs and area are corrections, not forces: no elastic energy and no
    // losses to report, and the CSV leaves those fields empty rather than writing 0.
    void seedHasNoElasticEnergy()
    {
        auto s = make("frog", SolverKind::Seed);
        SeriesRecorder series;
        s->step();
        const SeriesSample& x = series.record(*s);
        QVERIFY(!x.elastic && !x.dampingLoss && !x.otherLoss);
        QCOMPARE(x.total, x.kinetic + x.gravity);
        const QStringList fields = QString::fromStdString(seriesCsvRow(x, 0)).split(QLatin1Char(','));
        const QStringList header = QString::fromStdString(seriesCsvHeader(0)).split(QLatin1Char(','));
        QCOMPARE(fields.size(), header.size());
        QCOMPARE(fields[header.indexOf(QStringLiteral("elastic"))], QString());
        QCOMPARE(fields[header.indexOf(QStringLiteral("damping_loss"))], QString());
        QCOMPARE(fields[header.indexOf(QStringLiteral("step"))], QStringLiteral("1"));
        QCOMPARE(fields[header.indexOf(QStringLiteral("time_s"))].toDouble(), 1.0 / kStepsPerSecond);
    }

    void linkAngleFollowsTheSeed()
    {
        // A joint at parent + (−sin θ, cos θ)·L (Annex II's limits place it so).
        for (double theta : {0.0, 0.5, -1.2, 3.0, -3.0}) {
            const Point from(100, 50);
            const Point to(from.x - std::sin(theta) * 80, from.y + std::cos(theta) * 80);
            QVERIFY(std::abs(linkAngle(from, to) - theta) < 1e-12);
        }
    }

    // A free pendulum of one link, nudged: the phase plot's orbit has the small-angle period
    // T = 2π √(L/g) and, being a near-ellipse, ω_max = θ_max · 2π/T.
    void pendulumPhaseHasTheSmallAnglePeriod()
    {
        auto s = make("pendulum", SolverKind::Stable, {"friction=1,1"}, {80});
        const Point clau = s->scene().params.center;
        QVERIFY(s->press(clau + Point(6, 0))); // the nail jumps 6 px: the link is 4.3° off
        SeriesRecorder series;
        std::vector<double> theta, omega;
        for (int i = 0; i < 1300; ++i) {
            s->step();
            const SeriesSample& x = series.record(*s);
            QCOMPARE(series.phaseLinks(), 1);
            theta.push_back(x.angles.at(0));
            if (!x.angularVelocities.empty())
                omega.push_back(x.angularVelocities[0]);
        }
        const double g = s->scene().params.gravity.y, length = 80;
        const double expected = 2 * kPi * std::sqrt(length / g);
        const double period = meanPeriod(theta);
        qInfo("period %.4f steps, small-angle %.4f steps", period, expected);
        QVERIFY2(std::abs(period - expected) <= 0.005 * expected, qPrintable(QString::number(period)));
        double thetaMax = 0, omegaMax = 0;
        for (double t : theta)
            thetaMax = std::max(thetaMax, std::abs(t));
        for (double w : omega)
            omegaMax = std::max(omegaMax, std::abs(w));
        QVERIFY(thetaMax > 0.06 && thetaMax < 0.09);
        QVERIFY2(std::abs(omegaMax - thetaMax * 2 * kPi / expected) <= 0.03 * omegaMax,
                 qPrintable(QStringLiteral("ω_max %1, θ_max·2π/T %2").arg(omegaMax).arg(thetaMax * 2 * kPi / expected)));
    }

    // §4.15: with the shoulder limited to [0, π] the orbit is clipped at θ = 0; without the
    // limit the same swing goes past it.
    void angleLimitsClipTheOrbit()
    {
        for (SolverKind solver : {SolverKind::Seed, SolverKind::Stable}) {
            double lowest[2] = {0, 0};
            int k = 0;
            for (const char* scene : {"pendulum", "pendulum-limits"}) {
                auto s = make(scene, solver);
                const Point clau = s->scene().params.center;
                SeriesRecorder series;
                s->press(clau);
                for (int i = 0; i < 400; ++i) {
                    s->move(clau + Point(i < 60 ? 40.0 * std::sin(i / 6.0) : 0.0, 0));
                    s->step();
                    lowest[k] = std::min(lowest[k], series.record(*s).angles.at(0));
                }
                ++k;
            }
            qInfo("%s: lowest shoulder angle %.4f free, %.4f limited", solverName(solver).c_str(), lowest[0], lowest[1]);
            QVERIFY(lowest[0] < -0.2);
            QVERIFY(lowest[1] >= -0.02);
        }
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestEnergySeries)
#include "test_energy_series.moc"
