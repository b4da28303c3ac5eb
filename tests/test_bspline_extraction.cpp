// Bézier extraction in one pass (Piegl & Tiller A5.6, core/curves/bsplines/bezier_extraction.h)
// against the definition it replaces: every distinct knot of the domain inserted until it has
// multiplicity p, one knot at a time with the public Boehm insertion (knot_insertion.h), and
// the pieces read off the refined control polygon. The Bézier pieces of a curve are unique,
// so in Rational the two must agree exactly — points, weights and intervals — on seeded
// random curves: degrees 1–6, interior multiplicities 1..p, clamped, floating and mixed ends
// (a floating end whose knot is repeated too), polynomial and rational.
#include "core/curves/bsplines/bezier_extraction.h"
#include "core/curves/bsplines/knot_insertion.h"
#include "random_bsplines.h"

#include <QtTest>
#include "tests/test_main.h"

#include <algorithm>
#include <random>

using namespace granota;
using granota::testing::randomBSpline;
using granota::testing::RandomBSplineOptions;

namespace {

/// The reference: the curve refined knot by knot (each distinct knot of [u_p, u_{n+1}], the ends
/// included, raised to multiplicity p by insertKnot), the piece of span k being P_{k−p..k}.
std::vector<RationalBezierSegment<Rational>> extractionByInsertion(const BSplineCurve<Rational>& c)
{
    BSplineCurve<Rational> q = c;
    std::vector<Rational> distinct;
    for (std::size_t i = static_cast<std::size_t>(c.degree); i <= c.points.size(); ++i)
        if (distinct.empty() || distinct.back() != c.knots[i])
            distinct.push_back(c.knots[i]);
    for (const Rational& u : distinct) {
        const int s = static_cast<int>(std::count(q.knots.begin(), q.knots.end(), u));
        if (s < q.degree)
            q = insertKnot(q, u, q.degree - s);
    }
    const int p = q.degree, n = q.pointCount() - 1;
    std::vector<RationalBezierSegment<Rational>> out;
    for (int k = p; k <= n; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        if (!(q.knots[kk] < q.knots[kk + 1]))
            continue;
        RationalBezierSegment<Rational> seg;
        seg.points.assign(q.points.begin() + (k - p), q.points.begin() + (k + 1));
        if (q.rational())
            seg.weights.assign(q.weights.begin() + (k - p), q.weights.begin() + (k + 1));
        seg.start = q.knots[kk];
        seg.end = q.knots[kk + 1];
        out.push_back(std::move(seg));
    }
    return out;
}

/// A knot vector of groups of random multiplicity, the end groups up to p + 1 and the others
/// up to p (checkBSpline's rule): ends clamped, floating, or floating with a repeated knot at
/// u_p or u_{n+1}; random rational points and weights.
BSplineCurve<Rational> randomGroupedBSpline(std::mt19937& rng, int p, bool rational)
{
    std::uniform_int_distribution<int> extra(0, 5), step(1, 4), stepDen(1, 3), wNum(1, 15), wDen(1, 3);
    for (;;) {
        BSplineCurve<Rational> c;
        c.degree = p;
        const int n = p + extra(rng); // n + 1 control points
        c.points = granota::testing::randomRational(rng, n);
        if (rational)
            for (int i = 0; i <= n; ++i)
                c.weights.push_back(frac(wNum(rng), wDen(rng)));
        const auto knotCount = static_cast<std::size_t>(n + p + 2);
        Rational u(0);
        while (c.knots.size() < knotCount) {
            const int allowed = c.knots.empty() ? p + 1 : p;
            const int m = std::min(std::uniform_int_distribution<int>(1, allowed)(rng),
                                   static_cast<int>(knotCount - c.knots.size()));
            c.knots.insert(c.knots.end(), static_cast<std::size_t>(m), u);
            u += frac(step(rng), stepDen(rng));
        }
        if (checkBSpline(c).ok()) // else an empty domain: draw again
            return c;
    }
}

bool sameSegments(const std::vector<RationalBezierSegment<Rational>>& a, const std::vector<RationalBezierSegment<Rational>>& b)
{
    if (a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].points != b[i].points || a[i].weights != b[i].weights || a[i].start != b[i].start || a[i].end != b[i].end)
            return false;
    return true;
}

} // namespace

class TestBSplineExtraction : public QObject {
    Q_OBJECT
private slots:
    // The generator's curves: clamped or with p + 1 distinct knots at each end.
    void equalsInsertionOnRandomCurves()
    {
        std::mt19937 rng(3604);
        int cases = 0;
        for (int p = 1; p <= 6; ++p)
            for (int m = 1; m <= p; ++m)
                for (bool clamped : {true, false})
                    for (bool rational : {false, true})
                        for (int repeat = 0; repeat < 3; ++repeat) {
                            const auto c = randomBSpline(rng, {p, m, 4, clamped, rational});
                            QVERIFY(checkBSpline(c).ok());
                            const auto fast = toBezierSegments(c);
                            QVERIFY2(sameSegments(fast, extractionByInsertion(c)),
                                     qPrintable(QStringLiteral("p = %1, multiplicity ≤ %2, %3, %4")
                                                    .arg(p)
                                                    .arg(m)
                                                    .arg(clamped ? "clamped" : "floating")
                                                    .arg(rational ? "rational" : "polynomial")));
                            ++cases;
                        }
        QCOMPARE(cases, 6 * 7 / 2 * 2 * 2 * 3);
    }

    // Any knot vector checkBSpline accepts: repeated knots at a floating u_p or u_{n+1}, a knot
    // of multiplicity p anywhere, the two ends differently clamped.
    void equalsInsertionOnAnyKnotVector()
    {
        std::mt19937 rng(36);
        int floatingRepeatedStart = 0;
        for (int p = 1; p <= 6; ++p)
            for (bool rational : {false, true})
                for (int repeat = 0; repeat < 25; ++repeat) {
                    const auto c = randomGroupedBSpline(rng, p, rational);
                    const auto& k = c.knots;
                    const auto s = std::count(k.begin(), k.end(), c.domainStart());
                    floatingRepeatedStart += s > 1 && s < p;
                    QVERIFY2(sameSegments(toBezierSegments(c), extractionByInsertion(c)),
                             qPrintable(QStringLiteral("p = %1, %2 knots").arg(p).arg(k.size())));
                }
        // The case A5.6 leaves out (its first piece assumes u_0 = … = u_p) occurred.
        QVERIFY(floatingRepeatedStart > 0);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestBSplineExtraction)
#include "test_bspline_extraction.moc"
