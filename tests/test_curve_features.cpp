// Extrema, tight bounding box, inflections and cusps of Bézier curves
// (core/curves/bezier/curve_features.h), against values known in closed form.
#include "core/base/aabb.h"
#include "core/curves/bezier/bernstein.h"
#include "core/curves/bezier/curve_features.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <limits>

using namespace granota;

namespace {

bool near(double a, double b, double tolerance) { return std::fabs(a - b) <= tolerance; }

/// The box of a dense sample of the curve.
Aabb sampledBox(const std::vector<Point>& P, int m)
{
    Aabb box = Aabb::around(P.front());
    for (int j = 0; j <= m; ++j) {
        const Point p = bezierBernstein(P, j / double(m));
        box.minX = std::min(box.minX, p.x);
        box.minY = std::min(box.minY, p.y);
        box.maxX = std::max(box.maxX, p.x);
        box.maxY = std::max(box.maxY, p.y);
    }
    return box;
}

} // namespace

class TestCurveFeatures : public QObject {
    Q_OBJECT
private slots:
    // The frame of a curve tab's canvas (aabb.h's finiteBox): the finite points of both lists,
    // NaN and infinities skipped; none finite, no box. A single point has zero width and height.
    void finiteBoxSkipsWhatIsNotFinite()
    {
        const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
        QVERIFY(!finiteBox({}));
        QVERIFY(!finiteBox({Point(nan, 0), Point(inf, 1)}));
        const auto one = finiteBox({Point(2, -3)});
        QVERIFY(one && one->width() == 0 && one->height() == 0 && one->minX == 2 && one->minY == -3);
        const auto both = finiteBox({Point(1, 5), Point(nan, nan)}, {Point(-2, 7), Point(4, inf)});
        QVERIFY(both);
        QCOMPARE(both->minX, -2.0);
        QCOMPARE(both->maxX, 1.0);
        QCOMPARE(both->minY, 5.0);
        QCOMPARE(both->maxY, 7.0);
    }

    void inflectionsOfTheIssueCubic()
    {
        // (0,0),(1,0.25),(0,1),(1,0): x′y″ − y′x″ = 18(1−t)² − 22.5 t(1−t) + 4.5 t²
        // = 4.5 (2t − 1)(5t − 4): zero at t = 1/2 and t = 4/5, changing sign at both.
        const std::vector<Point> P{{0, 0}, {1, 0.25}, {0, 1}, {1, 0}};
        const auto D = curvatureNumerator(P);
        QCOMPARE(D, (std::vector<double>{18.0, -11.25, 4.5}));
        const auto f = curveFeatures(P);
        QCOMPARE(f.inflections.size(), std::size_t(2));
        QCOMPARE(f.inflections[0], 0.5);
        QVERIFY(near(f.inflections[1], 0.8, 1e-15));
        QVERIFY(!f.straight);
        QVERIFY(!f.stationary);
        QVERIFY(f.cusps.empty());
        QCOMPARE(inflectionParameters(P), f.inflections);
    }

    void quarticBoundingBox()
    {
        // x = 4t, y = 1 − (1 − t)⁴ − t⁴: the top is y(1/2) = 7/8, an extremum only a quartic
        // solver sees (bezier-js stops at cubics and returns the box of the ends: flat).
        const std::vector<Point> P{{0, 0}, {1, 1}, {2, 1}, {3, 1}, {4, 0}};
        const auto f = curveFeatures(P);
        QVERIFY(f.extremaX.empty());
        QCOMPARE(f.extremaY, std::vector<double>{0.5});
        QCOMPARE(f.bbox.minX, 0.0);
        QCOMPARE(f.bbox.minY, 0.0);
        QCOMPARE(f.bbox.maxX, 4.0);
        QVERIFY(near(f.bbox.maxY, 0.875, 1e-15));
        const Aabb box = tightBoundingBox(P);
        QCOMPARE(box.maxY, f.bbox.maxY);
    }

