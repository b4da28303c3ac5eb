// Arc length s(t), the total L and the inverse t(s): known lengths, a cusp against a
// high-precision reference, the inverse as a property, and degenerate curves.
#include "core/curves/bezier/arc_length.h"
#include "core/curves/bezier/de_casteljau.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <random>

using namespace granota;

namespace {

/// ∫_a^b |c′| in long double by composite Simpson with `intervals` intervals, c′ from the
/// power form (exact for these small integer curves): the reference where |c′| is smooth.
long double simpson(const std::vector<Point>& p, long double a, long double b, int intervals)
{
    const int n = static_cast<int>(p.size()) - 1;
    auto speed = [&](long double t) {
        // De Casteljau on the hodograph, in long double.
        std::vector<long double> x, y;
        for (int i = 0; i < n; ++i) {
            x.push_back(n * (static_cast<long double>(p[i + 1].x) - p[i].x));
            y.push_back(n * (static_cast<long double>(p[i + 1].y) - p[i].y));
        }
        for (int m = n - 1; m > 0; --m)
            for (int i = 0; i < m; ++i) {
                x[i] = (1 - t) * x[i] + t * x[i + 1];
                y[i] = (1 - t) * y[i] + t * y[i + 1];
            }
        return std::sqrt(x[0] * x[0] + y[0] * y[0]);
    };
    const long double h = (b - a) / intervals;
    long double s = speed(a) + speed(b);
    for (int i = 1; i < intervals; ++i)
        s += (i % 2 ? 4 : 2) * speed(a + i * h);
    return s * h / 3;
}

double polygonLength(const std::vector<Point>& p)
{
    double s = 0;
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
        s += distance(p[i], p[i + 1]);
    return s;
}

std::vector<Point> randomCurve(std::mt19937& rng, int n)
{
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Point> p;
    for (int i = 0; i <= n; ++i)
        p.emplace_back(u(rng), u(rng));
    return p;
}

} // namespace

class TestArcLength : public QObject {
    Q_OBJECT
private slots:
    // (0,0),(0,1),(1,1),(1,0): |c′(t)| = 3 − 6t + 6t² (|c′|² is a perfect square), so L = 2.
    void cubicOfLengthTwo()
    {
        const std::vector<Point> p{{0, 0}, {0, 1}, {1, 1}, {1, 0}};
        QVERIFY(std::abs(arcLength(p) - 2) <= 1e-14 * 2);
        const ArcLengthParametrization a(p);
        QVERIFY(std::abs(a.total() - 2) <= 1e-14 * 2);
        // s(t) = 3t − 3t² + 2t³: s(1/2) = 1 by symmetry, s(1/4) = 3/4 − 3/16 + 1/32 = 19/32.
        QVERIFY(std::abs(a.lengthAt(0.5) - 1) < 1e-14);
        QVERIFY(std::abs(a.lengthAt(0.25) - 19.0 / 32) < 1e-14);
        QVERIFY(std::abs(a.parameterAt(19.0 / 32) - 0.25) < 1e-14);
        QVERIFY(std::abs(arcLength(p, 0.25, 0.5) - (1 - 19.0 / 32)) < 1e-14);
        QVERIFY(std::abs(arcLength(p, 0.5, 0.25) + (1 - 19.0 / 32)) < 1e-14);
    }

    // The parabola (0,0),(0.5,1),(1,0): L = (2√5 + asinh 2)/4.
    void parabola()
    {
        const std::vector<Point> p{{0, 0}, {0.5, 1}, {1, 0}};
        const double exact = (2 * std::sqrt(5.0) + std::asinh(2.0)) / 4;
        QVERIFY(std::abs(arcLength(p) - exact) <= 1e-14 * exact);
        QVERIFY(std::abs(ArcLengthParametrization(p).total() - exact) <= 1e-14 * exact);
    }

