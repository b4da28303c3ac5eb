// The values at the joins of a segmented curve: Prop 2.3 (uniform Catmull-Rom curves are C¹,
// the tangent at a join is τ(q_{m+1} − q_{m−1}) from both sides), and G¹ (parallel, unequal
// tangents) for centripetal spacing.
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/segment_joins.h"

#include <QtTest>
#include "tests/test_main.h"

using namespace granota;

namespace {

Rational q(long n, long d = 1) { return frac(n, d); }

/// Ex 2.13's points.
std::vector<RPoint> ex213() { return {{q(3), q(5)}, {q(2), q(2)}, {q(6), q(0)}, {q(8), q(3)}, {q(7), q(5)}}; }

} // namespace

class TestSegmentJoins : public QObject {
    Q_OBJECT
private slots:
    void tangentsAtJoinsAreTauTimesChord_data()
    {
        QTest::addColumn<int>("mode");
        QTest::addColumn<int>("joins");
        QTest::newRow("open") << int(CatmullRomMode::Open) << 3;
        QTest::newRow("cyclic") << int(CatmullRomMode::Cyclic) << 3;
        QTest::newRow("closed") << int(CatmullRomMode::Closed) << 5;
    }
    void tangentsAtJoinsAreTauTimesChord()
    {
        QFETCH(int, mode);
        QFETCH(int, joins);
        const auto m = CatmullRomMode(mode);
        const auto pts = ex213();
        const Rational tau = q(1, 2);
        const auto segs = catmullRomSegments(pts, tau, m);
        QVERIFY(segs.ok());
        const bool closed = m == CatmullRomMode::Closed;
        const auto values = segmentJoinValues(*segs, 1, closed);
        QCOMPARE(int(values.size()), joins);
        const int n = int(pts.size());
        for (const auto& v : values) {
            QVERIFY(v.equal);
            QVERIFY(v.parallel);
            // The join of p_{j+1} and p_{j+2} is q_{j+1}: tangent τ(q_{j+2} − q_j), indices mod n+1.
            const int knot = (v.fromSegment + 1) % n;
            const RPoint expected = tau * (pts[(knot + 1) % n] - pts[(knot - 1 + n) % n]);
            QCOMPARE(v.left.x, expected.x);
            QCOMPARE(v.left.y, expected.y);
        }
        // Positions: every join is the knot itself.
        for (const auto& v : segmentJoinValues(*segs, 0, closed)) {
            QVERIFY(v.equal);
            const int knot = (v.fromSegment + 1) % n;
            QCOMPARE(v.left.x, pts[knot].x);
            QCOMPARE(v.left.y, pts[knot].y);
        }
    }

    void secondDerivativeJumps()
    {
        // C¹ only (§2.3): the second derivatives of Ex 2.13's open curve differ at its joins.
        const auto segs = catmullRomSegments(ex213(), q(1, 2), CatmullRomMode::Open);
        QVERIFY(segs.ok());
        const auto values = segmentJoinValues(*segs, 2);
        QCOMPARE(int(values.size()), 3);
        QVERIFY(!values[0].equal);
        // p_1'' (1) = 2c_2 + 6c_3 of p_1 = (−7 + 18, −7 + 12) = (11, 5); p_2''(0) = 2c_2 = (12, −3).
        QCOMPARE(values[0].left.x, q(11));
        QCOMPARE(values[0].left.y, q(5));
        QCOMPARE(values[0].right.x, q(12));
        QCOMPARE(values[0].right.y, q(-3));
        QVERIFY(!values[0].parallel);
    }

    void centripetalIsG1NotC1()
    {
        const std::vector<Point> pts = {{0, 0}, {1, 0}, {5, 3}, {6, 3}, {6, 8}};
        const auto segs = catmullRomSegments(pts, 0.5, CatmullRomMode::Open, 0.5);
        QVERIFY(segs.ok());
        const auto values = segmentJoinValues(*segs, 1, false, 1e-9);
        QCOMPARE(int(values.size()), 3);
        bool someUnequal = false;
        for (const auto& v : values) {
            QVERIFY(v.parallel);
            someUnequal = someUnequal || !v.equal;
        }
        QVERIFY(someUnequal);
        // Uniform spacing, the same points: equal tangents.
        const auto uniform = catmullRomSegments(pts, 0.5, CatmullRomMode::Open, 0.0);
        QVERIFY(uniform.ok());
        for (const auto& v : segmentJoinValues(*uniform, 1, false, 1e-12))
            QVERIFY(v.equal);
    }

    void oppositeTangentsAreNotParallel()
    {
        using P = Polynomial<double>;
        // p_1 from (0,0) to (1,0) ending with tangent (1,0); p_2 starting with tangent (−1,0).
        std::vector<Vec2<P>> segs = {Vec2<P>(P{0.0, 1.0}, P{0.0}), Vec2<P>(P{1.0, -1.0}, P{0.0})};
        const auto v = segmentJoinValues(segs, 1, false, 1e-9);
        QCOMPARE(int(v.size()), 1);
        QVERIFY(!v[0].equal);
        QVERIFY(!v[0].parallel);
        QVERIFY(segmentJoinValues(segs, 0, false, 1e-9)[0].equal);
        QVERIFY(segmentJoinValues(std::vector<Vec2<P>>{}, 1).empty());
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestSegmentJoins)
#include "test_segment_joins.moc"
