// B-spline curves (issue 36, docs/bsplines.md): the knot presets, the span of a parameter, the
// basis functions (Cox–de Boor and Piegl & Tiller A2.2–A2.3) and de Boor's algorithm, every
// property checked exactly in Rational; the refusals of checkBSpline.
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bsplines/bspline_basis.h"
#include "core/curves/bsplines/bspline_curve.h"
#include "core/curves/bsplines/de_boor.h"
#include "core/curves/bsplines/knot_vector.h"
#include "random_bsplines.h"
#include "rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <random>

using namespace granota;
using granota::testing::pts;
using granota::testing::randomBSpline;
using granota::testing::RandomBSplineOptions;
using granota::testing::randomRational;
using granota::testing::testParameters;

namespace {

std::vector<Rational> rationals(std::initializer_list<std::pair<long, long>> list)
{
    std::vector<Rational> out;
    for (auto [p, q] : list)
        out.push_back(frac(p, q));
    return out;
}

BSplineCurve<Rational> curve(int degree, std::vector<RPoint> points, std::vector<Rational> knots,
                             std::vector<Rational> weights = {})
{
    BSplineCurve<Rational> c;
    c.degree = degree;
    c.points = std::move(points);
    c.knots = std::move(knots);
    c.weights = std::move(weights);
    return c;
}

/// Every random curve family the property tests run on: degrees 1–5, clamped and floating
/// ends, interior knots repeated up to p times, polynomial and rational.
std::vector<BSplineCurve<Rational>> randomCurves()
{
    std::mt19937 rng(36);
    std::vector<BSplineCurve<Rational>> out;
    for (int p = 1; p <= 5; ++p)
        for (int m = 1; m <= p; ++m)
            for (bool clamped : {true, false})
                for (bool rational : {false, true})
                    for (int rep = 0; rep < 2; ++rep)
                        out.push_back(randomBSpline(rng, {p, m, 3, clamped, rational}));
    return out;
}

} // namespace

class TestBSplineDeBoor : public QObject {
    Q_OBJECT
private slots:
    // Every random curve passes the check (otherwise the property tests below test nothing).
    void randomCurvesAreValid()
    {
        for (const auto& c : randomCurves()) {
            const auto ok = checkBSpline(c);
            QVERIFY2(ok.ok(), ok.ok() ? "" : ok.error().message.c_str());
        }
    }

    // The presets, written out by hand from their definitions (knot_vector.h).
    void presets()
    {
        QCOMPARE(presetKnots<Rational>(KnotPreset::Clamped, 5, 2),
                 rationals({{0, 1}, {0, 1}, {0, 1}, {1, 3}, {2, 3}, {1, 1}, {1, 1}, {1, 1}}));
        QCOMPARE(presetKnots<Rational>(KnotPreset::Uniform, 4, 2),
                 rationals({{0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}, {6, 1}}));
        QCOMPARE(presetKnots<Rational>(KnotPreset::Bezier, 3, 2), rationals({{0, 1}, {0, 1}, {0, 1}, {1, 1}, {1, 1}, {1, 1}}));
        // Bezier exists only for n = p, and no preset for fewer than p + 1 points.
        QVERIFY(presetKnots<Rational>(KnotPreset::Bezier, 4, 2).empty());
        QVERIFY(presetKnots<Rational>(KnotPreset::Clamped, 2, 2).empty());
        // Every preset makes a valid curve for every degree 1..10 and up to 13 points.
        for (int p = 1; p <= kMaxBSplineDegree; ++p)
            for (int count = p + 1; count <= p + 3; ++count)
                for (KnotPreset preset : {KnotPreset::Clamped, KnotPreset::Uniform, KnotPreset::Bezier}) {
                    BSplineCurve<double> c;
                    c.degree = p;
                    c.points.assign(static_cast<std::size_t>(count), Point(1, 2));
                    c.knots = presetKnots<double>(preset, count, p);
                    const bool exists = preset != KnotPreset::Bezier || count == p + 1;
                    QCOMPARE(checkBSpline(c).ok(), exists);
                }
    }

