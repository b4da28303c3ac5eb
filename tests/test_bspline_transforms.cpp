// What rewrites a B-spline without changing it (issue 36, docs/bsplines.md): the derivative
// curve (Piegl & Tiller (3.4)), degree elevation (extraction, Bézier elevation, removal),
// clamping and unclamping — every result compared exactly in Rational with the original.
#include "core/curves/bezier/degree_elevation.h"
#include "core/curves/bsplines/bspline_basis.h"
#include "core/curves/bsplines/bspline_clamping.h"
#include "core/curves/bsplines/bspline_degree_elevation.h"
#include "core/curves/bsplines/bspline_derivative.h"
#include "core/curves/bsplines/de_boor.h"
#include "core/curves/bsplines/knot_vector.h"
#include "random_bsplines.h"
#include "rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <random>

using namespace granota;
using granota::testing::randomBSpline;
using granota::testing::RandomBSplineOptions;
using granota::testing::randomRational;
using granota::testing::testParameters;

namespace {

std::vector<BSplineCurve<Rational>> randomCurves(unsigned seed, bool withRational = true)
{
    std::mt19937 rng(seed);
    std::vector<BSplineCurve<Rational>> out;
    for (int p = 1; p <= 5; ++p)
        for (int m = 1; m <= p; ++m)
            for (bool clamped : {true, false})
                for (bool rational : {false, true})
                    if (withRational || !rational)
                        for (int rep = 0; rep < 2; ++rep)
                            out.push_back(randomBSpline(rng, {p, m, 3, clamped, rational}));
    return out;
}

/// The same curve on `a`'s domain, compared exactly at every knot and inside every span.
bool sameOnDomain(const BSplineCurve<Rational>& a, const BSplineCurve<Rational>& b)
{
    if (a.domainStart() != b.domainStart() || a.domainEnd() != b.domainEnd())
        return false;
    for (const auto& u : testParameters(a))
        if (bsplinePoint(a, u) != bsplinePoint(b, u))
            return false;
    for (const auto& u : testParameters(b))
        if (bsplinePoint(a, u) != bsplinePoint(b, u))
            return false;
    return true;
}

bool clampedEnds(const BSplineCurve<Rational>& c)
{
    const auto p = static_cast<std::size_t>(c.degree);
    const auto& k = c.knots;
    return k[0] == k[p] && k[k.size() - 1] == k[k.size() - 1 - p];
}

} // namespace

class TestBSplineTransforms : public QObject {
    Q_OBJECT
private slots:
    // c′(u) from the derivative curve equals Σ N′_{i,p}(u) P_i with the basis derivatives of
    // A2.3 (themselves checked against the differentiated recursion in test_bspline_de_boor),
    // exactly, inside every span and at the domain's ends (one-sided there).
    void derivative()
    {
        for (const auto& c : randomCurves(3, false)) {
            const int p = c.degree;
            const auto d = derivativeCurve(c);
            QCOMPARE(d.degree, p - 1);
            QCOMPARE(d.pointCount(), c.pointCount() - 1);
            QCOMPARE(d.domainStart(), c.domainStart());
            QCOMPARE(d.domainEnd(), c.domainEnd());
            // A knot of multiplicity p (c only C⁰ there) makes c′ jump: a knot repeated p times in a
            // curve of degree p − 1, which checkBSpline refuses; otherwise c′ is a valid B-spline.
            int interiorMultiplicity = 0;
            for (std::size_t i = static_cast<std::size_t>(p) + 1; i < c.points.size(); ++i)
                interiorMultiplicity = std::max(interiorMultiplicity, knotMultiplicity(c.knots, c.knots[i]));
            QCOMPARE(checkBSpline(d).ok(), p >= 2 && interiorMultiplicity < p);
            for (const auto& u : testParameters(c)) {
                const int k = findSpan(c.knots, p, c.pointCount(), u);
                const bool end = u == c.domainStart() || u == c.domainEnd();
                if (!end && (u == c.knots[static_cast<std::size_t>(k)]))
                    continue; // at an interior knot c′ may jump (multiplicity p)
                const auto ders = basisDerivatives(c.knots, p, k, u, 1);
                RPoint expected(Rational(0), Rational(0));
                for (int j = 0; j <= p; ++j)
                    expected += ders[1][static_cast<std::size_t>(j)] * c.points[static_cast<std::size_t>(k - p + j)];
                QVERIFY(bsplinePoint(d, u) == expected);
            }
        }
    }

