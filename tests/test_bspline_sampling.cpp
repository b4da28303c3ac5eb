// The hot paths of B-spline evaluation. bsplinePoints (bspline_sampling.h) carries the span from
// one parameter to the next instead of a bisection each time: its points must be bsplinePoint's
// to the bit, whatever the order of the parameters — increasing (a step or two a parameter),
// jumping ahead more than its few steps, going back, at repeated knots and at both ends of the
// domain — for doubles and exactly. And bsplinePoint's unrolled degrees give deBoor's point.
#include "core/curves/bsplines/bspline_sampling.h"
#include "core/exact/rational.h"

#include <QTest>
#include "tests/test_main.h"

#include <algorithm>
#include <random>

using namespace granota;

namespace {

/// A curve of degree p on `count` points with random interior knots in [0, 1] (some repeated up
/// to p times), clamped or not, polynomial or with weights.
BSplineCurve<double> randomCurve(std::mt19937& rng, int p, int count, bool clamped, bool rational)
{
    std::uniform_real_distribution<double> unit(0, 1), coord(-1, 1), weight(0.5, 2);
    BSplineCurve<double> c;
    c.degree = p;
    for (int i = 0; i < count; ++i)
        c.points.emplace_back(coord(rng), coord(rng));
    if (rational)
        for (int i = 0; i < count; ++i)
            c.weights.push_back(weight(rng));
    const int knotCount = count + p + 1;
    std::vector<double> inner;
    const int innerCount = clamped ? knotCount - 2 * (p + 1) : knotCount;
    while (static_cast<int>(inner.size()) < innerCount) {
        const double k = unit(rng);
        const int times = std::min<int>(
            {1 + static_cast<int>(rng() % static_cast<unsigned>(p)), innerCount - static_cast<int>(inner.size()), p});
        inner.insert(inner.end(), static_cast<std::size_t>(times), k);
    }
    std::sort(inner.begin(), inner.end());
    if (clamped) {
        c.knots.assign(static_cast<std::size_t>(p + 1), 0.0);
        c.knots.insert(c.knots.end(), inner.begin(), inner.end());
        c.knots.insert(c.knots.end(), static_cast<std::size_t>(p + 1), 1.0);
    } else {
        c.knots = inner;
    }
    return c;
}

/// Parameters in the domain: every knot in it, both ends, and random ones; sorted, or shuffled.
std::vector<double> parameters(std::mt19937& rng, const BSplineCurve<double>& c, bool sorted)
{
    std::vector<double> u;
    const double a = c.domainStart(), b = c.domainEnd();
    for (double k : c.knots)
        if (a <= k && k <= b)
            u.push_back(k);
    std::uniform_real_distribution<double> in(a, b);
    for (int i = 0; i < 200; ++i)
        u.push_back(in(rng));
    std::sort(u.begin(), u.end());
    if (!sorted)
        std::shuffle(u.begin(), u.end(), rng);
    return u;
}

} // namespace

class TestBSplineSampling : public QObject {
    Q_OBJECT

private slots:
    void sameAsBsplinePointToTheBit()
    {
        std::mt19937 rng(36);
        int curves = 0;
        for (int p = 1; p <= kMaxBSplineDegree; ++p)
            for (bool clamped : {true, false})
                for (bool rational : {false, true})
                    for (bool sorted : {true, false}) {
                        const int count = p + 1 + static_cast<int>(rng() % 30u);
                        const auto c = randomCurve(rng, p, count, clamped, rational);
                        if (!checkBSpline(c))
                            continue; // an empty domain drawn at random
                        const auto u = parameters(rng, c, sorted);
                        std::vector<Point> out;
                        bsplinePoints(c, u, out);
                        QCOMPARE(out.size(), u.size());
                        for (std::size_t i = 0; i < u.size(); ++i)
                            QVERIFY2(out[i] == bsplinePoint(c, u[i]),
                                     qPrintable(QStringLiteral("degree %1, u = %2").arg(p).arg(u[i], 0, 'g', 17)));
                        ++curves;
                    }
        QVERIFY(curves >= 60); // most of the 80 drawn
    }

    // bsplinePoint unrolls degrees 2 and 3 for polynomial doubles (de_boor.h): the same
    // operations in the same order as deBoor's table, so the same point to the bit, at every
    // degree (the others take the general loop).
    void hotPathEqualsDeBoorTable()
    {
        std::mt19937 rng(7);
        for (int p = 1; p <= kMaxBSplineDegree; ++p)
            for (bool clamped : {true, false})
                for (bool rational : {false, true}) {
                    const auto c = randomCurve(rng, p, p + 1 + static_cast<int>(rng() % 20u), clamped, rational);
                    if (!checkBSpline(c))
                        continue;
                    for (double u : parameters(rng, c, true))
                        QVERIFY2(bsplinePoint(c, u) == deBoor(c, u).point(),
                                 qPrintable(QStringLiteral("degree %1, u = %2").arg(p).arg(u, 0, 'g', 17)));
                }
    }

    // Exactly: a quadratic with one interior knot, at increasing and then decreasing rational
    // parameters, both ends included (a clamped curve starts at P_0 and ends at P_n).
    void exactParametersBothWays()
    {
        BSplineCurve<Rational> c;
        c.degree = 2;
        c.points = {RPoint(Rational(0), Rational(0)), RPoint(Rational(1), Rational(1)), RPoint(Rational(2), Rational(0)),
                    RPoint(Rational(3), Rational(2))};
        c.knots = {Rational(0), Rational(0), Rational(0), frac(1, 2), Rational(1), Rational(1), Rational(1)};
        QVERIFY(checkBSpline(c));
        std::vector<Rational> u;
        for (int j = 0; j <= 16; ++j)
            u.push_back(frac(j, 16));
        for (int j = 15; j >= 0; j -= 3)
            u.push_back(frac(j, 16));
        std::vector<RPoint> out;
        bsplinePoints(c, u, out);
        for (std::size_t i = 0; i < u.size(); ++i)
            QVERIFY(out[i] == bsplinePoint(c, u[i]));
        QVERIFY(out.front() == c.points.front());
        QVERIFY(out[16] == c.points.back());
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestBSplineSampling)
#include "test_bspline_sampling.moc"
