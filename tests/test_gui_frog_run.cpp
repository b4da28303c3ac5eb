// Issue 35, part 1: the frog's run is a model, FrogRun (ui/frog/frog_run.h), with no widget.
// Here a run alone, with no canvas: whether the seed's body has blown up is decided at each
// step, as the clock's frames step it (before FrogRun the canvas decided it in its text
// panel's refresh, four times a second, so a frame run by runFrame() left it unsaid); going
// back says it is whole again; the clock runs only while running and shown.
#include "core/softbody/scenes/scene.h"
#include "core/softbody/simulation.h"
#include "ui/frog/frog_run.h"

#include <QSignalSpy>
#include <QTest>
#include "tests/test_main.h"

using granota::SolverKind;
using granota::ui::FrogRun;

class TestGuiFrogRun : public QObject {
    Q_OBJECT

    /// §4.5's `area` stage on the seed with velmax 1000: it blows up within 300 steps
    /// (test_gui_frog, seedExplosionSaysPressReset).
    static std::unique_ptr<granota::Simulation> explodingSeed()
    {
        auto scene = granota::loadScene("area");
        if (!scene)
            return nullptr;
        scene->params.velmax = 1000;
        auto sim = granota::Simulation::create(*scene, SolverKind::Seed);
        return sim ? std::move(sim).value() : nullptr;
    }

private slots:
    void blownUpIsDecidedAtEachFrame()
    {
        FrogRun run;
        auto sim = explodingSeed();
        QVERIFY(sim);
        const double start = sim->readouts().areaErrorPercent;
        run.setSimulation(std::move(sim));
        run.setRunning(false);
        QVERIFY(!run.blownUp());
        QSignalSpy said(&run, &FrogRun::blownUpChanged);
        int changes = 0;
        bool was = false;
        for (int frame = 0; frame < 300; ++frame) {
            run.runFrame(); // one frame of the clock: one step at 1× speed
            // Expected from the simulation's own readout, with the core's rule.
            const bool expected = granota::blownUp(run.simulation()->readouts().areaErrorPercent, start);
            QCOMPARE(run.blownUp(), expected);
            changes += expected != was ? 1 : 0;
            was = expected;
        }
        QVERIFY(was); // it did blow up
        QCOMPARE(said.count(), changes);
        QCOMPARE(said.first().first().toBool(), true);
        // Back to the start: whole again, and said so.
        QVERIFY(run.seek(0));
        QVERIFY(!run.blownUp());
        QCOMPARE(said.last().first().toBool(), false);
    }

    void theClockRunsOnlyRunningAndShown()
    {
        FrogRun run;
        auto sim = explodingSeed();
        QVERIFY(sim);
        run.setSimulation(std::move(sim));
        QVERIFY(run.running());
        QVERIFY(!run.animating()); // no view shows it yet
        run.setShown(true);
        QVERIFY(run.animating());
        run.setRunning(false);
        QVERIFY(!run.animating());
        run.setRunning(true);
        QVERIFY(run.animating());
        run.setShown(false);
        QVERIFY(!run.animating());
    }

    void aStepIsRecordedAndSeriesSampled()
    {
        FrogRun run;
        auto sim = explodingSeed();
        QVERIFY(sim);
        run.setSimulation(std::move(sim));
        run.setRecordingSeries(true);
        QSignalSpy stepped(&run, &FrogRun::stepped), timeline(&run, &FrogRun::timelineChanged);
        for (int i = 0; i < 5; ++i)
            run.step();
        QCOMPARE(stepped.count(), 5);
        QCOMPARE(timeline.count(), 5);
        QCOMPARE(run.recordedSteps(), 5L);
        QCOMPARE(run.series().samples().size(), std::size_t(6)); // step 0 and one a step
        QCOMPARE(run.series().samples().back().step, 5L);
    }
};

GRANOTA_TEST_MAIN(TestGuiFrogRun)
#include "test_gui_frog_run.moc"
