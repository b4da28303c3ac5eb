// Kochanek–Bartels (TCB) splines as Hermite segments (kochanek_bartels.h, issue 37). Expected
// values are computed independently of the code under test:
//  - T alone against the Catmull-Rom curve of τ = (1 − T)/2, computed by Lemma 2.3's matrix
//    M(τ) (catmullRomSegments), exactly in Rational, every mode;
//  - per-knot T, C, B against the 1984 formulas written out coordinate by coordinate below,
//    on seeded random rational points and parameters;
//  - the closed (0,0),(1,1),(2,0) case with C = 1/2 worked by hand: Δ₋ = (1,1), Δ₊ = (1,−1),
//    in = ½[½(1,1) + 3/2(1,−1)] = (1,−1/2), out = ½[3/2(1,1) + ½(1,−1)] = (1,1/2);
//  - the continuity of each knot read by knot_continuity.h, and the jump of the first
//    derivative, in − out = (1−T)C[(1−B)Δ₊ − (1+B)Δ₋], derived by hand from the formulas.
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/kochanek_bartels.h"
#include "core/curves/splines/knot_continuity.h"
#include "core/exact/rational.h"
#include "tests/rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <random>

using namespace granota;

namespace granota {
static char* toString(const Vec2<Rational>& p)
{
    return qstrdup(("(" + granota::toString(p.x) + ", " + granota::toString(p.y) + ")").c_str());
}
} // namespace granota

Q_DECLARE_METATYPE(granota::CatmullRomMode)

namespace {

const CatmullRomMode kModes[] = {CatmullRomMode::Open, CatmullRomMode::Cyclic, CatmullRomMode::Closed};

TcbKnot<Rational> tcb(const Rational& t, const Rational& c, const Rational& b) { return {t, c, b}; }

/// A rational in [−1, 1] with a small denominator.
Rational unitRational(std::mt19937& rng)
{
    std::uniform_int_distribution<int> den(1, 6);
    const int d = den(rng);
    std::uniform_int_distribution<int> num(-d, d);
    return frac(num(rng), d);
}

/// The neighbour indices of point i for Def 2.10's mode: open repeats the end points.
std::size_t prevIndex(std::size_t i, std::size_t count, CatmullRomMode mode)
{
    return i > 0 ? i - 1 : mode == CatmullRomMode::Open ? 0 : count - 1;
}
std::size_t nextIndex(std::size_t i, std::size_t count, CatmullRomMode mode)
{
    return i + 1 < count ? i + 1 : mode == CatmullRomMode::Open ? count - 1 : 0;
}

} // namespace

class TestKochanekBartels : public QObject {
    Q_OBJECT
private slots:
    // T alone is Catmull-Rom with τ = (1 − T)/2, exactly, in every mode.
    void tensionAloneIsCatmullRom_data()
    {
        QTest::addColumn<CatmullRomMode>("mode");
        QTest::addColumn<QString>("tension");
        for (CatmullRomMode mode : kModes)
            for (const char* t : {"0", "1/2", "-1/3", "1", "3/2", "-2", "7/11"})
                QTest::addRow("%s T=%s", toString(mode).c_str(), t) << mode << QString(t);
    }
    void tensionAloneIsCatmullRom()
    {
        QFETCH(CatmullRomMode, mode);
        QFETCH(QString, tension);
        const Rational t = *parseRational(tension.toStdString());
        const Rational tau = (1 - t) / 2;
        std::mt19937 rng(370 + static_cast<unsigned>(mode));
        for (int n : {1, 2, 3, 6}) {
            if (mode != CatmullRomMode::Open && n < 2)
                continue;
            const auto q = testing::randomRational(rng, n);
            const auto kb = kochanekBartels(q, {tcb(t, 0, 0)}, mode);
            QVERIFY(kb.ok());
            const auto lemma23 = catmullRomSegments(q, tau, mode);
            QVERIFY(lemma23.ok());
            QCOMPARE(kb->segments.size(), lemma23->size());
            const auto mine = hermitePolynomials(kb->segments);
            for (std::size_t i = 0; i < mine.size(); ++i) {
                QVERIFY(mine[i].x == (*lemma23)[i].x);
                QVERIFY(mine[i].y == (*lemma23)[i].y);
            }
            // With C = 0 both tangents at a point are the same.
            for (const auto& k : kb->tangents)
                QCOMPARE(k.in, k.out);
        }
    }

