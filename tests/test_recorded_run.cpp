// Rewind (docs/rewind.md): a recorded run replays to the same bits, going back and forth
// gives the states of the run forward, a new event cuts the recorded future off, snapshots
// stay bounded, and a malformed recording is refused with a message.
#include "cli_runner.h"

#include "core/softbody/recorded_run.h"
#include "core/softbody/scenes/scene.h"
#include "core/softbody/simulation_trace.h"

#include <QtTest>
#include "tests/test_main.h"

#include <QFile>
#include <QTemporaryDir>

#include <random>

using namespace granota;
Q_DECLARE_METATYPE(SolverKind)

// Address-space limits do not work under AddressSanitizer: there the memory test runs
// without its limit (tests/asan.h).
#include "tests/asan.h"

namespace {

SceneSpec scene(const std::string& name)
{
    auto spec = loadScene(name);
    if (!spec)
        qFatal("%s", spec.error().message.c_str());
    return *spec;
}

Point centroid(const Simulation& s)
{
    if (s.bodyCount() == 0) // the pendulums: the nail
        return s.scene().params.center;
    std::vector<Point> v;
    s.bodyVertices(0, v);
    Point c;
    for (const Point& p : v)
        c += p;
    return Point(c.x / double(v.size()), c.y / double(v.size()));
}

/// A student's minute: grab the frog, swing it round, throw it, spawn another, let go, and
/// turn the stable solver's knobs twice on the way.
/// Returns the trace row after every step (index = step).
std::vector<std::string> drive(RecordedRun& run, int steps)
{
    std::vector<std::string> rows{simulationTraceRow(run.simulation())};
    for (int i = 0; i < steps; ++i) {
        if (i == 20)
            run.press(centroid(run.simulation()));
        if (i > 20 && i < 80)
            run.move(Point(640 + 150 * std::cos(i / 8.0), 300 + 80 * std::sin(i / 8.0)));
        if (i == 80)
            run.release();
        if (i == 150)
            run.spawn(Point(400, 200));
        if (i == 170)
            run.releaseSpawn();
        if (i == 120) // the stable solver's knobs, turned live (the seed keeps and ignores them)
            run.setStableSettings({4, 0.01, 0.4});
        if (i == 230)
            run.setStableSettings({12, 0});
        run.step();
        rows.push_back(simulationTraceRow(run.simulation()));
    }
    return rows;
}

} // namespace

