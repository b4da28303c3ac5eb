// The live canvas's outlines (core/softbody/outline_sampling.h) against the reference outlines of
// core/softbody/outline.h and de_casteljau.h: the same points, and no allocation once warm.
#include "core/curves/bezier/de_casteljau.h"
#include "core/softbody/outline.h"
#include "core/softbody/outline_sampling.h"
#include "core/softbody/regular_polygon.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <limits>

using namespace granota;

Q_DECLARE_METATYPE(std::vector<granota::Point>)

namespace {

/// Largest distance between corresponding points; NaN where exactly one side is NaN.
double maxDeviation(const std::vector<Point>& a, const std::vector<Point>& b)
{
    double worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const bool na = !isFinite(a[i]), nb = !isFinite(b[i]);
        if (na || nb) {
            if (na != nb)
                return std::numeric_limits<double>::quiet_NaN();
            continue;
        }
        worst = std::max(worst, distance(a[i], b[i]));
    }
    return worst;
}

std::vector<Point> wobbly(int n)
{
    auto v = regularPolygon({640, 360}, 120, n);
    for (int i = 0; i < n; ++i) // a squashed, irregular body as the seed leaves it on the floor
        v[std::size_t(i)] += Point(9 * std::sin(1.7 * i), 23 * std::cos(0.9 * i * i));
    return v;
}

} // namespace

class TestOutlineSampling : public QObject {
    Q_OBJECT
private slots:
    void bodyOutlinesMatch_data()
    {
        QTest::addColumn<std::vector<Point>>("vertices");
        QTest::addColumn<int>("samples");
        QTest::newRow("frog N=10") << regularPolygon({640, 360}, 120, 10) << 9;
        QTest::newRow("wobbly N=10") << wobbly(10) << 12;
        QTest::newRow("triangle") << regularPolygon({0, 0}, 1, 3) << 2;
        QTest::newRow("N=200") << wobbly(200) << 3;
        QTest::newRow("coincident") << std::vector<Point>(6, Point(5, 5)) << 5;
        QTest::newRow("huge") << regularPolygon({1e9, -1e9}, 1e8, 7) << 6;
        QTest::newRow("two points") << std::vector<Point>{{0, 0}, {10, 0}} << 4;
        QTest::newRow("NaN") << std::vector<Point>{{0, 0}, {10, 0}, {std::nan(""), 3}, {0, 10}} << 4;
    }
    void bodyOutlinesMatch()
    {
        QFETCH(std::vector<Point>, vertices);
        QFETCH(int, samples);
        std::vector<Point> out;
        sampleSeedBodyOutline(vertices, samples, out);
        const auto seed = seedBodyOutline(vertices, samples);
        QCOMPARE(out.size(), seed.size());
        QVERIFY(maxDeviation(out, seed) <= 1e-12 * (1 + std::abs(vertices.front().x)));

        for (double tau : {0.5, 0.0, -3.0, 10.0}) {
            sampleClosedCatmullRomOutline(vertices, samples, tau, out);
            const auto closed = closedCatmullRomOutline(vertices, samples, tau);
            QCOMPARE(out.size(), closed.size());
            QVERIFY(maxDeviation(out, closed) <= 1e-12 * (1 + std::abs(vertices.front().x)));
        }
    }

    void legOutlinesMatch_data()
    {
        QTest::addColumn<Point>("shoulder");
        QTest::addColumn<Point>("elbow");
        QTest::addColumn<Point>("wrist");
        QTest::newRow("straight") << Point(0, 0) << Point(40, 0) << Point(80, 0);
        QTest::newRow("bent") << Point(600, 400) << Point(640, 430) << Point(610, 470);
        QTest::newRow("folded") << Point(0, 0) << Point(0, 80) << Point(0, 0);
        QTest::newRow("collapsed") << Point(3, 3) << Point(3, 3) << Point(3, 3);
    }
    void legOutlinesMatch()
    {
        QFETCH(Point, shoulder);
        QFETCH(Point, elbow);
        QFETCH(Point, wrist);
        std::vector<Point> out;
        sampleLegOutline(shoulder, elbow, wrist, 7, 6, out);
        const auto reference = legOutline(shoulder, elbow, wrist, 7, 6);
        QCOMPARE(out.size(), reference.size());
        QVERIFY(maxDeviation(out, reference) <= 1e-12);
    }

    void bezierMatches_data()
    {
        QTest::addColumn<int>("degree");
        QTest::addColumn<int>("samples");
        QTest::newRow("point") << 0 << 5;
        QTest::newRow("cubic") << 3 << 2;
        QTest::newRow("degree 7") << 7 << 120;
        QTest::newRow("degree 30") << 30 << 64;
    }
    void bezierMatches()
    {
        QFETCH(int, degree);
        QFETCH(int, samples);
        const auto control = wobbly(degree + 3);
        const std::vector<Point> p(control.begin(), control.begin() + degree + 1);
        std::vector<Point> out, work;
        sampleBezierCurve(p, samples, work, out);
        const auto reference = sampleBezier(p, samples);
        QCOMPARE(out.size(), reference.size());
        QVERIFY(maxDeviation(out, reference) == 0); // the same arithmetic, in the same order
    }

    void noAllocationOnceWarm()
    {
        // The second frame reuses the first frame's storage: same buffer, same capacity.
        std::vector<Point> body, leg, curve, work;
        const auto v1 = wobbly(10), v2 = regularPolygon({300, 200}, 90, 10);
        sampleSeedBodyOutline(v1, 8, body);
        sampleLegOutline({0, 0}, {40, 5}, {70, 40}, 7, 8, leg);
        sampleBezierCurve(v1, 100, work, curve);
        const Point* bodyData = body.data();
        const Point* legData = leg.data();
        const Point* curveData = curve.data();
        const Point* workData = work.data();
        sampleSeedBodyOutline(v2, 8, body);
        sampleLegOutline({10, 0}, {50, 5}, {80, 40}, 7, 8, leg);
        sampleBezierCurve(v2, 100, work, curve);
        QCOMPARE(body.data(), bodyData);
        QCOMPARE(leg.data(), legData);
        QCOMPARE(curve.data(), curveData);
        QCOMPARE(work.data(), workData);
        QCOMPARE(body.front(), v2.front()); // and the content is the new frame's
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestOutlineSampling)
#include "test_outline_sampling.moc"
