// The global closest point of a Bézier curve (core/curves/bezier/closest_point.h).
#include "core/curves/bezier/bernstein.h"
#include "core/curves/bezier/closest_point.h"
#include "core/curves/bezier/de_casteljau.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <random>

using namespace granota;

class TestClosestPoint : public QObject {
    Q_OBJECT
private slots:
    void pointOnTheCurveHasDistanceZero()
    {
        const std::vector<Point> P{{0, 0}, {1, 2}, {3, 2}, {4, 0}};
        for (double t : {0.0, 0.125, 0.3, 0.5, 0.9, 1.0}) {
            const Point q = bezierBernstein(P, t);
            const ClosestPoint c = closestPoint(P, q);
            QVERIFY(c.distance < 1e-14);
            QVERIFY(std::fabs(c.t - t) < 1e-12);
        }
    }

    void residualIsNormalAtInteriorMinima()
    {
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(-2, 2);
        const std::vector<Point> P{{0, 0}, {1, 2}, {2, -1}, {3, 3}, {4, 0}};
        int interior = 0;
        for (int trial = 0; trial < 200; ++trial) {
            const Point p(u(rng) + 2, u(rng));
            const ClosestPoint c = closestPoint(P, p);
            if (c.t <= 0 || c.t >= 1)
                continue;
            ++interior;
            const Point tangent = deCasteljau(P, c.t).tangent();
            const Point r = c.point - p;
            // cos of the angle between the residual and the tangent.
            QVERIFY(std::fabs(dot(r, tangent)) <= 1e-12 * norm(r) * norm(tangent) + 1e-14);
        }
        QVERIFY(interior > 100);
    }

    void neverWorseThanADenseScan()
    {
        std::mt19937 rng(10);
        std::uniform_real_distribution<double> u(-1, 1);
        for (int n : {1, 2, 3, 5, 10, 20, 60}) {
            std::vector<Point> P;
            for (int i = 0; i <= n; ++i)
                P.emplace_back(i / double(n) + 0.4 * u(rng), u(rng));
            for (int trial = 0; trial < 30; ++trial) {
                const Point p(1.5 * u(rng) + 0.5, 1.5 * u(rng));
                const ClosestPoint c = closestPoint(P, p);
                QVERIFY(std::fabs(distance(bezierBernstein(P, c.t), p) - c.distance) < 1e-12);
                double scan = distance(P.front(), p);
                for (int j = 0; j <= 4000; ++j)
                    scan = std::min(scan, distance(bezierBernstein(P, j / 4000.0), p));
                QVERIFY2(c.distance <= scan + 1e-12,
                         qPrintable(QString("n=%1 trial %2: %3 > %4").arg(n).arg(trial).arg(c.distance).arg(scan)));
            }
        }
    }

    void tiesPickTheSmallestT()
    {
        // The arch (0,0),(0,1),(1,1),(1,0) is symmetric about x = 1/2; from (1/2, −1) below it
        // the two feet c(0) and c(1) are equally far: t = 0.
        const std::vector<Point> P{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
        const ClosestPoint below = closestPoint(P, {0.5, -1});
        QCOMPARE(below.t, 0.0);
        QCOMPARE(below.point, Point(0, 0));
        QVERIFY(std::fabs(below.distance - std::sqrt(1.25)) < 1e-15);
        // From far above the top, (1/2, 3/4) = c(1/2) is the unique closest point.
        const ClosestPoint above = closestPoint(P, {0.5, 5});
        QVERIFY(std::fabs(above.t - 0.5) < 1e-15);
        QVERIFY(std::fabs(above.distance - 4.25) < 1e-14);
        // A symmetric W: two interior feet at the same distance from a point on the axis.
        const std::vector<Point> W{{0, 1}, {0.25, -1}, {0.5, 1.5}, {0.75, -1}, {1, 1}};
        const ClosestPoint w = closestPoint(W, {0.5, -2});
        QVERIFY(w.t > 0 && w.t < 0.5);
        // Its mirror image 1 − t is as close: the smaller one was chosen.
        QVERIFY(std::fabs(distance(bezierBernstein(W, 1.0 - w.t), Point(0.5, -2)) - w.distance) < 1e-12);
    }

    void degenerateCurves()
    {
        const ClosestPoint single = closestPoint({{1, 1}}, {4, 5});
        QCOMPARE(single.t, 0.0);
        QCOMPARE(single.distance, 5.0);
        const ClosestPoint repeated = closestPoint({{1, 1}, {1, 1}, {1, 1}}, {4, 5});
        QCOMPARE(repeated.t, 0.0);
        QCOMPARE(repeated.distance, 5.0);
        // A segment: the foot of the perpendicular.
        const ClosestPoint foot = closestPoint({{0, 0}, {4, 0}}, {1, 3});
        QCOMPARE(foot.t, 0.25);
        QCOMPARE(foot.distance, 3.0);
        // A cusp: the point at the cusp itself is at distance 0.
        const ClosestPoint cusp = closestPoint({{0, 0}, {1, 1}, {0, 1}, {1, 0}}, {0.5, 0.75});
        QVERIFY(cusp.distance < 1e-15);
        QVERIFY(std::fabs(cusp.t - 0.5) < 1e-7);
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestClosestPoint)
#include "test_closest_point.moc"