    // Degree elevation keeps the curve exactly (polynomial and rational, clamped and floating
    // ends), ends clamped, and is minimal: each interior knot of multiplicity m comes back
    // with m + 1 (the continuity C^{p−m} needs no more). With no interior knot it is the
    // Bézier degree elevation (Farin §6.1) of the control points.
    void elevation()
    {
        for (const auto& c : randomCurves(5)) {
            const auto e = elevateDegree(c);
            QVERIFY(checkBSpline(e).ok());
            QCOMPARE(e.degree, c.degree + 1);
            QCOMPARE(e.rational(), c.rational());
            QVERIFY(clampedEnds(e));
            QVERIFY(sameOnDomain(c, e));
            for (std::size_t i = static_cast<std::size_t>(c.degree) + 1; i < c.points.size(); ++i) {
                const Rational& u = c.knots[i];
                if (c.domainStart() < u && u < c.domainEnd())
                    QCOMPARE(knotMultiplicity(e.knots, u), knotMultiplicity(c.knots, u) + 1);
            }
        }
        std::mt19937 rng(6);
        for (int p = 1; p < kMaxBSplineDegree; ++p) {
            BSplineCurve<Rational> c;
            c.degree = p;
            c.points = randomRational(rng, p);
            c.knots = presetKnots<Rational>(KnotPreset::Bezier, p + 1, p);
            const auto e = elevateDegree(c);
            QVERIFY(e.points == granota::elevateDegree(c.points));
            QVERIFY(e.knots == presetKnots<Rational>(KnotPreset::Bezier, p + 2, p + 1));
        }
    }

    // Doubles: the elevated curve stays within rounding of the exact one.
    void elevationInDoubles()
    {
        for (const auto& c : randomCurves(7)) {
            BSplineCurve<double> d;
            d.degree = c.degree;
            d.points = toDouble(c.points);
            for (const auto& k : c.knots)
                d.knots.push_back(toDouble(k));
            for (const auto& w : c.weights)
                d.weights.push_back(toDouble(w));
            const auto e = elevateDegree(d);
            QVERIFY(checkBSpline(e).ok());
            QCOMPARE(e.pointCount(), elevateDegree(c).pointCount()); // every removal also made it in doubles
            for (const auto& u : testParameters(c)) {
                const RPoint exact = bsplinePoint(c, u);
                const Point fast = bsplinePoint(e, toDouble(u));
                // Coordinates below 30; a few removals and de Boor steps lose well under 1e-9.
                QVERIFY(std::abs(fast.x - toDouble(exact.x)) < 1e-9);
                QVERIFY(std::abs(fast.y - toDouble(exact.y)) < 1e-9);
            }
        }
    }

    // Clamping keeps the curve on the domain, and it then starts at P_0 and ends at P_n;
    // a clamped curve is left alone. Unclamping keeps the curve too, with p + 1 distinct
    // knots at each end; clamping it again gives the clamped curve back, and the uniform
    // preset (equal spans) comes back whole from clamp then unclamp.
    void clamping()
    {
        for (const auto& c : randomCurves(9)) {
            const auto cl = clampCurve(c);
            QVERIFY(checkBSpline(cl).ok());
            QVERIFY(clampedEnds(cl));
            QVERIFY(sameOnDomain(c, cl));
            QVERIFY(bsplinePoint(cl, cl.domainStart()) == cl.points.front());
            QVERIFY(bsplinePoint(cl, cl.domainEnd()) == cl.points.back());
            const auto again = clampCurve(cl);
            QVERIFY(again.points == cl.points && again.knots == cl.knots && again.weights == cl.weights);

            const auto floated = unclampCurve(cl);
            QVERIFY2(floated.ok(), floated.ok() ? "" : floated.error().message.c_str());
            const auto& un = floated.value();
            const auto unOk = checkBSpline(un);
            QVERIFY2(unOk.ok(), unOk.ok() ? "" : unOk.error().message.c_str());
            QVERIFY(sameOnDomain(c, un));
            const auto p = static_cast<std::size_t>(c.degree);
            for (std::size_t i = 0; i < p; ++i) {
                QVERIFY(un.knots[i] < un.knots[i + 1]);
                QVERIFY(un.knots[un.knots.size() - 2 - i] < un.knots[un.knots.size() - 1 - i]);
            }
            const auto back = clampCurve(un);
            QVERIFY(back.points == cl.points && back.knots == cl.knots && back.weights == cl.weights);
        }
        std::mt19937 rng(10);
        for (int p = 1; p <= 6; ++p)
            for (int extra = 0; extra <= 3; ++extra) {
                BSplineCurve<Rational> c;
                c.degree = p;
                c.points = randomRational(rng, p + extra);
                c.knots = presetKnots<Rational>(KnotPreset::Uniform, p + extra + 1, p);
                const auto round = unclampCurve(clampCurve(c));
                QVERIFY(round.ok());
                QVERIFY(round->knots == c.knots);
                QVERIFY(round->points == c.points);
            }
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestBSplineTransforms)
#include "test_bspline_transforms.moc"
