// A golden hash of the stable solver, as Box2D keeps one: a scripted run of the `frog` and
// `many-bodies` scenes (a grab, a fast drag that leaves the frame, a release, a spawn held
// and let go, 600 steps) hashed over every coordinate of every body vertex and chain joint
// after every step. The constants below hold in the release and the debug-asan builds
// alike; anything that changes the solver's results must change them on purpose (run the
// test, read the new value it prints, and say in the commit why the results moved).
#include "core/softbody/scenes/scene.h"
#include "core/softbody/simulation.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cstdint>
#include <cstring>
#include <vector>

using namespace granota;

namespace {

/// FNV-1a, 64 bits, over the bit patterns of doubles (−0 folded into +0).
struct Fnv1a {
    std::uint64_t h = 14695981039346656037ull;
    void add(std::uint64_t v)
    {
        for (int i = 0; i < 8; ++i) {
            h ^= (v >> (8 * i)) & 0xffu;
            h *= 1099511628211ull;
        }
    }
    void add(double d)
    {
        if (d == 0)
            d = 0;
        std::uint64_t bits;
        std::memcpy(&bits, &d, sizeof bits);
        add(bits);
    }
};

struct Script {
    int grabAt = 60;    ///< press inside body 0, at the mean of its vertices
    int dragSteps = 40; ///< then 40 px to the right per step, out of the frame
    int releaseAt = 120;
    int spawnAt = 200; ///< Space held at the frame's centre for 12 steps
    int steps = 600;
};

/// Runs `scene` on the stable solver along `script`; the hash of every position, every step.
std::uint64_t scriptedHash(const std::string& sceneName, const Script& script = {})
{
    const auto scene = loadScene(sceneName);
    if (!scene)
        qFatal("%s", scene.error().message.c_str());
    auto sim = Simulation::create(*scene, SolverKind::Stable);
    if (!sim)
        qFatal("%s", sim.error().message.c_str());
    Simulation& s = **sim;
    Fnv1a hash;
    std::vector<Point> points;
    Point mouse{0, 0};
    const Point centre{scene->params.width / 2, scene->params.height / 2};
    for (int step = 0; step < script.steps; ++step) {
        if (step == script.grabAt && s.bodyCount() > 0) {
            s.bodyVertices(0, points); // the grab takes a body when the mouse is inside it
            mouse = {0, 0};
            for (const Point& p : points)
                mouse = mouse + p * (1.0 / static_cast<double>(points.size()));
            if (!s.press(mouse))
                qFatal("the grab at step %d took nothing", step);
        } else if (step > script.grabAt && step <= script.grabAt + script.dragSteps) {
            mouse.x += 40;
            mouse.y -= 7;
            s.move(mouse);
        } else if (step == script.releaseAt) {
            s.release();
        } else if (step == script.spawnAt) {
            s.spawn(centre);
        } else if (step == script.spawnAt + 12) {
            s.releaseSpawn();
        }
        s.step();
        hash.add(static_cast<std::uint64_t>(s.bodyCount()));
        for (int b = 0; b < s.bodyCount(); ++b) {
            s.bodyVertices(b, points);
            for (const Point& p : points) {
                hash.add(p.x);
                hash.add(p.y);
            }
        }
        for (int c = 0; c < s.chainCount(); ++c) {
            s.chainJoints(c, points);
            for (const Point& p : points) {
                hash.add(p.x);
                hash.add(p.y);
            }
        }
    }
    if (!s.finite())
        qFatal("%s: a coordinate is not finite", sceneName.c_str());
    return hash.h;
}

} // namespace

class TestGoldenHash : public QObject {
    Q_OBJECT
private slots:
    void stableSolverResultsAreUnchanged_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<quint64>("golden");
        QTest::newRow("frog") << QStringLiteral("frog") << quint64(0x0ab840d3039c7982ull);
        QTest::newRow("many-bodies") << QStringLiteral("many-bodies") << quint64(0xbb332ea8ad281993ull);
    }
    void stableSolverResultsAreUnchanged()
    {
        QFETCH(QString, scene);
        QFETCH(quint64, golden);
        const std::uint64_t h = scriptedHash(scene.toStdString());
        QVERIFY2(h == golden, qPrintable(QStringLiteral("%1: hash 0x%2, golden 0x%3")
                                             .arg(scene)
                                             .arg(h, 16, 16, QLatin1Char('0'))
                                             .arg(golden, 16, 16, QLatin1Char('0'))));
    }

    void theHashSeesEveryPartOfTheScript()
    {
        // The same run twice gives the same hash (the solver is deterministic) ...
        const std::uint64_t base = scriptedHash("frog");
        QCOMPARE(scriptedHash("frog"), base);
        // ... and each event of the script, moved by one step, moves the hash.
        Script grab, release, spawn, shorter;
        grab.grabAt += 1;
        release.releaseAt += 1;
        spawn.spawnAt += 1;
        shorter.steps -= 1;
        for (const Script& s : {grab, release, spawn, shorter})
            QVERIFY(scriptedHash("frog", s) != base);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestGoldenHash)
#include "test_golden_hash.moc"