    // One T, C, B per point on seeded random rational data, against the formulas of the
    // 1984 paper written out here coordinate by coordinate.
    void perKnotAgainstFormulas_data()
    {
        QTest::addColumn<CatmullRomMode>("mode");
        for (CatmullRomMode mode : kModes)
            QTest::addRow("%s", toString(mode).c_str()) << mode;
    }
    void perKnotAgainstFormulas()
    {
        QFETCH(CatmullRomMode, mode);
        std::mt19937 rng(1984);
        for (int trial = 0; trial < 20; ++trial) {
            const int n = 2 + trial % 6;
            const auto q = testing::randomRational(rng, n);
            std::vector<TcbKnot<Rational>> knots;
            for (int i = 0; i <= n; ++i)
                knots.push_back(tcb(2 * unitRational(rng), unitRational(rng), unitRational(rng)));
            const auto kb = kochanekBartels(q, knots, mode);
            QVERIFY(kb.ok());
            const std::size_t count = q.size();
            QCOMPARE(kb->tangents.size(), count);
            std::vector<RPoint> in(count), out(count);
            for (std::size_t i = 0; i < count; ++i) {
                const RPoint& a = q[prevIndex(i, count, mode)];
                const RPoint& p = q[i];
                const RPoint& b = q[nextIndex(i, count, mode)];
                const Rational& T = knots[i].tension;
                const Rational& C = knots[i].continuity;
                const Rational& B = knots[i].bias;
                const Rational dmx = p.x - a.x, dmy = p.y - a.y, dpx = b.x - p.x, dpy = b.y - p.y;
                const Rational w = (1 - T) / 2;
                in[i] = RPoint(Rational(w * ((1 + B) * (1 - C) * dmx + (1 - B) * (1 + C) * dpx)),
                               Rational(w * ((1 + B) * (1 - C) * dmy + (1 - B) * (1 + C) * dpy)));
                out[i] = RPoint(Rational(w * ((1 + B) * (1 + C) * dmx + (1 - B) * (1 - C) * dpx)),
                                Rational(w * ((1 + B) * (1 + C) * dmy + (1 - B) * (1 - C) * dpy)));
                QCOMPARE(kb->tangents[i].in, in[i]);
                QCOMPARE(kb->tangents[i].out, out[i]);
            }
            const std::size_t segments = mode == CatmullRomMode::Closed ? count : count - 1;
            QCOMPARE(kb->segments.size(), segments);
            for (std::size_t i = 0; i < segments; ++i) {
                const std::size_t j = (i + 1) % count;
                QCOMPARE(kb->segments[i].p0, q[i]);
                QCOMPARE(kb->segments[i].p1, q[j]);
                QCOMPARE(kb->segments[i].m0, out[i]);
                QCOMPARE(kb->segments[i].m1, in[j]);
            }
        }
    }

    // The hand-worked case: closed (0,0),(1,1),(2,0), C = 1/2; the knot (1,1) is not G¹.
    void closedTriangleWithContinuity()
    {
        const auto q = testing::pts({{0, 0}, {1, 1}, {2, 0}});
        const auto kb = kochanekBartels(q, {tcb(0, frac(1, 2), 0)}, CatmullRomMode::Closed);
        QVERIFY(kb.ok());
        QCOMPARE(kb->tangents[1].in, RPoint(Rational(1), frac(-1, 2)));
        QCOMPARE(kb->tangents[1].out, RPoint(Rational(1), frac(1, 2)));
        const auto knots = knotContinuity(hermitePolynomials(kb->segments), {}, true);
        QCOMPARE(knots.size(), std::size_t(3));
        // Knot 0 joins segment 0 (q_0 → q_1) to segment 1 at q_1.
        QCOMPARE(knots[0].fromSegment, 0);
        QCOMPARE(knots[0].left[1], RPoint(Rational(1), frac(-1, 2)));
        QCOMPARE(knots[0].right[1], RPoint(Rational(1), frac(1, 2)));
        QVERIFY(knots[0].equal[0]);
        QVERIFY(!knots[0].equal[1]);
        QVERIFY(!knots[0].g1);
        QCOMPARE(knots[0].geometricOrder(), 0);
    }

