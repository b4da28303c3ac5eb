// κ against arc length along piecewise curves (curvature_profile.h): the samples are at
// equal steps of arc length, the knots sit where the segments' lengths add up, κ agrees with
// the curvature at the knots (knot_continuity.h), and the plot's known shapes hold: 0 on a
// straight piece, ≈ 1/r on a circle made of four cubic arcs, jumps at Catmull-Rom knots.
#include "core/curves/bezier/arc_length.h"
#include "core/curves/bezier/curvature.h"
#include "core/curves/splines/bezier_segments.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/curvature_profile.h"
#include "core/curves/splines/knot_continuity.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>

using namespace granota;

namespace {

std::vector<std::vector<Point>> polygons(const std::vector<BezierSegment<double>>& segs)
{
    std::vector<std::vector<Point>> out;
    for (const auto& b : segs)
        out.push_back({b[0], b[1], b[2], b[3]});
    return out;
}

/// The circle of radius r as four cubic arcs, k = 4(√2 − 1)/3 (the usual quarter-circle cubic).
std::vector<std::vector<Point>> circle(double r)
{
    const double k = 4.0 * (std::sqrt(2.0) - 1.0) / 3.0 * r;
    return {{{r, 0}, {r, k}, {k, r}, {0, r}},
            {{0, r}, {-k, r}, {-r, k}, {-r, 0}},
            {{-r, 0}, {-r, -k}, {-k, -r}, {0, -r}},
            {{0, -r}, {k, -r}, {r, -k}, {r, 0}}};
}

} // namespace

class TestCurvatureProfile : public QObject {
    Q_OBJECT
private slots:
    void straightPiecesHaveZeroCurvature()
    {
        const auto p = curvatureProfile({{{0, 0}, {1, 1}, {3, 3}, {4, 4}}, {{4, 4}, {4, 5}}}, 9);
        QCOMPARE(p.samples.size(), std::size_t(2));
        for (const auto& row : p.samples)
            for (const auto& s : row) {
                QVERIFY(s.kappa.has_value());
                QCOMPARE(*s.kappa, 0.0);
            }
        QVERIFY(std::fabs(p.knots[1] - 4 * std::sqrt(2.0)) < 1e-13);
        QVERIFY(std::fabs(p.length() - (4 * std::sqrt(2.0) + 1)) < 1e-13);
    }

    // Counter-clockwise, so κ > 0. Each cubic arc (k = 4(√2 − 1)/3) has at its ends
    // κ·r = (2/3)(1 − k)/k² ≈ 0.9786 (from κ(0) = (n−1)/n · (b₁ − b₀)×(b₂ − b₁)/|b₁ − b₀|³),
    // its farthest from the circle's 1; by symmetry each arc ends with the curvature the
    // next starts with.
    void circleOfFourArcs_data()
    {
        QTest::addColumn<double>("r");
        QTest::newRow("r=1") << 1.0;
        QTest::newRow("r=7.5") << 7.5;
        QTest::newRow("r=1e-6") << 1e-6;
    }
    void circleOfFourArcs()
    {
        QFETCH(double, r);
        const auto p = curvatureProfile(circle(r), 33);
        const double k = 4.0 * (std::sqrt(2.0) - 1.0) / 3.0;
        const double ends = 2.0 * (1.0 - k) / (3.0 * k * k);
        QVERIFY(std::fabs(p.length() / (2 * M_PI * r) - 1) < 1e-3);
        for (std::size_t i = 0; i < 4; ++i) {
            QVERIFY(std::fabs(p.knots[i] - i * p.length() / 4) < 1e-12 * p.length());
            for (const auto& s : p.samples[i]) {
                QVERIFY(s.kappa.has_value());
                QVERIFY2(std::fabs(*s.kappa * r - 1) <= 1 - ends + 1e-12, qPrintable(QString::number(*s.kappa * r)));
            }
            QVERIFY(std::fabs(*p.samples[i].front().kappa * r - ends) < 1e-12);
            const auto& next = p.samples[(i + 1) % 4];
            QVERIFY(std::fabs(*p.samples[i].back().kappa - *next.front().kappa) < 1e-9 / r);
        }
    }

