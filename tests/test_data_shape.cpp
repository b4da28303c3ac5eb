// The shape of data points before fitting: coincident points, zero chords, collinearity.
#include "core/curves/fitting/data_shape.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <limits>

using namespace granota;

class TestDataShape : public QObject {
    Q_OBJECT
private slots:
    void thesisDataIsGeneral()
    {
        const DataShape s = analyseDataShape({{0, 0}, {1, 3}, {4, 2}, {8, -2}, {1, 5}}); // Ex 2.7
        QVERIFY(!s.allCoincide);
        QVERIFY(!s.collinear);
        QCOMPARE(s.zeroChords, 0);
        QCOMPARE(s.firstZeroChord, -1);
    }
    void collinear_data()
    {
        QTest::addColumn<double>("scale");
        QTest::newRow("1") << 1.0;
        QTest::newRow("1e9") << 1e9;
        QTest::newRow("1e-9") << 1e-9;
    }
    void collinear()
    {
        QFETCH(double, scale);
        std::vector<Point> q;
        for (int i = 0; i < 12; ++i) {
            const double x = 0.1 * i * i - 0.9 * i; // back and forth along y = 2x + 1
            q.emplace_back(scale * x, scale * (2 * x + 1));
        }
        QVERIFY(analyseDataShape(q).collinear);
        QVERIFY(!analyseDataShape(q).allCoincide);
        q[5].y += scale * 1e-6; // off the line by a millionth of the size
        QVERIFY(!analyseDataShape(q).collinear);
    }
    void zeroChords()
    {
        const DataShape s = analyseDataShape({{0, 0}, {1, 1}, {1, 1}, {2, 0}, {2, 0}, {2, 0}});
        QCOMPARE(s.zeroChords, 3);
        QCOMPARE(s.firstZeroChord, 2);
        QVERIFY(!s.collinear);
    }
    void allCoincide()
    {
        const DataShape s = analyseDataShape({{3, 4}, {3, 4}, {3, 4}});
        QVERIFY(s.allCoincide);
        QVERIFY(s.collinear);
        QCOMPARE(s.zeroChords, 2);
        QVERIFY(analyseDataShape({}).allCoincide);
    }
    void ignoresNonFinite()
    {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const DataShape s = analyseDataShape({{0, 0}, {nan, 1}, {1, 1}, {2, 2}});
        QVERIFY(s.collinear);
        QVERIFY(!s.allCoincide);
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestDataShape)
#include "test_data_shape.moc"