    // findSpan: u_k ≤ u < u_{k+1}; the domain's end gives the last non-empty span; outside
    // the domain the end spans. knotMultiplicity counts equal knots.
    void spans()
    {
        // p = 2, n = 5: u = 0 0 0 1 1 2 3 3 3; domain [u_2, u_6] = [0, 3]; spans 2, 4, 5.
        const auto knots = rationals({{0, 1}, {0, 1}, {0, 1}, {1, 1}, {1, 1}, {2, 1}, {3, 1}, {3, 1}, {3, 1}});
        QCOMPARE(findSpan(knots, 2, 6, Rational(0)), 2);
        QCOMPARE(findSpan(knots, 2, 6, frac(1, 2)), 2);
        QCOMPARE(findSpan(knots, 2, 6, Rational(1)), 4);
        QCOMPARE(findSpan(knots, 2, 6, frac(3, 2)), 4);
        QCOMPARE(findSpan(knots, 2, 6, Rational(2)), 5);
        QCOMPARE(findSpan(knots, 2, 6, Rational(3)), 5);
        QCOMPARE(findSpan(knots, 2, 6, Rational(-1)), 2);
        QCOMPARE(findSpan(knots, 2, 6, Rational(7)), 5);
        QCOMPARE(knotMultiplicity(knots, Rational(0)), 3);
        QCOMPARE(knotMultiplicity(knots, Rational(1)), 2);
        QCOMPARE(knotMultiplicity(knots, Rational(2)), 1);
        QCOMPARE(knotMultiplicity(knots, frac(1, 2)), 0);
        // A floating end: p = 1, u = 0 1 2 3, domain [1, 2]; u = 2 is in span 1, not 2.
        const auto uniform = presetKnots<Rational>(KnotPreset::Uniform, 2, 1);
        QCOMPARE(findSpan(uniform, 1, 2, Rational(2)), 1);
        QCOMPARE(findSpan(uniform, 1, 2, Rational(1)), 1);
        // Every random curve: the span found contains u (closed at the domain's end).
        for (const auto& c : randomCurves())
            for (const auto& u : testParameters(c)) {
                const int k = findSpan(c.knots, c.degree, c.pointCount(), u);
                const auto K = [&](int i) { return c.knots[static_cast<std::size_t>(i)]; };
                QVERIFY(k >= c.degree && k < c.pointCount());
                QVERIFY(K(k) < K(k + 1));
                QVERIFY(K(k) <= u);
                QVERIFY(u < K(k + 1) || (u == c.domainEnd() && K(k + 1) == u));
            }
    }

    // Partition of unity and non-negativity, exactly; the Cox–de Boor recursion (basisFunction)
    // agrees with A2.2 (basisFunctions) on the span's p + 1 functions and is 0 for the others.
    void partitionOfUnity()
    {
        for (const auto& c : randomCurves())
            for (const auto& u : testParameters(c)) {
                const int p = c.degree, n = c.pointCount() - 1;
                const int k = findSpan(c.knots, p, n + 1, u);
                const auto N = basisFunctions(c.knots, p, k, u);
                QCOMPARE(static_cast<int>(N.size()), p + 1);
                Rational sum(0);
                for (const auto& v : N) {
                    QVERIFY(v >= 0);
                    sum += v;
                }
                QCOMPARE(sum, Rational(1));
                for (int i = 0; i <= n; ++i) {
                    const Rational expected = (i >= k - p && i <= k) ? N[static_cast<std::size_t>(i - (k - p))] : Rational(0);
                    QCOMPARE(basisFunction(c.knots, i, p, u), expected);
                }
            }
    }

    // basisFunctionsInto (the caller's fixed array, no allocation) writes the values of the
    // Cox–de Boor recursion (basisFunction, computed independently) into N[0..p], and nothing
    // past them (a sentinel there stays).
    void basisIntoCallerStorage()
    {
        for (const auto& c : randomCurves())
            for (const auto& u : testParameters(c)) {
                const int p = c.degree, n = c.pointCount() - 1;
                const int k = findSpan(c.knots, p, n + 1, u);
                BasisValues<Rational> N;
                N.fill(Rational(-7));
                basisFunctionsInto(c.knots, p, k, u, N);
                for (int j = 0; j <= kMaxBSplineDegree; ++j) {
                    const auto jj = static_cast<std::size_t>(j);
                    QCOMPARE(N[jj], j <= p ? basisFunction(c.knots, k - p + j, p, u) : Rational(-7));
                }
            }
    }