    // C ≠ 0 breaks C¹ (Prop 2.3 no longer holds) with the jump in − out worked by hand;
    // C = 0 keeps every knot C¹.
    void continuityBreaksC1()
    {
        std::mt19937 rng(23);
        for (int trial = 0; trial < 10; ++trial) {
            const auto q = testing::randomRational(rng, 5);
            const Rational T = unitRational(rng), B = unitRational(rng) / 2;
            const auto smooth = kochanekBartels(q, {tcb(T, 0, B)}, CatmullRomMode::Closed);
            QVERIFY(smooth.ok());
            for (const auto& k : knotContinuity(hermitePolynomials(smooth->segments), {}, true))
                QVERIFY(k.parametricOrder() >= 1);
            const Rational C = frac(1, 4 + trial);
            const auto kinked = kochanekBartels(q, {tcb(T, C, B)}, CatmullRomMode::Closed);
            QVERIFY(kinked.ok());
            const auto knots = knotContinuity(hermitePolynomials(kinked->segments), {}, true);
            QCOMPARE(knots.size(), q.size());
            for (const auto& k : knots) {
                const std::size_t i = static_cast<std::size_t>(k.toSegment); // the knot is q_i
                const RPoint dm = q[i] - q[(i + q.size() - 1) % q.size()], dp = q[(i + 1) % q.size()] - q[i];
                const Rational f = (1 - T) * C;
                const RPoint expected(Rational(f * ((1 - B) * dp.x - (1 + B) * dm.x)),
                                      Rational(f * ((1 - B) * dp.y - (1 + B) * dm.y)));
                QCOMPARE(k.left[1] - k.right[1], expected); // in − out
                QCOMPARE(k.equal[1], expected == RPoint(Rational(0), Rational(0)));
            }
        }
    }

    // C = −1: each segment takes its own chord at both ends; with T = B = 0 both tangents
    // are the chord itself and the segment is that straight line (degree ≤ 1).
    void continuityMinusOneGivesChords()
    {
        std::mt19937 rng(5);
        const auto q = testing::randomRational(rng, 6);
        const auto kb = kochanekBartels(q, {tcb(0, -1, 0)}, CatmullRomMode::Closed);
        QVERIFY(kb.ok());
        for (const auto& g : kb->segments) {
            QCOMPARE(g.m0, g.p1 - g.p0);
            QCOMPARE(g.m1, g.p1 - g.p0);
            const auto p = hermitePolynomial(g);
            QVERIFY(p.x.degree() <= 1 && p.y.degree() <= 1);
        }
    }

    // Non-uniform spacing (α = 1, chordal) on (0,0),(3,4),(3,5): h_0 = 5, h_1 = 1, the uniform
    // tangent at (3,4) is ½((3,4) + (0,1)) = (3/2, 5/2); the paper's adjustment gives
    // in = (3/2, 5/2)·2·5/6 = (5/2, 25/6) and out = (3/2, 5/2)·2/6 = (1/2, 5/6), and the
    // derivatives in the global parameter, in/h_0 and out/h_1, agree (C¹).
    void nonUniformSpacing()
    {
        const std::vector<Point> q{{0, 0}, {3, 4}, {3, 5}};
        const auto kb = kochanekBartels(q, {TcbKnot<double>{}}, CatmullRomMode::Open, 1.0);
        QVERIFY(kb.ok());
        QVERIFY(std::abs(kb->tangents[1].in.x - 2.5) < 1e-14 && std::abs(kb->tangents[1].in.y - 25.0 / 6) < 1e-14);
        QVERIFY(std::abs(kb->tangents[1].out.x - 0.5) < 1e-14 && std::abs(kb->tangents[1].out.y - 5.0 / 6) < 1e-14);
        // Open ends keep the uniform tangents ½(q_1 − q_0) and ½(q_2 − q_1).
        QCOMPARE(kb->segments[0].m0, Point(1.5, 2.0));
        QCOMPARE(kb->segments[1].m1, Point(0.0, 0.5));

        // Any α, C = 0: C¹ in the global parameter of catmullRomIntervals() at every knot.
        std::mt19937 rng(12);
        for (double alpha : {0.25, 0.5, 1.0}) {
            const auto r = testing::randomRational(rng, 7);
            const auto d = toDouble(r);
            const auto curve = kochanekBartels(d, {TcbKnot<double>{0.3, 0.0, -0.4}}, CatmullRomMode::Closed, alpha);
            QVERIFY(curve.ok());
            const auto h = catmullRomIntervals(d, CatmullRomMode::Closed, alpha);
            const auto knots = knotContinuity(hermitePolynomials(curve->segments), h, true, 1e-12);
            QCOMPARE(knots.size(), d.size());
            for (const auto& k : knots)
                QVERIFY(k.equal[1]);
        }
    }

