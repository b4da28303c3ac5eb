// The stable solver allocates nothing per step once its contact lists have reached their
// working size: every global operator new of this test binary is counted.
#include "core/softbody/scenes/scene.h"
#include "core/softbody/simulation.h"
#include "core/softbody/xpbd/xpbd_world.h"

#include <QtTest>
#include "tests/test_main.h"

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t size)
{
    ++g_allocations;
    if (void* p = std::malloc(size ? size : 1))
        return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size)
{
    ++g_allocations;
    if (void* p = std::malloc(size ? size : 1))
        return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

using namespace granota;

namespace {
/// Allocations that adding one body may make, amortized (its outline, its constraints).
constexpr double kAllocationsPerBody = 3;
} // namespace

class TestXpbdAllocation : public QObject {
    Q_OBJECT
private slots:
    void stepDoesNotAllocate_data()
    {
        QTest::addColumn<int>("bodies");
        QTest::newRow("one frog") << 1;
        QTest::newRow("60 bodies, obstacles, chains, mouse") << 60;
    }
    void stepDoesNotAllocate()
    {
        QFETCH(int, bodies);
        const long start = g_allocations.load();
        XpbdWorld w = XpbdWorld::create().value();
        for (int k = 0; k < bodies; ++k)
            QVERIFY(w.addRegularBody({100.0 + (k % 12) * 95, 80.0 + (k / 12) * 90}, 35, 6 + k % 7, 3000, {}).ok());
        QVERIFY(w.addSegmentObstacle({200, 500}, {700, 560}).ok());
        QVERIFY(w.addPolygonObstacle({{900, 600}, {1150, 600}, {1020, 450}}).ok());
        for (int leg = 0; leg < 4; ++leg) {
            const ChainAnchor a = frogLegAnchor(0, leg, 6);
            QVERIFY(w.addChain(frogLegChain(FrogParams{}.legs[std::size_t(leg)], a, w.anchorPoint(a))).ok());
        }
        QVERIFY(g_allocations.load() > start); // the counter does see allocations
        for (int i = 0; i < 300; ++i)          // the contact lists grow to their working size
            w.step();
        QVERIFY(w.press(w.centroid(0)));
        const long before = g_allocations.load();
        for (int i = 0; i < 300; ++i) {
            w.move({400 + std::sin(i * 0.05) * 300, 200});
            w.step();
        }
        w.release();
        for (int i = 0; i < 100; ++i)
            w.step();
        const long during = g_allocations.load() - before;
        QCOMPARE(during, 0L);
    }

    void addingBodiesReallocatesRarely()
    {
        // Found with the scene fuzz target's harness (many-bodies with --set bodies=5000
        // took seconds to build): every body added reserved room for exactly one more in a
        // dozen lists, so N bodies reallocated each list N times (N² copying).
        XpbdWorld w = XpbdWorld::create().value();
        constexpr int kBodies = 2048;
        const long start = g_allocations.load();
        for (int k = 0; k < kBodies; ++k)
            QVERIFY(w.addRegularBody({20.0 + (k % 64) * 20, 20.0 + (k / 64) * 20}, 8, 6, 150, {}).ok());
        const double perBody = static_cast<double>(g_allocations.load() - start) / kBodies;
        QVERIFY2(perBody < kAllocationsPerBody, qPrintable(QStringLiteral("%1 allocations per body").arg(perBody)));
    }

    // What the frog canvas does every frame, on either solver: step, then read every
    // body's vertices and every leg's joints into vectors it keeps.
    void frameDoesNotAllocate_data()
    {
        QTest::addColumn<int>("solver");
        QTest::newRow("seed") << int(SolverKind::Seed);
        QTest::newRow("stable") << int(SolverKind::Stable);
    }
    void frameDoesNotAllocate()
    {
        QFETCH(int, solver);
        auto spec = loadScene("frog");
        QVERIFY(spec.ok());
        auto sim = Simulation::create(spec.value(), SolverKind(solver));
        QVERIFY(sim.ok());
        Simulation& s = *sim.value();
        QCOMPARE(s.chainCount(), 4);
        std::vector<Point> vertices, joints;
        const auto frame = [&] {
            s.step();
            double sum = 0;
            for (int b = 0; b < s.bodyCount(); ++b) {
                s.bodyVertices(b, vertices);
                sum += vertices.front().x;
            }
            for (int c = 0; c < s.chainCount(); ++c) {
                s.chainJoints(c, joints);
                sum += joints.back().y;
            }
            return sum;
        };
        for (int i = 0; i < 10; ++i) // the vectors reach their size
            frame();
        const long before = g_allocations.load();
        double sum = 0;
        for (int i = 0; i < 200; ++i)
            sum += frame();
        QCOMPARE(g_allocations.load() - before, 0L);
        QVERIFY(std::isfinite(sum));
        QVERIFY(vertices.size() >= 3);
        QCOMPARE(joints.size(), std::size_t(3));
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestXpbdAllocation)
#include "test_xpbd_allocation.moc"
