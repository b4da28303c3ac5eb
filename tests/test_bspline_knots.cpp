// Knot insertion (Boehm 1980), knot removal (Tiller 1992, Piegl & Tiller A5.8) and Bézier
// extraction (issue 36, docs/bsplines.md): the curve never changes, exactly in Rational; the
// two NURBS-Python bug reports (#135, #158) as regression cases.
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bsplines/bezier_extraction.h"
#include "core/curves/bsplines/de_boor.h"
#include "core/curves/bsplines/knot_insertion.h"
#include "core/curves/bsplines/knot_removal.h"
#include "core/curves/bsplines/knot_vector.h"
#include "random_bsplines.h"
#include "rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <random>

using namespace granota;
using granota::testing::pts;
using granota::testing::randomBSpline;
using granota::testing::RandomBSplineOptions;
using granota::testing::testParameters;

namespace {

std::vector<Rational> ints(std::initializer_list<long> list)
{
    std::vector<Rational> out;
    for (long v : list)
        out.emplace_back(v);
    return out;
}

bool sameCurve(const BSplineCurve<Rational>& a, const BSplineCurve<Rational>& b)
{
    return a.degree == b.degree && a.points == b.points && a.weights == b.weights && a.knots == b.knots;
}

/// The curve is the same: equal at every knot and inside every span of `a`'s domain.
bool sameShape(const BSplineCurve<Rational>& a, const BSplineCurve<Rational>& b)
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

/// A random rational parameter strictly inside the domain: a/b of the way, 0 < a < b ≤ 9.
Rational randomInside(std::mt19937& rng, const BSplineCurve<Rational>& c)
{
    std::uniform_int_distribution<int> den(2, 9);
    const int b = den(rng);
    std::uniform_int_distribution<int> num(1, b - 1);
    return c.domainStart() + frac(num(rng), b) * (c.domainEnd() - c.domainStart());
}

/// The rational Bézier point Σ w_i B_i P_i / Σ w_i B_i by De Casteljau (Def 2.4) on the
/// homogeneous points; the polynomial one when `weights` is empty.
RPoint bezierPoint(const RationalBezierSegment<Rational>& s, const Rational& t)
{
    if (s.weights.empty())
        return deCasteljauPoint(s.points, t);
    std::vector<RPoint> h, w;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        h.push_back(s.weights[i] * s.points[i]);
        w.emplace_back(s.weights[i], Rational(0));
    }
    const RPoint num = deCasteljauPoint(h, t);
    const Rational den = deCasteljauPoint(w, t).x;
    return RPoint(Rational(num.x / den), Rational(num.y / den));
}

} // namespace

class TestBSplineKnots : public QObject {
    Q_OBJECT
private slots:
    // NURBS-Python issue #135: insert 0.5 into the quadratic Bézier (0,0), (1,1), (2,0) and
    // remove it again: the original points come back, exactly. The inserted points are the
    // halves (0,0), (1/2,1/2), (3/2,1/2), (2,0) (Boehm with α = 1/2, by hand).
    void geomdl135()
    {
        BSplineCurve<Rational> c;
        c.degree = 2;
        c.points = pts({{0, 0}, {1, 1}, {2, 0}});
        c.knots = ints({0, 0, 0, 1, 1, 1});
        const auto inserted = insertKnot(c, frac(1, 2));
        QVERIFY(checkBSpline(inserted).ok());
        const std::vector<RPoint> expected = {RPoint(0, 0), RPoint(frac(1, 2), frac(1, 2)), RPoint(frac(3, 2), frac(1, 2)),
                                              RPoint(2, 0)};
        QVERIFY(inserted.points == expected);
        QVERIFY(inserted.knots == (std::vector<Rational>{0, 0, 0, frac(1, 2), 1, 1, 1}));
        const auto removed = removeKnot(inserted, frac(1, 2));
        QCOMPARE(removed.removed, 1);
        QCOMPARE(removed.maxError, 0.0);
        QVERIFY(sameCurve(removed.curve, c));
    }