class TestRecordedRun : public QObject {
    Q_OBJECT
private slots:
    void replaysToTheSameBits_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<SolverKind>("solver");
        QTest::newRow("frog, seed") << "frog" << SolverKind::Seed;
        QTest::newRow("frog, stable") << "frog" << SolverKind::Stable;
        QTest::newRow("tuned, stable") << "tuned" << SolverKind::Stable;
        QTest::newRow("many-bodies, stable") << "many-bodies" << SolverKind::Stable;
        QTest::newRow("bounce, seed") << "bounce" << SolverKind::Seed;
        QTest::newRow("pendulum-limits, seed") << "pendulum-limits" << SolverKind::Seed;
    }
    void replaysToTheSameBits()
    {
        QFETCH(QString, name);
        QFETCH(SolverKind, solver);
        auto run = RecordedRun::start(scene(name.toStdString()), solver, 50);
        QVERIFY(run.ok());
        QVERIFY(!run->press(Point(std::nan(""), 3))); // not finite: neither applied nor recorded
        QVERIFY(run->recording().events.empty());
        const auto forward = drive(*run, 300);
        QCOMPARE(run->recordedSteps(), 300L);
        QVERIFY(run->recording().events.size() > 60);
        // Through the file format and back.
        const std::string text = recordingToJson(run->recording()).dump(1);
        auto parsed = recordingFromJson(Json::parse(text).value());
        QVERIFY2(parsed.ok(), parsed.ok() ? "" : parsed.error().message.c_str());
        QVERIFY(parsed->events == run->recording().events);
        auto replay = RecordedRun::load(*parsed);
        QVERIFY(replay.ok());
        QVERIFY(replay->playingBack());
        QCOMPARE(simulationTraceRow(replay->simulation()), forward[0]);
        for (long step = 1; step <= 300; ++step) {
            replay->step();
            QCOMPARE(simulationTraceRow(replay->simulation()), forward[std::size_t(step)]);
        }
        QVERIFY(!replay->playingBack());
    }

    void scrubbingGivesTheStatesOfTheRunForward_data() { replaysToTheSameBits_data(); }
    void scrubbingGivesTheStatesOfTheRunForward()
    {
        QFETCH(QString, name);
        QFETCH(SolverKind, solver);
        auto run = RecordedRun::start(scene(name.toStdString()), solver, 50);
        const auto forward = drive(*run, 300);
        std::mt19937 random(16);
        std::uniform_int_distribution<long> anyStep(0, 300);
        std::vector<long> targets{299, 0, 300, 21, 20, 80, 81, 150, 151, 49, 50, 51, 1};
        for (int i = 0; i < 30; ++i)
            targets.push_back(anyStep(random));
        for (long t : targets) {
            QVERIFY(run->seek(t).ok());
            QCOMPARE(run->stepCount(), t);
            QCOMPARE(simulationTraceRow(run->simulation()), forward[std::size_t(t)]);
        }
        // From a step gone back to, running on plays the recording back.
        QVERIFY(run->seek(137).ok());
        for (long step = 138; step <= 300; ++step) {
            run->step();
            QCOMPARE(simulationTraceRow(run->simulation()), forward[std::size_t(step)]);
        }
        QVERIFY(!run->seek(301).ok());
        QVERIFY(!run->seek(-1).ok());
        QCOMPARE(run->stepCount(), 300L);
    }

    void aNewEventCutsTheFutureOff()
    {
        auto run = RecordedRun::start(scene("frog"), SolverKind::Stable, 50);
        const auto forward = drive(*run, 300);
        const std::size_t all = run->recording().events.size();
        QVERIFY(run->seek(100).ok());
        run->press(centroid(run->simulation()));
        QCOMPARE(run->recordedSteps(), 100L);
        QVERIFY(run->recording().events.size() < all);
        QCOMPARE(run->recording().events.back().step, 100L);
        QVERIFY(run->recording().events.back().kind == InputKind::Press);
        for (const InputEvent& e : run->recording().events)
            QVERIFY(e.step <= 100);
        for (int i = 0; i < 40; ++i)
            run->step();
        QCOMPARE(run->recordedSteps(), 140L);
        QVERIFY(simulationTraceRow(run->simulation()) != forward[140]); // a new branch
        // The new branch replays too.
        const std::string now = simulationTraceRow(run->simulation());
        QVERIFY(run->seek(0).ok());
        run->runToEnd();
        QCOMPARE(simulationTraceRow(run->simulation()), now);
    }

    // A long run keeps at most kMaxSnapshots snapshots, farther apart, and still goes back right.
    void snapshotsStayBounded()
    {
        auto run = RecordedRun::start(scene("frog"), SolverKind::Seed, 10);
        std::vector<std::string> rows{simulationTraceRow(run->simulation())};
        for (int i = 0; i < 6000; ++i) {
            if (i % 500 == 100)
                run->press(centroid(run->simulation()));
            if (i % 500 == 200)
                run->release();
            run->step();
            rows.push_back(simulationTraceRow(run->simulation()));
            QVERIFY(run->snapshotCount() <= RecordedRun::kMaxSnapshots);
        }
        QVERIFY(run->snapshotEvery() > 10);
        for (long t : {5999L, 3333L, 10L, 4500L, 0L, 6000L}) {
            QVERIFY(run->seek(t).ok());
            QCOMPARE(simulationTraceRow(run->simulation()), rows[std::size_t(t)]);
        }
    }

    // The fewest steps between snapshots that keep them within a share of the stepping time.
    void snapshotSpacing_data()
    {
        QTest::addColumn<double>("snapshotNs");
        QTest::addColumn<double>("stepNs");
        QTest::addColumn<double>("share");
        QTest::addColumn<int>("spacing");
        QTest::newRow("1000 bodies: 6.5 ms a copy, 2 ms a step, 1 %") << 6.5e6 << 2e6 << 0.01 << 325;
        QTest::newRow("a copy as long as a step, 2 %") << 1e3 << 1e3 << 0.02 << 50;
        QTest::newRow("exactly 1 step") << 1e3 << 1e5 << 0.01 << 1;
        QTest::newRow("a cheap copy: every step") << 1.0 << 1e6 << 0.02 << 1;
        QTest::newRow("rounded up") << 1001.0 << 1e3 << 0.1 << 11;
        QTest::newRow("step not timed yet") << 1e6 << 0.0 << 0.01 << 1;
        QTest::newRow("copy not timed yet") << 0.0 << 1e3 << 0.01 << 1;
        QTest::newRow("share off") << 1e6 << 1e3 << 0.0 << 1;
        QTest::newRow("not a number") << std::nan("") << 1e3 << 0.01 << 1;
        QTest::newRow("a step too fast to see") << 1e6 << 1e-300 << 0.01 << RecordedRun::kMaxSnapshotSpacing;
    }
    void snapshotSpacing()
    {
        QFETCH(double, snapshotNs);
        QFETCH(double, stepNs);
        QFETCH(double, share);
        QFETCH(int, spacing);
        QCOMPARE(RecordedRun::snapshotSpacing(snapshotNs, stepNs, share), spacing);
    }

    // limitSnapshotCost: on a clock where every timed piece of work (a step, a copy) takes
    // the same time, a 2 % share puts 50 steps between snapshots even when 1 is asked; the
    // snapshots are that far apart, seeks still give the run forward's rows, and a long run
    // still keeps at most maxSnapshots. Turned off, the interval asked is back.
    void snapshotCostIsLimited()
    {
        auto run = RecordedRun::start(scene("frog"), SolverKind::Stable, 1);
        double now = 0;
        int readings = 0;
        run->limitSnapshotCost(0.02, [&] {
            ++readings;
            return now += 1e6; // 1 ms from one reading to the next
        });
        const auto forward = drive(*run, 300);
        QCOMPARE(run->snapshotEvery(), 50);
        // Steps 1 and 51, …: the first timed step (0) comes before the first copy timed (1).
        QCOMPARE(run->snapshotCount(), std::size_t(1 + 1 + (300 - 1) / 50));
        // One step in kTimedStepEvery and every copy, two readings each: not every step.
        QCOMPARE(readings, 2 * (300 / RecordedRun::kTimedStepEvery + 1) + 2 * int(run->snapshotCount() - 1));
        for (long t : {0L, 1L, 2L, 50L, 51L, 52L, 299L, 137L, 300L, 100L}) {
            QVERIFY(run->seek(t).ok());
            QCOMPARE(simulationTraceRow(run->simulation()), forward[std::size_t(t)]);
        }
        run->setMaxSnapshots(3);
        QVERIFY(run->snapshotCount() <= 3);
        QVERIFY(run->snapshotEvery() >= 100);
        QVERIFY(run->seek(211).ok());
        QCOMPARE(simulationTraceRow(run->simulation()), forward[211]);

        auto plain = RecordedRun::start(scene("frog"), SolverKind::Stable, 7);
        plain->limitSnapshotCost(0.02, [&] { return now += 1e6; });
        plain->limitSnapshotCost(0); // off again: the interval asked
        drive(*plain, 50);
        QCOMPARE(plain->snapshotEvery(), 7);
        QCOMPARE(plain->snapshotCount(), std::size_t(1 + 50 / 7));
    }

    // A mouse sends more events than there are steps: the moves of one step are recorded
    // as the last of them, and the replay is still the run.
    void movesWithinAStepRecordAsOne()
    {
        auto run = RecordedRun::start(scene("frog"), SolverKind::Stable, 50);
        std::vector<std::string> rows{simulationTraceRow(run->simulation())};
        for (int i = 0; i < 120; ++i) {
            for (int k = 0; k < 5; ++k) { // five mouse events a step, as a 300 Hz mouse sends
                if (i == 10 && k == 2)
                    run->press(centroid(run->simulation()));
                run->move(Point(500 + 3 * i + k, 300 - 2 * i + k));
            }
            if (i == 60)
                run->release();
            run->step();
            rows.push_back(simulationTraceRow(run->simulation()));
        }
        long moves = 0;
        for (const InputEvent& e : run->recording().events)
            moves += e.kind == InputKind::Move;
        QCOMPARE(moves, 120L + 1); // one a step, and at step 10 one before the press and one after
        auto replay = RecordedRun::load(run->recording());
        replay->runToEnd();
        QCOMPARE(simulationTraceRow(replay->simulation()), rows.back());
    }

    // The Frog tab records the simulation it built, and a document gives the run back.
    void adoptedRunsTakeADocumentsEvents()
    {
        auto built = Simulation::create(scene("frog"), SolverKind::Seed);
        auto run = RecordedRun::adopt(std::move(built).value(), 25);
        QVERIFY(run.ok());
        QCOMPARE(run->recording().scene.name, std::string("frog"));
        const auto forward = drive(*run, 300);
        const Json events = eventsToJson(run->recording().events);
        auto parsed = eventsFromJson(events, 300);
        QVERIFY(parsed.ok());
        auto again = RecordedRun::adopt(std::move(Simulation::create(scene("frog"), SolverKind::Seed)).value(), 25);
        QVERIFY(again->setRecording(*parsed, 300).ok());
        QCOMPARE(again->recordedSteps(), 300L);
        QVERIFY(again->seek(233).ok());
        QCOMPARE(simulationTraceRow(again->simulation()), forward[233]);
        // Going through it once more from the start replaces the snapshots of the old run.
        QVERIFY(again->setRecording(*parsed, 300).ok());
        QCOMPARE(again->stepCount(), 0L);
        QCOMPARE(again->snapshotCount(), std::size_t(1));
        again->runToEnd();
        QCOMPARE(simulationTraceRow(again->simulation()), forward[300]);
        // Refused: events past the steps, out of order, not finite; one that has stepped.
        std::vector<InputEvent> late{{301, InputKind::Release, Point()}};
        QVERIFY(!again->setRecording(late, 300).ok());
        std::vector<InputEvent> order{{5, InputKind::Release, Point()}, {4, InputKind::Release, Point()}};
        QVERIFY(!again->setRecording(order, 300).ok());
        std::vector<InputEvent> nan{{5, InputKind::Move, Point(std::nan(""), 0)}};
        QVERIFY(!again->setRecording(nan, 300).ok());
        QCOMPARE(again->recordedSteps(), 300L); // unchanged
        QCOMPARE(simulationTraceRow(again->simulation()), forward[300]);
        QVERIFY(!eventsFromJson(Json::parse(R"([[3, "move", 1]])").value(), 300).ok());
        // As a document keeps it: steps, the step shown, the events.
        QVERIFY(again->seek(120).ok());
        auto kept = documentRunFromJson(documentRunToJson(*again));
        QVERIFY(kept.ok());
        QCOMPARE(kept->steps, 300L);
        QCOMPARE(kept->step, 120L);
        QVERIFY(kept->events == again->recording().events);
        for (const char* bad : {R"({"steps": 10, "step": 11, "events": []})", R"({"steps": -1, "events": []})",
                                R"({"steps": 10})", R"({"steps": 10, "step": 2.5, "events": []})", "[1]"}) {
            auto refused = documentRunFromJson(Json::parse(bad).value());
            QVERIFY2(!refused.ok(), bad);
            QVERIFY(refused.error().message.rfind("recording: ", 0) == 0);
        }
        QCOMPARE(documentRunFromJson(Json::parse(R"({"steps": 10, "events": []})").value())->step, 0L);
        auto stepped = Simulation::create(scene("frog"), SolverKind::Seed);
        (*stepped)->step();
        QVERIFY(!RecordedRun::adopt(std::move(stepped).value()).ok());
    }

    // A big scene keeps fewer copies: the bound holds, and seeks stay right.
    void fewerSnapshotsForBigScenes()
    {
        auto run = RecordedRun::start(scene("frog"), SolverKind::Stable, 5);
        run->setMaxSnapshots(8);
        const auto forward = drive(*run, 300);
        QVERIFY(run->snapshotCount() <= 8);
        QVERIFY(run->snapshotEvery() >= 40); // 300 steps in at most 8 snapshots
        for (long t : {0L, 299L, 17L, 150L, 300L, 81L}) {
            QVERIFY(run->seek(t).ok());
            QCOMPARE(simulationTraceRow(run->simulation()), forward[std::size_t(t)]);
        }
        run->setMaxSnapshots(0); // at least 2
        QCOMPARE(run->maxSnapshots(), std::size_t(2));
        QVERIFY(run->snapshotCount() <= 2);
        QVERIFY(run->seek(211).ok());
        QCOMPARE(simulationTraceRow(run->simulation()), forward[211]);
    }

    // Issue 16, "live substeps and stiffness": a knob turned mid-run takes effect from the
    // next step without starting the run again, is recorded (a run of turns within a step as
    // one event), is in force at the step it was turned when the run goes back there, and
    // the seed, which keeps the knobs, steps as Annex II does.
    void knobsTurnLive()
    {
        const SceneSpec frog = scene("frog");
        auto plain = RecordedRun::start(frog, SolverKind::Stable);
        auto run = RecordedRun::start(frog, SolverKind::Stable, 25);
        std::vector<std::string> plainRows{simulationTraceRow(plain->simulation())}, rows{plainRows};
        for (int i = 0; i < 200; ++i) {
            if (i == 100) {
                QVERIFY(!run->setStableSettings({33, 0.01})); // out of range: nothing changes
                QVERIFY(!run->setStableSettings({4, -1}));
                QVERIFY(run->recording().events.empty());
                QVERIFY(run->setStableSettings({2, 0.05}));
                QVERIFY(run->setStableSettings({3, 0.05})); // the same step: one event a knob
                QCOMPARE(run->simulation().substeps(), 3);
            }
            if (i == 150)
                QVERIFY(run->setStableSettings({3, 0}));
            plain->step();
            run->step();
            plainRows.push_back(simulationTraceRow(plain->simulation()));
            rows.push_back(simulationTraceRow(run->simulation()));
        }
        QCOMPARE(run->stepCount(), 200L); // the run went on
        for (int k = 0; k <= 100; ++k)
            QCOMPARE(rows[std::size_t(k)], plainRows[std::size_t(k)]);
        QVERIFY(rows[101] != plainRows[101]); // three substeps from step 100 on, not eight
        const auto& events = run->recording().events;
        QCOMPARE(events.size(), std::size_t(3));
        QVERIFY((events[0] == InputEvent{100, InputKind::Substeps, Point(), 3}));
        QVERIFY((events[1] == InputEvent{100, InputKind::EdgeCompliance, Point(), 0.05}));
        QVERIFY((events[2] == InputEvent{150, InputKind::EdgeCompliance, Point(), 0}));
        // Back to a step: the knobs in force there, and the state the run went through.
        const std::pair<long, StableSettings> at[] = {{99, {8, 2e-3}}, {100, {3, 0.05}}, {149, {3, 0.05}}, {150, {3, 0}},
                                                      {0, {8, 2e-3}},  {175, {3, 0}},    {101, {3, 0.05}}};
        for (const auto& [step, knobs] : at) {
            QVERIFY(run->seek(step).ok());
            QVERIFY2(run->simulation().stableSettings() == knobs, qPrintable(QString::number(step)));
            QCOMPARE(run->simulation().substeps(), knobs.substeps);
            QCOMPARE(simulationTraceRow(run->simulation()), rows[std::size_t(step)]);
        }
        // The file keeps them: [step, "substeps", n], [step, "edge_compliance", α].
        const Json doc = recordingToJson(run->recording());
        QVERIFY(QString::fromStdString(doc.dump()).contains(R"([100,"substeps",3])"));
        auto parsed = recordingFromJson(doc);
        QVERIFY(parsed.ok());
        QVERIFY(parsed->events == events);
        // The seed keeps the knobs to hand on, and its trace is Annex II's all the same.
        auto seedPlain = RecordedRun::start(frog, SolverKind::Seed), seed = RecordedRun::start(frog, SolverKind::Seed);
        for (int i = 0; i < 60; ++i) {
            if (i == 10)
                QVERIFY(seed->setStableSettings({1, 1}));
            seed->step();
            seedPlain->step();
        }
        QCOMPARE(seed->simulation().stableSettings().substeps, 1);
        QCOMPARE(simulationTraceRow(seed->simulation()), simulationTraceRow(seedPlain->simulation()));
    }

    void badRecordingsAreRefused_data()
    {
        QTest::addColumn<QString>("change");
        QTest::addColumn<QString>("message");
        QTest::newRow("format") << R"("format": "granota")"
                                << "format";
        QTest::newRow("version") << R"("version": 2)"
                                 << "version";
        QTest::newRow("solver") << R"("solver": "fast")"
                                << "solver";
        QTest::newRow("steps negative") << R"("steps": -1)"
                                        << "steps";
        QTest::newRow("steps fraction") << R"("steps": 2.5)"
                                        << "steps";
        QTest::newRow("events not an array") << R"("events": {})"
                                             << "events";
        QTest::newRow("event after the end") << R"("events": [[11, "release"]])"
                                             << "event 1";
        QTest::newRow("events out of order") << R"("events": [[5, "release"], [4, "release"]])"
                                             << "event 2";
        QTest::newRow("unknown kind") << R"("events": [[1, "jump"]])"
                                      << "kind";
        QTest::newRow("press without a point") << R"("events": [[1, "press"]])"
                                               << "x and y";
        QTest::newRow("release with a point") << R"("events": [[1, "release", 3, 4]])"
                                              << "no point";
        QTest::newRow("substeps 0") << R"("events": [[1, "substeps", 0]])"
                                    << "substeps must be a whole number from 1 to 32";
        QTest::newRow("substeps 2.5") << R"("events": [[1, "substeps", 2.5]])"
                                      << "event 1: substeps";
        QTest::newRow("compliance 2") << R"("events": [[1, "edge_compliance", 2]])"
                                      << "edge_compliance must be";
        QTest::newRow("damping ratio 2.5") << R"("events": [[1, "edge_damping_ratio", 2.5]])"
                                           << "edge_damping_ratio must be a number from 0 (no damping) to 2";
        QTest::newRow("damping ratio negative") << R"("events": [[1, "edge_damping_ratio", -0.1]])"
                                                << "event 1: edge_damping_ratio";
        QTest::newRow("knob without a value") << R"("events": [[1, "substeps"]])"
                                              << "needs its value";
        QTest::newRow("huge coordinate") << R"("events": [[1, "move", 1e999, 4]])"
                                         << "";
        QTest::newRow("bad scene") << R"("scene": {"name": "frog"})"
                                   << "scene";
    }
    void badRecordingsAreRefused()
    {
        QFETCH(QString, change);
        QFETCH(QString, message);
        auto run = RecordedRun::start(scene("frog"), SolverKind::Seed);
        for (int i = 0; i < 10; ++i)
            run->step();
        Json doc = recordingToJson(run->recording());
        const auto changed = Json::parse("{" + change.toStdString() + "}");
        if (!changed) { // 1e999 is no JSON number: refused as text already
            QVERIFY(message.isEmpty());
            return;
        }
        for (const auto& [key, value] : *changed->asObject())
            doc.set(key, value);
        auto parsed = recordingFromJson(doc);
        QVERIFY(!parsed.ok());
        QVERIFY2(QString::fromStdString(parsed.error().message).contains(message), parsed.error().message.c_str());
        QVERIFY(QString::fromStdString(parsed.error().message).startsWith("recording: "));
        // The streaming reader (the CLI's) refuses it with the same words.
        bool notJson = true;
        auto streamed = recordingFromText(doc.dump(), &notJson);
        QVERIFY(!streamed.ok() && !notJson);
        QCOMPARE(streamed.error().message, parsed.error().message);
    }

    // recordingFromText streams the events instead of holding them as Json: the same
    // recording, or the same first error, as recordingFromJson(Json::parse(text)), whatever
    // the order of the keys ("steps" after "events", so the steps are learnt last), with
    // an event beyond the steps before or after another bad event, and a repeated key.
    void streamingReaderAgreesWithTheTree_data()
    {
        QTest::addColumn<QString>("tail");
        const QString events = R"("events": [[0, "press", 1, 2], [3, "move", 4, 5], [9, "release"], [9, "substeps", 4]])";
        QTest::newRow("steps first") << R"("steps": 9, )" + events;
        QTest::newRow("steps last") << events + R"(, "steps": 9)";
        QTest::newRow("beyond the steps") << events + R"(, "steps": 5)";
        QTest::newRow("beyond, then bad kind") << R"("events": [[7, "move", 1, 2], [8, "jump"]], "steps": 5)";
        QTest::newRow("bad kind, then beyond") << R"("events": [[1, "jump"], [8, "move", 1, 2]], "steps": 5)";
        QTest::newRow("out of order") << R"("events": [[3, "move", 1, 2], [2, "release"]], "steps": 5)";
        QTest::newRow("step not whole") << R"("events": [[1.5, "release"]], "steps": 5)";
        QTest::newRow("repeated events key") << R"("events": [[1, "jump"]], "steps": 5, "events": [[2, "release"]])";
        QTest::newRow("events not an array") << R"("steps": 5, "events": {"a": 1})";
        QTest::newRow("no events") << R"("steps": 5)";
        QTest::newRow("no steps") << events;
        QTest::newRow("nested") << R"("steps": 5, "events": [[1, "move", [1], 2]])";
    }
    void streamingReaderAgreesWithTheTree()
    {
        QFETCH(QString, tail);
        const std::string head = R"({"format": "granota-recording", "version": 1, "scene": )" +
                                 sceneToJson(scene("frog")).dump() + R"(, "solver": "seed", )";
        const std::string text = head + tail.toStdString() + "}";
        const auto tree = Json::parse(text);
        QVERIFY(tree.ok());
        const auto expected = recordingFromJson(*tree);
        const auto streamed = recordingFromText(text);
        QCOMPARE(streamed.ok(), expected.ok());
        if (expected.ok()) {
            QCOMPARE(streamed->steps, expected->steps);
            QVERIFY(streamed->events == expected->events);
        } else {
            QCOMPARE(streamed.error().message, expected.error().message);
        }
        bool notJson = false;
        QVERIFY(!recordingFromText(text.substr(0, text.size() - 1), &notJson).ok());
        QVERIFY(notJson);
    }

    // A recording of a million events (24 MB of text; the issue's had 2.4 million in 55 MB)
    // replays under a 300 MB address-space limit: the events are streamed into InputEvents
    // (40 bytes each) instead of being held as a Json tree first (some 300 bytes each). Before,
    // the replay needed more than 400 MB of address space ("error: not enough memory" at
    // 400 MB; docs/extreme-cases.md has the figures). The replay is still the run itself: the
    // trace's last row is the one of the same recording stepped here.
    void aMillionEventsReplayInBoundedMemory()
    {
        constexpr long kEvents = 1000000, kPerStep = 1000;
        Recording r;
        r.scene = scene("frog");
        r.solver = SolverKind::Seed;
        r.steps = kEvents / kPerStep;
        r.events.reserve(kEvents);
        {
            auto start = RecordedRun::start(r.scene, r.solver);
            r.events.push_back({0, InputKind::Press, centroid(start->simulation())});
        }
        for (long i = 1; i + 1 < kEvents; ++i)
            r.events.push_back({i / kPerStep, InputKind::Move, Point(600 + double(i % 97) * 0.75, 300 + double(i % 89) * 0.5)});
        r.events.push_back({r.steps, InputKind::Release, Point()});
        QTemporaryDir dir;
        const QString file = dir.filePath("million.json"), trace = dir.filePath("trace.csv");
        {
            QFile f(file);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray::fromStdString(recordingToJson(r).dump()));
        }
        // Expected: the same recording stepped here.
        auto replay = RecordedRun::load(r, static_cast<int>(kMaxRecordedSteps));
        QVERIFY(replay.ok());
        for (long step = 0; step < r.steps; ++step)
            replay->step();
        const QByteArray last = QByteArray::fromStdString(simulationTraceRow(replay->simulation()));
        r.events = {};

        const QStringList args{QStringLiteral("simulate"), QStringLiteral("--replay"), file, QStringLiteral("--trace"), trace};
        constexpr int kHangGuardMs = 300000; // a hang guard only