    // α = 0 in doubles is the exact curve rounded.
    void doublesFollowTheExactCurve()
    {
        std::mt19937 rng(99);
        const auto r = testing::randomRational(rng, 6);
        const std::vector<TcbKnot<Rational>> exact{tcb(frac(1, 3), frac(-1, 2), frac(1, 5))};
        const std::vector<TcbKnot<double>> approx{TcbKnot<double>{1.0 / 3, -0.5, 0.2}};
        const auto a = kochanekBartels(r, exact, CatmullRomMode::Cyclic);
        const auto b = kochanekBartels(toDouble(r), approx, CatmullRomMode::Cyclic);
        QVERIFY(a.ok() && b.ok());
        for (std::size_t i = 0; i < a->tangents.size(); ++i)
            for (const auto& [e, v] :
                 {std::pair{a->tangents[i].in, b->tangents[i].in}, std::pair{a->tangents[i].out, b->tangents[i].out}}) {
                QVERIFY(std::abs(e.x.get_d() - v.x) <= 1e-12 * (1 + std::abs(v.x)));
                QVERIFY(std::abs(e.y.get_d() - v.y) <= 1e-12 * (1 + std::abs(v.y)));
            }
    }

    void refusals()
    {
        const auto q = testing::pts({{0, 0}, {1, 1}, {2, 0}, {3, 2}});
        QCOMPARE(kochanekBartels(q, {tcb(0, 2, 0)}, CatmullRomMode::Open).error().code, ErrorCode::OutOfRange);
        QCOMPARE(kochanekBartels(q, {tcb(0, 0, frac(-3, 2))}, CatmullRomMode::Open).error().code, ErrorCode::OutOfRange);
        QCOMPARE(kochanekBartels(q, {tcb(0, 0, 0), tcb(0, 0, 0)}, CatmullRomMode::Open).error().code, ErrorCode::InvalidInput);
        QCOMPARE(kochanekBartels(q, {}, CatmullRomMode::Open).error().code, ErrorCode::InvalidInput);
        QCOMPARE(kochanekBartels(testing::pts({{0, 0}, {1, 1}}), {tcb(0, 0, 0)}, CatmullRomMode::Cyclic).error().code,
                 ErrorCode::TooFewPoints);
        QCOMPARE(kochanekBartels(testing::pts({{0, 0}}), {tcb(0, 0, 0)}, CatmullRomMode::Open).error().code,
                 ErrorCode::TooFewPoints);
        QCOMPARE(kochanekBartels(q, {tcb(0, 0, 0)}, CatmullRomMode::Open, 0.5).error().code, ErrorCode::NotRational);
        // T beyond [−1, 1] is still a Catmull-Rom tension (τ = (1 − T)/2): accepted.
        QVERIFY(kochanekBartels(q, {tcb(5, 1, -1)}, CatmullRomMode::Open).ok());
        const auto d = toDouble(q);
        QCOMPARE(kochanekBartels(d, {TcbKnot<double>{std::nan(""), 0, 0}}, CatmullRomMode::Open).error().code,
                 ErrorCode::InvalidInput);
        QCOMPARE(kochanekBartels(d, {TcbKnot<double>{}}, CatmullRomMode::Open, 2.0).error().code, ErrorCode::OutOfRange);
        QCOMPARE(kochanekBartels(std::vector<Point>{{0, 0}, {1e308, 0}, {-1e308, 0}}, {TcbKnot<double>{-3, 0, 0}},
                                 CatmullRomMode::Open)
                     .error()
                     .code,
                 ErrorCode::OutOfRange);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestKochanekBartels)
#include "test_kochanek_bartels.moc"
