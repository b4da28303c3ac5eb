// The parameter correction's progress and cancellation hook (FitOptions::keepGoing,
// core/curves/fitting/least_squares_fit.h), which the Fitting tab answers from its worker
// thread (ui/fit/background_fit.h), and the work estimate fitWork that decides which fits go
// there and which the CLI's fit --iterate refuses. A stopped fit is the best one so far: the
// same bits as the fit asked for that many corrections.
#include "core/curves/fitting/least_squares_fit.h"

#include <QtTest>
#include "tests/test_main.h"

#include <vector>

using namespace granota;

namespace {

/// Samples of a cubic whose speed varies a lot, at chord-length parameters: each correction
/// lowers the error, for hundreds of corrections (test_least_squares_fit,
/// correctionImprovesChordLength).
std::vector<Point> misparametrizedCubic()
{
    const Point P[4] = {Point(0, 0), Point(0.5, 3), Point(1, -3), Point(10, 1)};
    std::vector<Point> q;
    for (int i = 0; i < 40; ++i) {
        const double t = i / 39.0, u = 1 - t;
        q.push_back(Point(u * u * u * P[0].x + 3 * u * u * t * P[1].x + 3 * u * t * t * P[2].x + t * t * t * P[3].x,
                          u * u * u * P[0].y + 3 * u * u * t * P[1].y + 3 * u * t * t * P[2].y + t * t * t * P[3].y));
    }
    return q;
}

FitOptions correcting(int maxCorrections)
{
    FitOptions o;
    o.degree = 3;
    o.parametrization = Parametrization::ChordLength;
    o.correctParameters = true;
    o.maxCorrections = maxCorrections;
    return o;
}

} // namespace

class TestFitCancellation : public QObject {
    Q_OBJECT
private slots:
    // A hook that always says go on changes nothing, and hears of every correction.
    void goingOnChangesNothing()
    {
        const std::vector<Point> q = misparametrizedCubic();
        const auto plain = fitBezier(q, correcting(20));
        QVERIFY(plain.ok());
        QCOMPARE(plain->corrections, 20); // the premise: it does not stop by itself before
        FitOptions o = correcting(20);
        int calls = 0, highest = -1;
        o.keepGoing = [&](int done) {
            ++calls;
            highest = std::max(highest, done);
            return true;
        };
        const auto asked = fitBezier(q, o);
        QVERIFY(asked.ok());
        QVERIFY(!asked->cancelled && !plain->cancelled);
        QCOMPARE(asked->controlPoints, plain->controlPoints);
        QCOMPARE(asked->sse, plain->sse);
        QVERIFY(calls >= 20);
        QCOMPARE(highest, 19); // asked before each correction with the number made so far
        // Without correction it is never asked.
        FitOptions fixed = o;
        fixed.correctParameters = false;
        calls = 0;
        QVERIFY(fitBezier(q, fixed).ok());
        QCOMPARE(calls, 0);
    }

    // Stopped between corrections: the fit of that many corrections, marked cancelled.
    void stoppedBetweenCorrections()
    {
        const std::vector<Point> q = misparametrizedCubic();
        const auto three = fitBezier(q, correcting(3));
        QVERIFY(three.ok());
        FitOptions o = correcting(1000);
        o.keepGoing = [](int done) { return done < 3; };
        const auto stopped = fitBezier(q, o);
        QVERIFY(stopped.ok());
        QVERIFY(stopped->cancelled);
        QCOMPARE(stopped->corrections, 3);
        QCOMPARE(stopped->controlPoints, three->controlPoints);
        QCOMPARE(stopped->params, three->params);
        QCOMPARE(stopped->sse, three->sse);
    }

    // Stopped within a correction (the projection of the points asks too): the half-made
    // correction is dropped, and the fit is the one before it.
    void stoppedWithinACorrection()
    {
        const std::vector<Point> q = misparametrizedCubic();
        const auto one = fitBezier(q, correcting(1));
        QVERIFY(one.ok());
        FitOptions o = correcting(1000);
        int askedWithOne = 0;
        // The first ask with one correction made is before the second; the next is inside it.
        o.keepGoing = [&](int done) { return !(done == 1 && ++askedWithOne == 2); };
        const auto stopped = fitBezier(q, o);
        QVERIFY(stopped.ok());
        QVERIFY(stopped->cancelled);
        QCOMPARE(askedWithOne, 2);
        QCOMPARE(stopped->corrections, 1);
        QCOMPARE(stopped->controlPoints, one->controlPoints);
        QCOMPARE(stopped->sse, one->sse);
    }

    // fitWork: (k + 1)(n + 1)² per solve, one more for each correction allowed.
    void work()
    {
        QCOMPARE(fitWork(2000, 100, false, 1000), 2000.0 * 101 * 101);
        QCOMPARE(fitWork(2000, 100, true, 1000), 2000.0 * 101 * 101 * 1001);
        QCOMPARE(fitWork(10, 0, true, 50), 10.0); // degree 0 is never corrected
        // The document (87 s on the GUI thread) is far beyond the CLI's bound.
        QVERIFY(fitWork(2000, 100, true, 1000) > 10 * kMaxCliFitWork);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestFitCancellation)
#include "test_fit_cancellation.moc"