    // NURBS-Python issue #158: degree 2, points (0,0), (1,1), (2,1), (3,0), the floating knots
    // 0, 1, …, 6; inserting 4 (the domain's end) must give (0,0), (1,1), (2,1), (5/2,1/2),
    // (3,0) — as the reporter computed, and Boehm's rule on the span [4, 5) gives
    // Q_3 = (P_2 + P_3)/2. The domain's span [3, 4) would repeat P_2 (the library's bug).
    void geomdl158()
    {
        BSplineCurve<Rational> c;
        c.degree = 2;
        c.points = pts({{0, 0}, {1, 1}, {2, 1}, {3, 0}});
        c.knots = ints({0, 1, 2, 3, 4, 5, 6});
        QVERIFY(checkKnotInsertion(c, Rational(4), 1).ok());
        const auto q = insertKnot(c, Rational(4));
        const std::vector<RPoint> expected = {RPoint(0, 0), RPoint(1, 1), RPoint(2, 1), RPoint(frac(5, 2), frac(1, 2)),
                                              RPoint(3, 0)};
        QVERIFY(q.points == expected);
        QVERIFY(q.knots == ints({0, 1, 2, 3, 4, 4, 5, 6}));
        QVERIFY(sameShape(c, q));
    }

    // Insertion keeps the curve, exactly, on random curves (degrees 1–5, clamped and floating,
    // polynomial and rational, interior knots repeated up to p times), at new and existing
    // knots, at the domain's ends too; removing what was inserted gives the curve back,
    // control point for control point.
    void insertThenRemove()
    {
        std::mt19937 rng(1980);
        int cases = 0;
        for (int p = 1; p <= 5; ++p)
            for (int m = 1; m <= p; ++m)
                for (bool clamped : {true, false})
                    for (bool rational : {false, true})
                        for (int rep = 0; rep < 4; ++rep) {
                            const auto c = randomBSpline(rng, {p, m, 3, clamped, rational});
                            // rep 0: a new knot; rep 1: an existing interior knot if any; rep 2 and 3:
                            // the domain's start and end (floating ends only: clamped ends are full).
                            Rational u = randomInside(rng, c);
                            if (rep == 1)
                                for (std::size_t i = static_cast<std::size_t>(p) + 1; i < c.points.size(); ++i)
                                    if (c.knots[i] < c.domainEnd() && knotMultiplicity(c.knots, c.knots[i]) < p)
                                        u = c.knots[i];
                            if (rep == 2)
                                u = c.domainStart();
                            if (rep == 3)
                                u = c.domainEnd();
                            const int s = knotMultiplicity(c.knots, u);
                            if (s >= p)
                                continue;
                            const int times = 1 + static_cast<int>(rng() % static_cast<unsigned>(p - s));
                            QVERIFY(checkKnotInsertion(c, u, times).ok());
                            const auto q = insertKnot(c, u, times);
                            QVERIFY(checkBSpline(q).ok());
                            QCOMPARE(q.pointCount(), c.pointCount() + times);
                            QCOMPARE(knotMultiplicity(q.knots, u), s + times);
                            QVERIFY(sameShape(c, q));
                            if (rep >= 2) {
                                // Not strictly inside the domain: removal refuses.
                                QCOMPARE(removeKnot(q, u, times).removed, 0);
                                continue;
                            }
                            const auto back = removeKnot(q, u, times);
                            QCOMPARE(back.removed, times);
                            QVERIFY(sameCurve(back.curve, c));
                            ++cases;
                        }
        QVERIFY(cases > 100);
    }

    // A knot the curve needs is not removed: the corner of a polyline, and every interior knot
    // of random curves (random rational points make no knot removable); the curve is returned
    // unchanged with removed == 0.
    void neededKnotStays()
    {
        BSplineCurve<Rational> corner;
        corner.degree = 1;
        corner.points = pts({{0, 0}, {1, 1}, {2, 0}});
        corner.knots = {0, 0, frac(1, 2), 1, 1};
        const auto r = removeKnot(corner, frac(1, 2));
        QCOMPARE(r.removed, 0);
        QVERIFY(sameCurve(r.curve, corner));
        // A knot of a straight polyline is removable: (0,0), (1,1), (2,2) with the knot at 1/2.
        auto straight = corner;
        straight.points = pts({{0, 0}, {1, 1}, {2, 2}});
        QCOMPARE(removeKnot(straight, frac(1, 2)).removed, 1);

        std::mt19937 rng(1992);
        for (int p = 1; p <= 5; ++p)
            for (bool rational : {false, true}) {
                const auto c = randomBSpline(rng, {p, p, 3, true, rational});
                for (std::size_t i = static_cast<std::size_t>(p) + 1; i < c.points.size(); ++i) {
                    const auto res = removeKnot(c, c.knots[i], p);
                    QCOMPARE(res.removed, 0);
                    QVERIFY(sameCurve(res.curve, c));
                }
            }
    }

