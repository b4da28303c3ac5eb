// The speeds of the Frog tab (StepPacer): steps per frame at ⅛ … 4 times real time, and
// what a step heavier than a frame leaves of them.
#include "core/softbody/step_pacer.h"

#include <QtTest>
#include "tests/test_main.h"

using namespace granota;

class TestStepPacer : public QObject {
    Q_OBJECT
private slots:
    void stepsInAWhile_data()
    {
        QTest::addColumn<double>("speed");
        for (double s : StepPacer::kSpeeds)
            QTest::newRow(qPrintable(QString::number(s))) << s;
    }
    void stepsInAWhile()
    {
        QFETCH(double, speed);
        StepPacer pacer;
        QVERIFY(pacer.setSpeed(speed));
        pacer.setWork(10, 24000);
        int steps = 0, most = 0;
        for (int frame = 0; frame < 96; ++frame) {
            const int n = pacer.stepsThisFrame();
            steps += n;
            most = std::max(most, n);
        }
        QCOMPARE(steps, int(96 * speed)); // 96 frames: 12 steps at ⅛, 384 at 4×
        QCOMPARE(most, speed > 1 ? int(speed) : 1);
        QCOMPARE(pacer.effectiveSpeed(), speed);
    }
    void onlyTheOfferedSpeeds()
    {
        StepPacer pacer;
        for (double bad : {0.0, 3.0, -1.0, 0.3, 8.0, std::nan("")})
            QVERIFY(!pacer.setSpeed(bad));
        QCOMPARE(pacer.speed(), 1.0);
    }
    void heavyStepsSlowEverything()
    {
        StepPacer pacer;
        pacer.setWork(80000, 24000); // 4 frames of work a step
        QCOMPARE(pacer.framesPerStep(), 4);
        QVERIFY(pacer.setSpeed(0.5));
        QCOMPARE(pacer.framesPerStep(), 8);
        QVERIFY(pacer.setSpeed(4));
        QCOMPARE(pacer.framesPerStep(), 4);
        QCOMPARE(pacer.stepsPerFrame(), 1); // never more than one heavy step in a frame
        pacer.setWork(8000, 24000);         // 3 steps fit a frame
        QCOMPARE(pacer.stepsPerFrame(), 3);
        QCOMPARE(pacer.effectiveSpeed(), 3.0);
        pacer.setWork(0, 24000);
        QCOMPARE(pacer.stepsPerFrame(), 4);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestStepPacer)
#include "test_step_pacer.moc"