    // Samples are at equal arc length, both ends included: s(t) of each sample's t, measured
    // independently, is the sample's s; the two samples at a knot share their s.
    void equalStepsOfArcLength()
    {
        const std::vector<Point> q{{3, 5}, {2, 2}, {6, 0}, {8, 3}, {7, 5}};
        const auto segs = catmullRomSegments(q, 0.5, CatmullRomMode::Open);
        QVERIFY(static_cast<bool>(segs));
        const auto polys = polygons(bezierSegments(*segs));
        const int m = 11;
        const auto p = curvatureProfile(polys, m);
        QCOMPARE(p.knots.size(), polys.size() + 1);
        for (std::size_t i = 0; i < polys.size(); ++i) {
            const auto& row = p.samples[i];
            QCOMPARE(static_cast<int>(row.size()), m);
            const double L = arcLength(polys[i]);
            QVERIFY(std::fabs(p.knots[i + 1] - p.knots[i] - L) < 1e-12 * p.length());
            QCOMPARE(row.front().s, p.knots[i]);
            QVERIFY(std::fabs(row.back().s - p.knots[i + 1]) < 1e-12 * p.length());
            for (int j = 1; j < m; ++j)
                QVERIFY(std::fabs(row[std::size_t(j)].s - row[std::size_t(j - 1)].s - L / (m - 1)) < 1e-10 * L);
        }
        // κ at the knots is the curvature of each side (knot_continuity.h): Ex 2.13's curve
        // jumps there (no knot is G²), by more than 1 % of the larger value.
        const auto knots = knotContinuity(*segs, {}, false, 1e-12);
        for (std::size_t j = 0; j < knots.size(); ++j) {
            const double left = *p.samples[j].back().kappa, right = *p.samples[j + 1].front().kappa;
            QVERIFY(std::fabs(left - *knots[j].curvatureLeft) < 1e-9 * std::fabs(left) + 1e-12);
            QVERIFY(std::fabs(right - *knots[j].curvatureRight) < 1e-9 * std::fabs(right) + 1e-12);
            QVERIFY(!knots[j].g2);
            QVERIFY2(std::fabs(left - right) > 0.01 * std::max(std::fabs(left), std::fabs(right)),
                     qPrintable(QString("knot %1: %2 %3").arg(j).arg(left).arg(right)));
        }
    }

    // A zero end tangent (coincident control points) leaves κ undefined there — a gap in the
    // plot, not 0 — and every other sample finite. A single repeated point has length 0.
    void undefinedCurvatureIsAGap()
    {
        const auto p = curvatureProfile({{{0, 0}, {0, 0}, {1, 1}, {2, 0}}, {{2, 0}, {2, 0}, {2, 0}}}, 7);
        QVERIFY(!p.samples[0].front().kappa.has_value());
        for (std::size_t j = 1; j < p.samples[0].size(); ++j)
            QVERIFY(p.samples[0][j].kappa && std::isfinite(*p.samples[0][j].kappa));
        for (const auto& s : p.samples[1]) {
            QVERIFY(!s.kappa.has_value());
            QCOMPARE(s.s, p.knots[1]);
        }
        QCOMPARE(p.length(), p.knots[1]);
        QVERIFY(curvatureProfile({}, 5).samples.empty());
    }

    // The rational quarter circle (1, 0), (1, 1), (0, 1) with weights 1, √2/2, 1 is the unit
    // circle's arc exactly: κ = 1 at every sample (the unit circle's curvature, counter-clockwise)
    // and s runs to π/2 (its length). A polynomial segment beside it (no weights) is sampled as
    // by the polynomial overload: the straight line after the arc has κ = 0 and length 1.
    void rationalQuarterCircle()
    {
        const double h = std::sqrt(2.0) / 2;
        const auto p = curvatureProfile({{{1, 0}, {1, 1}, {0, 1}}, {{0, 1}, {-1, 1}}}, {{1, h, 1}, {}}, 17);
        QCOMPARE(p.samples.size(), std::size_t(2));
        for (const auto& sample : p.samples[0]) {
            QVERIFY(sample.kappa.has_value());
            QVERIFY(std::fabs(*sample.kappa - 1) < 1e-12);
        }
        QCOMPARE(p.samples[0].front().s, 0.0);
        QVERIFY(std::fabs(p.knots[1] - M_PI / 2) < 1e-13);
        QCOMPARE(p.samples[1].front().s, p.knots[1]);
        for (const auto& sample : p.samples[1])
            QCOMPARE(*sample.kappa, 0.0);
        QVERIFY(std::fabs(p.length() - (M_PI / 2 + 1)) < 1e-13);
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestCurvatureProfile)
#include "test_curvature_profile.moc"