#ifdef GRANOTA_TEST_ASAN
        const CliRun run = runCli(args, kHangGuardMs);
#else
        const CliRun run = runCliInAddressSpace(QString::number(300 * 1024), args, kHangGuardMs);
#endif
        QVERIFY2(run.exitCode == 0, run.err.constData());
        QFile t(trace);
        QVERIFY(t.open(QIODevice::ReadOnly));
        const QList<QByteArray> rows = t.readAll().trimmed().split('\n');
        QCOMPARE(rows.size(), int(r.steps) + 2); // the header and a row for each step from 0
        QCOMPARE(rows.back(), last);
    }

    // granota-cli: --record writes a run, --replay runs a recording (the GUI's, with its
    // mouse) to the same trace bits.
    void cliRecordsAndReplays()
    {
        QTemporaryDir dir;
        auto run = RecordedRun::start(scene("frog"), SolverKind::Stable, 50);
        const auto forward = drive(*run, 300);
        const QString recording = dir.filePath("run.json"), trace = dir.filePath("trace.csv");
        {
            QFile f(recording);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray::fromStdString(recordingToJson(run->recording()).dump()));
        }
        const CliRun replay = runCli({"simulate", "--replay", recording, "--trace", trace, "--json"});
        QCOMPARE(replay.exitCode, 0);
        QCOMPARE(replay.json()["steps"].toInt(), 300);
        QFile t(trace);
        QVERIFY(t.open(QIODevice::ReadOnly));
        const QList<QByteArray> rows = t.readAll().split('\n');
        QCOMPARE(rows.size(), 303); // header, 301 rows, the last newline
        for (int step = 0; step <= 300; ++step)
            QCOMPARE(rows[step + 1], QByteArray::fromStdString(forward[std::size_t(step)]));
        // --record, then --replay of that: the same final state as the plain run.
        const QString mine = dir.filePath("mine.json");
        const CliRun record = runCli({"simulate", "--scene", "frog", "--solver", "stable", "--steps", "120", "--set",
                                      "gravity=0.2,0.75", "--record", mine, "--json"});
        QCOMPARE(record.exitCode, 0);
        const CliRun again = runCli({"simulate", "--replay", mine, "--json"});
        QCOMPARE(again.exitCode, 0);
        QCOMPARE(again.json()["bodies"], record.json()["bodies"]);
        QCOMPARE(again.json()["chains"], record.json()["chains"]);
        // Bad input: exit 2 with a message.
        const CliRun both = runCli({"simulate", "--replay", mine, "--steps", "5"});
        QCOMPARE(both.exitCode, 2);
        QVERIFY(both.err.startsWith("error: --replay"));
        const CliRun zero = runCli({"simulate", "--replay", "/dev/zero"});
        QCOMPARE(zero.exitCode, 2);
        QVERIFY(zero.err.startsWith("error: "));
        const CliRun missing = runCli({"simulate", "--replay", dir.filePath("none.json")});
        QCOMPARE(missing.exitCode, 2);
        QFile broken(dir.filePath("broken.json"));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write(R"({"format":"granota-recording","version":1,"scene":{},"solver":"seed","steps":3,"events":[]})");
        broken.close();
        const CliRun bad = runCli({"simulate", "--replay", broken.fileName()});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY2(bad.err.contains("recording: its scene"), bad.err.constData());
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestRecordedRun)
#include "test_recorded_run.moc"