    // N_{i,p} is zero outside [u_i, u_{i+p+1}) and positive inside (u_i, u_{i+p+1}) — checked
    // at every knot and inside every span of the domain.
    void support()
    {
        for (const auto& c : randomCurves()) {
            const int p = c.degree, n = c.pointCount() - 1;
            for (const auto& u : testParameters(c)) {
                if (u == c.domainEnd())
                    continue; // closed on the right there by convention (bspline_basis.h)
                for (int i = 0; i <= n; ++i) {
                    const Rational& a = c.knots[static_cast<std::size_t>(i)];
                    const Rational& b = c.knots[static_cast<std::size_t>(i + p + 1)];
                    const Rational v = basisFunction(c.knots, i, p, u);
                    if (u < a || u >= b)
                        QCOMPARE(v, Rational(0));
                    else if (a < u)
                        QVERIFY(v > 0);
                }
            }
        }
    }

    // The derivatives of A2.3 against the derivative of the Cox–de Boor recursion,
    //   N'_{i,p} = p/(u_{i+p} − u_i) N_{i,p−1} − p/(u_{i+p+1} − u_{i+1}) N_{i+1,p−1}
    // (Piegl & Tiller eq. (2.7)), evaluated by basisFunction of degree p − 1 inside the spans;
    // the second derivative likewise from the first; derivatives above p are 0.
    void derivatives()
    {
        const auto firstDerivative = [](const std::vector<Rational>& knots, int i, int p, const Rational& u) {
            const auto K = [&](int j) { return knots[static_cast<std::size_t>(j)]; };
            Rational d(0);
            if (K(i + p) != K(i))
                d += Rational(p) / (K(i + p) - K(i)) * basisFunction(knots, i, p - 1, u);
            if (K(i + p + 1) != K(i + 1))
                d -= Rational(p) / (K(i + p + 1) - K(i + 1)) * basisFunction(knots, i + 1, p - 1, u);
            return d;
        };
        std::mt19937 rng(2);
        for (int p = 2; p <= 5; ++p)
            for (int rep = 0; rep < 3; ++rep) {
                const auto c = randomBSpline(rng, {p, p - 1, 3, rep != 1, false});
                for (const auto& u : testParameters(c)) {
                    const int k = findSpan(c.knots, p, c.pointCount(), u);
                    if (u == c.knots[static_cast<std::size_t>(k)] || u == c.knots[static_cast<std::size_t>(k + 1)])
                        continue; // a knot: one-sided derivatives may differ
                    const auto ders = basisDerivatives(c.knots, p, k, u, p + 2);
                    QCOMPARE(static_cast<int>(ders.size()), p + 3);
                    QCOMPARE(ders[0], basisFunctions(c.knots, p, k, u));
                    for (int j = 0; j <= p; ++j) {
                        const int i = k - p + j;
                        QCOMPARE(ders[1][static_cast<std::size_t>(j)], firstDerivative(c.knots, i, p, u));
                        // N''_{i,p} = p/(u_{i+p} − u_i) N'_{i,p−1} − p/(u_{i+p+1} − u_{i+1}) N'_{i+1,p−1}
                        const auto K = [&](int m) { return c.knots[static_cast<std::size_t>(m)]; };
                        Rational second(0);
                        if (K(i + p) != K(i))
                            second += Rational(p) / (K(i + p) - K(i)) * firstDerivative(c.knots, i, p - 1, u);
                        if (K(i + p + 1) != K(i + 1))
                            second -= Rational(p) / (K(i + p + 1) - K(i + 1)) * firstDerivative(c.knots, i + 1, p - 1, u);
                        QCOMPARE(ders[2][static_cast<std::size_t>(j)], second);
                        QCOMPARE(ders[static_cast<std::size_t>(p + 1)][static_cast<std::size_t>(j)], Rational(0));
                        QCOMPARE(ders[static_cast<std::size_t>(p + 2)][static_cast<std::size_t>(j)], Rational(0));
                    }
                }
            }
    }