    // Doubles: a knot removable but for a perturbation of 1e-9 is removed under a tolerance of
    // 1e-6 (maxError reports the distance, between 0 and 1e-6) and kept under 1e-12.
    void toleranceForDoubles()
    {
        BSplineCurve<double> c;
        c.degree = 3;
        c.points = {Point(0, 0), Point(1, 2), Point(3, 3), Point(4, 0)};
        c.knots = {0, 0, 0, 0, 1, 1, 1, 1};
        BSplineCurve<double> q = insertKnot(c, 0.5);
        q.points[2].y += 1e-9;
        const auto loose = removeKnot(q, 0.5, 1, 1e-6);
        QCOMPARE(loose.removed, 1);
        QVERIFY(loose.maxError > 0 && loose.maxError < 1e-6);
        for (std::size_t i = 0; i < c.points.size(); ++i) {
            QVERIFY(std::abs(loose.curve.points[i].x - c.points[i].x) < 1e-8);
            QVERIFY(std::abs(loose.curve.points[i].y - c.points[i].y) < 1e-8);
        }
        const auto tight = removeKnot(q, 0.5, 1, 1e-12);
        QCOMPARE(tight.removed, 0);
        QCOMPARE(tight.curve.pointCount(), q.pointCount());
    }

    // What insertion refuses.
    void insertionRefusals()
    {
        BSplineCurve<Rational> c;
        c.degree = 2;
        c.points = pts({{0, 0}, {1, 1}, {2, 0}, {3, 1}});
        c.knots = {0, 0, 0, frac(1, 2), 1, 1, 1};
        QVERIFY(checkKnotInsertion(c, frac(1, 2), 1).ok());
        QVERIFY(checkKnotInsertion(c, frac(1, 3), 2).ok());
        QCOMPARE(checkKnotInsertion(c, frac(1, 2), 2).error().message,
                 std::string("the knot 1/2 has multiplicity 1; inserting it 2 more times would exceed the degree 2"));
        QCOMPARE(checkKnotInsertion(c, Rational(2), 1).error().message, std::string("the knot 2 is outside the domain [0, 1]"));
        QCOMPARE(checkKnotInsertion(c, Rational(0), 1).error().message,
                 std::string("the knot 0 has multiplicity 3; inserting it 1 more times would exceed the degree 2"));
        QCOMPARE(checkKnotInsertion(c, frac(1, 4), 0).error().message,
                 std::string("a knot is inserted at least once, not 0 times"));
        // The GUI's sentences (message_id.h) and their values.
        const auto outside = checkKnotInsertion(c, frac(3, 2), 1).error();
        QCOMPARE(outside.id, MessageId::KnotOutsideDomain);
        QCOMPARE(outside.args[0].text, std::string("3/2"));
        QCOMPARE(outside.args[2].number, std::optional<double>(1));
        QCOMPARE(checkKnotInsertion(c, frac(1, 2), 2).error().id, MessageId::KnotInsertionMultiplicity);
        QCOMPARE(checkKnotInsertion(c, frac(1, 2), 0).error().id, MessageId::KnotInsertionTimes);
    }

    // Bézier extraction: one piece per non-empty span, covering the domain in order; each
    // piece's De Casteljau (rational: on the homogeneous points) equals the B-spline on its
    // interval exactly, at the ends and inside.
    void extraction()
    {
        std::mt19937 rng(1997);
        for (int p = 1; p <= 5; ++p)
            for (int m = 1; m <= p; ++m)
                for (bool clamped : {true, false})
                    for (bool rational : {false, true}) {
                        const auto c = randomBSpline(rng, {p, m, 3, clamped, rational});
                        const auto segments = toBezierSegments(c);
                        int spans = 0;
                        for (int k = p; k < c.pointCount(); ++k)
                            spans += c.knots[static_cast<std::size_t>(k)] < c.knots[static_cast<std::size_t>(k + 1)];
                        QCOMPARE(static_cast<int>(segments.size()), spans);
                        QCOMPARE(segments.front().start, c.domainStart());
                        QCOMPARE(segments.back().end, c.domainEnd());
                        for (std::size_t j = 0; j < segments.size(); ++j) {
                            const auto& s = segments[j];
                            QCOMPARE(static_cast<int>(s.points.size()), p + 1);
                            QCOMPARE(s.weights.size(), rational ? s.points.size() : std::size_t(0));
                            if (j > 0)
                                QCOMPARE(s.start, segments[j - 1].end);
                            for (const Rational& t : {Rational(0), frac(1, 3), frac(1, 2), frac(4, 5), Rational(1)}) {
                                const Rational u = s.start + t * (s.end - s.start);
                                QVERIFY(bezierPoint(s, t) == bsplinePoint(c, u));
                            }
                        }
                    }
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestBSplineKnots)
#include "test_bspline_knots.moc"