    void cubicExtrema()
    {
        // (0,0),(0,1),(1,1),(1,0): y′ = 3[(1, 0, −1)] = 3(1 − 2t) → y extremum at 1/2, y = 3/4;
        // x′ = 3[0, 1, 0] = 6t(1 − t) → zeros only at the ends, no interior x extremum.
        const std::vector<Point> P{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
        const auto f = curveFeatures(P);
        QVERIFY(f.extremaX.empty());
        QCOMPARE(f.extremaY, std::vector<double>{0.5});
        QCOMPARE(f.bbox.maxY, 0.75);
        QCOMPARE(f.bbox.maxX, 1.0);
        QVERIFY(f.inflections.empty());
        QVERIFY(f.cusps.empty());
    }

    void cuspAtOneHalf()
    {
        // (0,0),(1,1),(0,1),(1,0): c′ = 3[(1,1), (−1,0), (1,−1)], x′ = 3(1 − 2t)², y′ = 3(1 − 2t):
        // both vanish at 1/2. x′y″ − y′x″ = 18(1 − 2t)² touches 0 there: no inflection.
        const std::vector<Point> P{{0, 0}, {1, 1}, {0, 1}, {1, 0}};
        const auto f = curveFeatures(P);
        QCOMPARE(f.cusps, std::vector<double>{0.5});
        QCOMPARE(cuspParameters(P), f.cusps);
        QVERIFY(f.inflections.empty());
        QCOMPARE(f.extremaY, std::vector<double>{0.5});
        QCOMPARE(f.extremaX.size(), std::size_t(1)); // a double zero of x′, once
        QVERIFY(near(f.extremaX[0], 0.5, 1e-7));
        // The box: x ∈ [0, 1] (x(1/2) = 1/2), y ∈ [0, 3/4].
        QCOMPARE(f.bbox.minX, 0.0);
        QCOMPARE(f.bbox.maxX, 1.0);
        QCOMPARE(f.bbox.maxY, 0.75);
    }

    // Control points near ±1e308 (test_curvature's smallTangentAmongHugePoints): y′ = 0 at
    // t = 1/2 and x′ nearly so, but c′(1/2) = (21/4, 0) exactly, and x′ and y′ never vanish
    // together (y′ = 3e308 (1 − 2t) is 0 only at 1/2): no cusp. Before, n (P_1 − P_0) = 6e308
    // overflowed to infinity and every zero of x′ or y′ passed for a cusp. The same shape
    // with an exact cusp (cuspAtOneHalf scaled by 1e308) keeps it.
    void noFalseCuspNearTheLargestDoubles()
    {
        const std::vector<Point> P{{-1e308, 0}, {1e308, 1e308}, {0, 1e308}, {7, 0}};
        const auto f = curveFeatures(P);
        QVERIFY(f.cusps.empty());
        QVERIFY(cuspParameters(P).empty());
        QVERIFY(!f.stationary);
        QCOMPARE(f.extremaY, std::vector<double>{0.5});
        const std::vector<Point> Q{{0, 0}, {1e308, 1e308}, {0, 1e308}, {1e308, 0}};
        QCOMPARE(curveFeatures(Q).cusps, std::vector<double>{0.5});
        QCOMPARE(cuspParameters(Q), std::vector<double>{0.5});
        QVERIFY(curveFeatures(Q).inflections.empty());
    }

    void coincidentEndPointsAreCusps()
    {
        const std::vector<Point> P{{0, 0}, {0, 0}, {1, 2}, {3, 1}, {3, 1}};
        const auto f = curveFeatures(P);
        QCOMPARE(f.cusps, (std::vector<double>{0.0, 1.0}));
        // Extrema are in (0, 1) only.
        for (double t : f.extremaX)
            QVERIFY(t > 0 && t < 1);
    }

    void collinearPoints()
    {
        // On the line y = 3x, given as decimals (not collinear in binary): straight, no
        // inflection; monotone, so no extremum and no cusp.
        const std::vector<Point> P{{0, 0}, {0.1, 0.3}, {0.2, 0.6}, {0.7, 2.1}};
        const auto f = curveFeatures(P);
        QVERIFY(f.straight);
        QVERIFY(f.inflections.empty());
        QVERIFY(f.extremaX.empty());
        QVERIFY(f.cusps.empty());
        QCOMPARE(f.bbox.maxX, 0.7);
        // Back and forth on y = x: c′ = 0 where the direction reverses, so there x and y
        // extrema coincide with the cusps.
        const std::vector<Point> Q{{0, 0}, {3, 3}, {-1, -1}, {2, 2}};
        const auto g = curveFeatures(Q);
        QVERIFY(g.straight);
        QCOMPARE(g.cusps.size(), std::size_t(2));
        QCOMPARE(g.extremaX.size(), std::size_t(2));
        for (std::size_t k = 0; k < 2; ++k) {
            QVERIFY(near(g.cusps[k], g.extremaX[k], 1e-12));
            QVERIFY(near(g.extremaX[k], g.extremaY[k], 1e-12));
        }
        // A segment: degree 1.
        const auto segment = curveFeatures({{0, 0}, {2, 1}});
        QVERIFY(segment.straight);
        QVERIFY(segment.extremaX.empty() && segment.cusps.empty() && segment.inflections.empty());
    }

    void singleRepeatedPoint()
    {
        // c(t) = (2, 5) for every t: c′ ≡ 0. Flagged as stationary rather than answering
        // "every t" with a list; the box is the point; nothing is NaN.
        const auto f = curveFeatures({{2, 5}, {2, 5}, {2, 5}, {2, 5}});
        QVERIFY(f.stationary);
        QVERIFY(f.straight);
        QVERIFY(f.cusps.empty() && f.extremaX.empty() && f.extremaY.empty() && f.inflections.empty());
        QCOMPARE(f.bbox.minCorner(), Point(2, 5));
        QCOMPARE(f.bbox.maxCorner(), Point(2, 5));
        const auto one = curveFeatures({{1, 1}});
        QVERIFY(one.stationary);
        QCOMPARE(one.bbox.maxCorner(), Point(1, 1));
    }

    void degree60BoxIsTight()
    {
        // A wiggly degree-60 curve: the box contains a dense sample and is no larger than it
        // by more than the sample's spacing allows.
        std::vector<Point> P;
        for (int i = 0; i <= 60; ++i)
            P.emplace_back(i / 60.0 + 0.3 * std::sin(0.9 * i), std::cos(1.3 * i) + 0.01 * i);
        const auto f = curveFeatures(P);
        const Aabb s = sampledBox(P, 20000);
        QVERIFY(f.bbox.minX <= s.minX + 1e-14 && f.bbox.minY <= s.minY + 1e-14);
        QVERIFY(f.bbox.maxX >= s.maxX - 1e-14 && f.bbox.maxY >= s.maxY - 1e-14);
        QVERIFY(s.minX - f.bbox.minX < 1e-6 && s.minY - f.bbox.minY < 1e-6);
        QVERIFY(f.bbox.maxX - s.maxX < 1e-6 && f.bbox.maxY - s.maxY < 1e-6);
        for (const auto* list : {&f.extremaX, &f.extremaY, &f.inflections}) {
            QVERIFY(std::is_sorted(list->begin(), list->end()));
            for (double t : *list)
                QVERIFY(std::isfinite(t) && t > 0 && t < 1);
        }
        // Between consecutive inflections the turning direction keeps one sign.
        const auto D = curvatureNumerator(P);
        QCOMPARE(D.size(), std::size_t(2 * 60 - 3));
    }

    void inflectionsAreSignChanges()
    {
        // An S-curve family: the sign of x′y″ − y′x″ (as a Bernstein polynomial) differs on
        // the two sides of every inflection reported.
        const std::vector<Point> P{{0, 0}, {2, 3}, {-1, 2}, {3, -1}, {1, 4}, {4, 0}};
        const auto f = curveFeatures(P);
        QVERIFY(!f.inflections.empty());
        const auto D = curvatureNumerator(P);
        for (double t : f.inflections) {
            double v = 0, w = 0;
            const auto bl = bernsteinAll(static_cast<int>(D.size()) - 1, t - 1e-6);
            const auto br = bernsteinAll(static_cast<int>(D.size()) - 1, t + 1e-6);
            for (std::size_t k = 0; k < D.size(); ++k) {
                v += D[k] * bl[k];
                w += D[k] * br[k];
            }
            QVERIFY(v * w < 0);
        }
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestCurveFeatures)
#include "test_curve_features.moc"