    // On the clamped vector with no interior knot the B-spline is the Bézier curve: de Boor's
    // table equals De Casteljau's (Def 2.4) entry by entry, exactly, for degrees 1–10.
    void clampedIsBezier()
    {
        std::mt19937 rng(1972);
        for (int p = 1; p <= kMaxBSplineDegree; ++p) {
            BSplineCurve<Rational> c;
            c.degree = p;
            c.points = randomRational(rng, p);
            c.knots = presetKnots<Rational>(KnotPreset::Bezier, p + 1, p);
            QVERIFY(checkBSpline(c).ok());
            for (const Rational& u : {Rational(0), frac(1, 7), frac(1, 3), frac(1, 2), frac(5, 8), frac(99, 100), Rational(1)}) {
                const auto bezier = deCasteljau(c.points, u);
                const auto table = deBoor(c, u);
                QCOMPARE(table.span, p);
                QCOMPARE(table.degree(), p);
                QVERIFY(table.weightLevels.empty());
                for (int r = 0; r <= p; ++r)
                    QVERIFY(table.levels[static_cast<std::size_t>(r)] == bezier.levels[static_cast<std::size_t>(r)]);
                QVERIFY(table.point() == bezier.point());
                QVERIFY(bsplinePoint(c, u) == bezier.point());
            }
        }
    }

    // A rational B-spline on the Bézier knots is the rational Bézier curve
    // Σ w_i B_i^p P_i / Σ w_i B_i^p, computed here from the Bernstein polynomials directly;
    // equal weights give the polynomial curve.
    void rationalBezier()
    {
        std::mt19937 rng(1980);
        for (int p = 1; p <= 6; ++p) {
            auto c = randomBSpline(rng, {p, 1, 0, true, true});
            QCOMPARE(c.pointCount(), p + 1);
            const Rational a = c.domainStart(), b = c.domainEnd();
            for (const Rational& t : {Rational(0), frac(1, 5), frac(1, 2), frac(6, 7), Rational(1)}) {
                const Rational u = a + t * (b - a); // the Bernstein parameter t on [u_p, u_{p+1}]
                Rational sx(0), sy(0), sw(0);
                for (int i = 0; i <= p; ++i) {
                    Rational B = binomial(p, i);
                    for (int j = 0; j < i; ++j)
                        B *= t;
                    for (int j = 0; j < p - i; ++j)
                        B *= Rational(1 - t);
                    const auto& w = c.weights[static_cast<std::size_t>(i)];
                    const auto& P = c.points[static_cast<std::size_t>(i)];
                    sx += w * B * P.x;
                    sy += w * B * P.y;
                    sw += w * B;
                }
                const RPoint expected(Rational(sx / sw), Rational(sy / sw));
                const auto table = deBoor(c, u);
                QVERIFY(table.point() == expected);
                QVERIFY(bsplinePoint(c, u) == expected);
                QCOMPARE(table.weightLevels.back().front(), sw); // the point's weight is Σ w_i B_i^p
                QVERIFY(table.levels.front() == c.points);
                QVERIFY(table.weightLevels.front() == c.weights);
            }
            auto equal = c;
            equal.weights.assign(c.weights.size(), Rational(3));
            auto polynomial = c;
            polynomial.weights.clear();
            for (const Rational& u : {frac(1, 3), frac(3, 4)})
                QVERIFY(bsplinePoint(equal, u) == bsplinePoint(polynomial, u));
        }
    }

    // The uniform cubic B-spline starts at (P_0 + 4 P_1 + P_2)/6 and ends at
    // (P_{n−2} + 4 P_{n−1} + P_n)/6 (N_{i,3} at a knot of the uniform vector: 1/6, 4/6, 1/6).
    void uniformCubicEnds()
    {
        const auto P = pts({{0, 0}, {6, 12}, {12, 0}, {18, 6}, {30, 0}});
        const auto c = curve(3, P, presetKnots<Rational>(KnotPreset::Uniform, 5, 3));
        QVERIFY(checkBSpline(c).ok());
        QVERIFY(bsplinePoint(c, c.domainStart()) == RPoint(Rational(6), Rational(8))); // (0 + 24 + 12, 0 + 48 + 0)/6
        QVERIFY(bsplinePoint(c, c.domainEnd()) == RPoint(Rational(19), Rational(4)));  // (12 + 72 + 30, 0 + 24 + 0)/6
    }

