// Geometry of chapter 4: the regular polygon (§4.1), the trapezoid-rule area (§4.5) and
// the point-in-polygon crossing test (§4.6).
#include "core/softbody/polygon_geometry.h"
#include "core/softbody/regular_polygon.h"
#include "core/exact/rational.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>

using namespace granota;

class TestGeometry : public QObject {
    Q_OBJECT
private slots:
    void regularPolygonStartsAtTheTop()
    {
        const auto v = regularPolygon({640, 360}, 120, 10);
        QCOMPARE(int(v.size()), 10);
        QVERIFY(std::abs(v[0].x - 640) < 1e-12);
        QVERIFY(std::abs(v[0].y - 240) < 1e-12); // y grows downwards: the top vertex
        for (const auto& p : v)
            QVERIFY(std::abs(distance(p, {640, 360}) - 120) < 1e-12);
        for (int i = 0; i < 10; ++i) // equal sides
            QVERIFY(std::abs(distance(v[i], v[(i + 1) % 10]) - 2 * 120 * std::sin(M_PI / 10)) < 1e-9);
    }

    void areaOfRegularPolygons_data()
    {
        QTest::addColumn<int>("sides");
        for (int n : {3, 4, 10, 57, 200})
            QTest::newRow(qPrintable(QString::number(n))) << n;
    }
    void areaOfRegularPolygons()
    {
        QFETCH(int, sides);
        const double r = 120;
        const auto v = regularPolygon({640, 360}, r, sides);
        const double expected = 0.5 * sides * r * r * std::sin(2 * M_PI / sides);
        QVERIFY(std::abs(polygonArea(v) - expected) < 1e-9 * expected);
        // The §4.1 order (clockwise on screen, y down) gives a positive trapezoid sum;
        // walking the other way flips the sign.
        QVERIFY(trapezoidArea(v) > 0);
        std::vector<Point> reversed(v.rbegin(), v.rend());
        QVERIFY(std::abs(trapezoidArea(reversed) + trapezoidArea(v)) < 1e-9);
    }

    void areaIsExactForRationals()
    {
        // A non-convex L shape of area 3, exactly.
        const std::vector<RPoint> l{{Rational(0), Rational(0)}, {Rational(2), Rational(0)}, {Rational(2), Rational(1)},
                                    {Rational(1), Rational(1)}, {Rational(1), Rational(2)}, {Rational(0), Rational(2)}};
        QCOMPARE(abs(trapezoidArea(l)), Rational(3));
        // Translating the polygon does not change its area (the trapezoids cancel).
        std::vector<RPoint> moved = l;
        for (auto& p : moved)
            p += RPoint(Rational(1000, 3), Rational(-77, 2));
        QCOMPARE(trapezoidArea(moved), trapezoidArea(l));
    }

    void pointInPolygon_data()
    {
        QTest::addColumn<double>("x");
        QTest::addColumn<double>("y");
        QTest::addColumn<bool>("inside");
        QTest::newRow("centre") << 640.0 << 360.0 << true;
        QTest::newRow("far") << 0.0 << 0.0 << false;
        QTest::newRow("right of the box") << 800.0 << 360.0 << false;
        QTest::newRow("below the vertex column") << 640.0 << 500.0 << false; // x of two vertices
        QTest::newRow("above the top vertex") << 640.0 << 200.0 << false;
        QTest::newRow("just inside the top") << 640.0 << 241.0 << true;
        QTest::newRow("in the notch of the L") << 1.5 << 1.5 << false;
        QTest::newRow("in the L") << 0.5 << 1.5 << true;
    }
    void pointInPolygon()
    {
        QFETCH(double, x);
        QFETCH(double, y);
        QFETCH(bool, inside);
        const auto decagon = regularPolygon({640, 360}, 120, 10);
        const std::vector<Point> l{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
        const auto& poly = x < 10 && y < 10 ? l : decagon;
        QCOMPARE(granota::pointInPolygon({x, y}, poly), inside);
        // Orientation does not matter.
        std::vector<Point> reversed(poly.rbegin(), poly.rend());
        QCOMPARE(granota::pointInPolygon({x, y}, reversed), inside);
    }

    void pointInPolygonThroughVertices()
    {
        // A vertical line through a vertex must not count the two edges there twice: a
        // diamond with vertices exactly at the query's x.
        const std::vector<Point> diamond{{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
        QVERIFY(granota::pointInPolygon({0, 0}, diamond));
        QVERIFY(!granota::pointInPolygon({0, 2}, diamond));
        QVERIFY(!granota::pointInPolygon({0, -2}, diamond));
        QVERIFY(!granota::pointInPolygon({1, 0.5}, diamond));
        QVERIFY(!granota::pointInPolygon({0, 0}, {})); // empty polygon: nothing is inside
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestGeometry)
#include "test_geometry.moc"
