// Outlines for drawing (§4.9–4.12, §4.16): Processing's curveVertex shapes, the thick
// legs, the thesis's precomputed Bézier points and the per-frame least-squares fit.
#include "core/curves/fitting/least_squares_fit.h"
#include "core/softbody/outline.h"
#include "core/softbody/polygon_geometry.h"
#include "core/softbody/regular_polygon.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>

using namespace granota;

namespace {
bool contains(const std::vector<Point>& curve, Point p, double tol = 1e-9)
{
    for (const Point& q : curve)
        if (distance(p, q) < tol)
            return true;
    return false;
}
double angleBetween(Point a, Point b) { return std::acos(std::clamp(dot(a, b) / (norm(a) * norm(b)), -1.0, 1.0)); }
} // namespace

class TestOutline : public QObject {
    Q_OBJECT
private slots:
    void seedBodyOutlineHasTheSeedsCorner()
    {
        const auto v = regularPolygon({640, 360}, 120, 10);
        const int S = 9;
        const auto o = seedBodyOutline(v, S);
        QCOMPARE(int(o.size()), 10 * (S - 1) + 1); // 10 segments v0→v1 … v9→v0
        QCOMPARE(o.front(), v.front());
        QVERIFY(distance(o.back(), v.front()) < 1e-12);
        for (const Point& p : v)
            QVERIFY(contains(o, p));
        // How much the direction turns from one sample chord to the next: at v0 the curve
        // has a corner (the open curve's end tangents meet there), at v3 it is as smooth
        // as in the middle of a segment (C¹, Prop 2.3).
        const double atV0 = angleBetween(o.back() - o[o.size() - 2], o[1] - o[0]);
        const std::size_t k = 3 * (S - 1);
        const double atV3 = angleBetween(o[k] - o[k - 1], o[k + 1] - o[k]);
        QVERIFY(atV0 > 3 * atV3);
    }

    void closedOutlineIsSmoothEverywhere()
    {
        const auto v = regularPolygon({0, 0}, 100, 7);
        const int S = 17;
        const auto o = closedCatmullRomOutline(v, S);
        QCOMPARE(int(o.size()), 7 * (S - 1) + 1);
        for (const Point& p : v)
            QVERIFY(contains(o, p));
        // Every vertex of a regular polygon is alike on the closed curve: v0 included.
        const double atV0 = angleBetween(o.back() - o[o.size() - 2], o[1] - o[0]);
        const std::size_t k = 3 * (S - 1);
        const double atV3 = angleBetween(o[k] - o[k - 1], o[k + 1] - o[k]);
        QVERIFY(std::abs(atV0 - atV3) < 1e-9);
    }

    void legOutlineIsFactorThick()
    {
        // A straight horizontal leg: the outline keeps 7 px either side of the bones.
        const Point m(0, 0), e(40, 0), w(80, 0);
        const auto o = legOutline(m, e, w, 7, 5);
        QCOMPARE(o.front(), Point(0, -7)); // muscle + perp (direc.y, −direc.x)·7
        QVERIFY(contains(o, Point(80, -7)));
        QVERIFY(contains(o, Point(80, 7)));
        QVERIFY(distance(o.back(), Point(0, 7)) < 1e-12);
        for (const Point& p : o)
            QVERIFY(std::abs(p.y) <= 7 + 1.5); // Catmull-Rom overshoots only a little at the wrist
    }

    void bezierPointsShrinkTheBody()
    {
        // §4.9: "the body ends up smaller than the original polygon".
        const auto v = regularPolygon({640, 360}, 120, 10);
        const auto b = bezierBodyPoints(v, 20);
        QCOMPARE(int(b.size()), 20);
        QCOMPARE(b.front(), v.front());
        for (const Point& p : b)
            QVERIFY(pointInPolygon(p, v) || distance(p, v.front()) < 1e-9);
        QVERIFY(polygonArea(b) < 0.6 * polygonArea(v));
    }

    void outlineFitMatchesTheFittingCode_data()
    {
        QTest::addColumn<int>("degree");
        for (int n : {3, 5, 7, 10})
            QTest::newRow(qPrintable(QString::number(n))) << n;
    }
    void outlineFitMatchesTheFittingCode()
    {
        QFETCH(int, degree);
        auto v = regularPolygon({640, 360}, 120, 10);
        v[3].x += 17; // not symmetric
        OutlineFitter fitter(10, degree);
        std::vector<Point> control;
        fitter.fit(v, control);
        std::vector<Point> closed(v);
        closed.push_back(v.front());
        FitOptions options;
        options.degree = degree;
        auto reference = fitBezier(closed, options);
        QVERIFY(reference.ok());
        QCOMPARE(int(control.size()), degree + 1);
        for (int j = 0; j <= degree; ++j)
            QVERIFY(distance(control[j], reference->controlPoints[j]) < 1e-8 * 640);
        QVERIFY(std::abs(fitter.lastError() - reference->sse) < 1e-8 * (1 + reference->sse));
        // The error falls as the degree grows, and degree N interpolates the N + 1 points.
        if (degree == 10)
            QVERIFY(fitter.lastError() < 1e-12 * 640 * 640);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestOutline)
#include "test_outline.moc"