    // De Boor's table: level 0 holds the span's p + 1 points P_{k−p}..P_k, level r has p + 1 − r
    // points, the last one is bsplinePoint; for a rational curve the point is the homogeneous
    // sum Σ w_i N_{i,p} P_i / Σ w_i N_{i,p} of the basis functions.
    void deBoorLevels()
    {
        for (const auto& c : randomCurves())
            for (const auto& u : testParameters(c)) {
                const int p = c.degree;
                const auto t = deBoor(c, u);
                const int k = t.span;
                QCOMPARE(k, findSpan(c.knots, p, c.pointCount(), u));
                QCOMPARE(static_cast<int>(t.levels.size()), p + 1);
                for (int r = 0; r <= p; ++r)
                    QCOMPARE(static_cast<int>(t.levels[static_cast<std::size_t>(r)].size()), p + 1 - r);
                const std::vector<RPoint> span(c.points.begin() + (k - p), c.points.begin() + (k + 1));
                QVERIFY(t.levels.front() == span);
                QVERIFY(t.point() == bsplinePoint(c, u));
                const auto N = basisFunctions(c.knots, p, k, u);
                Rational sx(0), sy(0), sw(0);
                for (int j = 0; j <= p; ++j) {
                    const auto i = static_cast<std::size_t>(k - p + j);
                    const Rational w = c.rational() ? c.weights[i] : Rational(1);
                    sx += w * N[static_cast<std::size_t>(j)] * c.points[i].x;
                    sy += w * N[static_cast<std::size_t>(j)] * c.points[i].y;
                    sw += w * N[static_cast<std::size_t>(j)];
                }
                QVERIFY(t.point() == RPoint(Rational(sx / sw), Rational(sy / sw)));
                QCOMPARE(t.weightLevels.size(), c.rational() ? t.levels.size() : std::size_t(0));
            }
    }

    // A clamped curve interpolates its end points; the doubles agree with the exact values.
    void endsAndDoubles()
    {
        for (const auto& c : randomCurves()) {
            if (c.knots.front() == c.knots[static_cast<std::size_t>(c.degree)]) { // clamped
                QVERIFY(bsplinePoint(c, c.domainStart()) == c.points.front());
                QVERIFY(bsplinePoint(c, c.domainEnd()) == c.points.back());
            }
            BSplineCurve<double> d;
            d.degree = c.degree;
            d.points = toDouble(c.points);
            for (const auto& k : c.knots)
                d.knots.push_back(toDouble(k));
            for (const auto& w : c.weights)
                d.weights.push_back(toDouble(w));
            QVERIFY(checkBSpline(d).ok());
            for (const auto& u : testParameters(c)) {
                const RPoint exact = bsplinePoint(c, u);
                const Point fast = bsplinePoint(d, toDouble(u));
                // The coordinates are below 30 in size; de Boor's convex combinations lose a few ulps.
                QVERIFY(std::abs(fast.x - toDouble(exact.x)) < 1e-12);
                QVERIFY(std::abs(fast.y - toDouble(exact.y)) < 1e-12);
            }
        }
    }