    // The cusp of (0,0),(1,1),(0,1),(1,0) at t = 1/2, where |c′| has a kink: against long
    // double Simpson on each smooth half.
    void cusp()
    {
        const std::vector<Point> p{{0, 0}, {1, 1}, {0, 1}, {1, 0}};
        const long double ref = simpson(p, 0, 0.5L, 1 << 14) + simpson(p, 0.5L, 1, 1 << 14);
        const double L = arcLength(p);
        QVERIFY2(std::abs(L - static_cast<double>(ref)) <= 1e-12 * L, qPrintable(QString::number(L - double(ref))));
        const ArcLengthParametrization a(p);
        QVERIFY(std::abs(a.total() - static_cast<double>(ref)) <= 1e-12 * L);
        QVERIFY(std::abs(a.lengthAt(0.5) - static_cast<double>(ref) / 2) <= 1e-12 * L); // symmetric
        QVERIFY(std::abs(a.parameterAt(a.total() / 2) - 0.5) < 1e-9);
    }

    // t(s(t)) = t and s(t(s)) = s on random curves of degrees 1–12; s is increasing; the
    // total lies between the chord and the control polygon's length.
    void inverseProperty()
    {
        std::mt19937 rng(2026);
        for (int trial = 0; trial < 60; ++trial) {
            const auto p = randomCurve(rng, 1 + trial % 12);
            const ArcLengthParametrization a(p);
            const double L = a.total();
            QVERIFY(L >= distance(p.front(), p.back()) * (1 - 1e-14));
            QVERIFY(L <= polygonLength(p) * (1 + 1e-14));
            QVERIFY(std::abs(L - arcLength(p)) <= 1e-12 * L);
            double previous = -1;
            for (int j = 0; j <= 40; ++j) {
                const double t = j / 40.0;
                const double s = a.lengthAt(t);
                QVERIFY(s >= previous);
                previous = s;
                QVERIFY2(std::abs(a.parameterAt(s) - t) < 1e-10, qPrintable(QString("%1 %2").arg(trial).arg(t)));
                const double s2 = L * j / 40.0;
                QVERIFY(std::abs(a.lengthAt(a.parameterAt(s2)) - s2) <= 1e-12 * L);
                QVERIFY(std::abs(a.lengthAt(t) - arcLength(p, 0, t)) <= 1e-12 * L);
            }
        }
    }

    // Degenerate curves: a single repeated point has length 0 (and t(s) = 0); a straight
    // line with uneven control points has the chord's length; degree 60 stays finite and
    // within its bounds; huge coordinates do not overflow.
    void degenerate()
    {
        QCOMPARE(arcLength({{2, 3}}), 0.0);
        QCOMPARE(arcLength({{2, 3}, {2, 3}, {2, 3}}), 0.0);
        const ArcLengthParametrization z({{2, 3}, {2, 3}});
        QCOMPARE(z.total(), 0.0);
        QCOMPARE(z.parameterAt(1.0), 0.0);
        QCOMPARE(z.lengthAt(0.7), 0.0);

        const std::vector<Point> line{{0, 0}, {0.3, 0.4}, {2.4, 3.2}, {3, 4}};
        QVERIFY(std::abs(arcLength(line) - 5) <= 1e-14 * 5);

        std::mt19937 rng(60);
        const auto p60 = randomCurve(rng, 60);
        const double L = arcLength(p60);
        QVERIFY(std::isfinite(L));
        QVERIFY(L >= distance(p60.front(), p60.back()) && L <= polygonLength(p60));
        const ArcLengthParametrization a(p60);
        QVERIFY(std::abs(a.total() - L) <= 1e-12 * L);
        QVERIFY(std::abs(a.parameterAt(a.lengthAt(0.3)) - 0.3) < 1e-10);

        std::vector<Point> huge;
        for (const Point& q : std::vector<Point>{{0, 0}, {0, 1}, {1, 1}, {1, 0}})
            huge.emplace_back(q.x * 1e300, q.y * 1e300);
        QVERIFY(std::abs(arcLength(huge) / 1e300 - 2) <= 1e-14 * 2);
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestArcLength)
#include "test_arc_length.moc"