    // What checkBSpline refuses, each with a message naming the fault.
    void refusals_data()
    {
        QTest::addColumn<int>("degree");
        QTest::addColumn<int>("points");
        QTest::addColumn<QString>("knots");
        QTest::addColumn<QString>("weights");
        QTest::addColumn<QString>("message");
        QTest::newRow("degree 0") << 0 << 2 << "0 0 1 1"
                                  << ""
                                  << "degree of a B-spline must be from 1 to 10, not 0";
        QTest::newRow("degree 11") << 11 << 12 << ""
                                   << ""
                                   << "from 1 to 10, not 11";
        QTest::newRow("too few points") << 3 << 3 << "0 0 0 0 1 1 1"
                                        << ""
                                        << "needs at least 4 control points, not 3";
        QTest::newRow("knot count") << 2 << 4 << "0 0 0 1 1 1"
                                    << ""
                                    << "needs n + p + 2 = 7 knots, not 6";
        QTest::newRow("decreasing") << 2 << 4 << "0 0 0 2 1 1 1"
                                    << ""
                                    << "must not decrease: u_3 = 2 > u_4 = 1";
        QTest::newRow("interior multiplicity")
            << 2 << 6 << "0 0 0 1/2 1/2 1/2 1 1 1"
            << ""
            << "the knot 1/2 is repeated 3 times; a B-spline of degree 2 allows at most 2 inside";
        QTest::newRow("end multiplicity") << 2 << 4 << "0 0 0 0 1 1 1"
                                          << ""
                                          << "knot 0 is repeated 4 times; a B-spline of degree 2 allows at most 3 at an end";
        QTest::newRow("empty domain") << 2 << 3 << "0 1 2 2 3 4"
                                      << ""
                                      << "the domain [u_p, u_{n+1}] = [2, 2] is empty";
        QTest::newRow("weight count") << 2 << 3 << "0 0 0 1 1 1"
                                      << "1 1"
                                      << "one weight per control point: 3 weights, not 2";
        QTest::newRow("weight zero") << 2 << 3 << "0 0 0 1 1 1"
                                     << "1 0 1"
                                     << "weight w_1 = 0 must be positive";
        QTest::newRow("weight negative") << 2 << 3 << "0 0 0 1 1 1"
                                         << "1 1 -1/2"
                                         << "weight w_2 = -1/2 must be positive";
    }
    void refusals()
    {
        QFETCH(int, degree);
        QFETCH(int, points);
        QFETCH(QString, knots);
        QFETCH(QString, weights);
        QFETCH(QString, message);
        BSplineCurve<Rational> c;
        c.degree = degree;
        for (int i = 0; i < points; ++i)
            c.points.emplace_back(Rational(i), Rational(i * i));
        for (const auto& k : knots.split(' ', Qt::SkipEmptyParts))
            c.knots.push_back(*parseRational(k.toStdString()));
        for (const auto& w : weights.split(' ', Qt::SkipEmptyParts))
            c.weights.push_back(*parseRational(w.toStdString()));
        const auto check = checkBSpline(c);
        QVERIFY(!check.ok());
        QVERIFY2(check.error().message.find(message.toStdString()) != std::string::npos, check.error().message.c_str());
    }

    // The refusals carry the sentence and its values for the GUI's translation (message_id.h):
    // a knot that is a fraction keeps its exact text, whole numbers are numbers.
    void messageIds()
    {
        BSplineCurve<Rational> c;
        c.degree = 2;
        for (int i = 0; i < 6; ++i)
            c.points.emplace_back(Rational(i), Rational(0));
        c.knots = {0, 0, 0, frac(1, 2), frac(1, 2), frac(1, 2), 1, 1, 1};
        auto e = checkBSpline(c).error();
        QCOMPARE(e.id, MessageId::BSplineInteriorMultiplicity);
        QCOMPARE(e.args.size(), std::size_t(4));
        QCOMPARE(e.args[0].text, std::string("1/2"));
        QCOMPARE(e.args[1].number, std::optional<double>(3));
        QCOMPARE(e.args[3].number, std::optional<double>(2));
        c.knots.pop_back();
        e = checkBSpline(c).error();
        QCOMPARE(e.id, MessageId::BSplineKnotCount);
        QCOMPARE(e.args[2].number, std::optional<double>(9));
        QCOMPARE(e.args[3].number, std::optional<double>(8));
        c.knots = {0, 0, 0, frac(1, 3), frac(2, 3), frac(3, 4), 1, 1, 1};
        c.weights = {1, 1, 1, Rational(-2), 1, 1};
        e = checkBSpline(c).error();
        QCOMPARE(e.id, MessageId::BSplineWeightNotPositive);
        QCOMPARE(e.args[0].number, std::optional<double>(3));
        QCOMPARE(e.args[1].number, std::optional<double>(-2));
    }

    // Non-finite doubles are refused, naming the value.
    void nonFinite()
    {
        BSplineCurve<double> c;
        c.degree = 1;
        c.points = {Point(0, 0), Point(1, 1)};
        c.knots = {0, 0, 1, 1};
        QVERIFY(checkBSpline(c).ok());
        auto bad = c;
        bad.points[1].y = std::nan("");
        QCOMPARE(checkBSpline(bad).error().message, std::string("control point P_1 is not finite"));
        bad = c;
        bad.knots[3] = HUGE_VAL;
        QCOMPARE(checkBSpline(bad).error().message, std::string("knot u_3 is not finite"));
        bad = c;
        bad.weights = {1, std::nan("")};
        QCOMPARE(checkBSpline(bad).error().message, std::string("weight w_1 is not finite"));
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestBSplineDeBoor)
#include "test_bspline_de_boor.moc"
