// Catmull-Rom curves (§2.2): the thesis's examples exactly as printed (Ex 2.11, Ex 2.12,
// Ex 2.13), the properties it proves (partition of unity, interpolation, Prop 2.3), and the
// extensions (centripetal/chordal spacing, extreme input, Processing's curveTightness).
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/continuity_check.h"
#include "core/exact/polynomial_text.h"
#include "core/exact/rational.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <limits>

using namespace granota;

// Readable QCOMPARE failures for exact values (found by argument-dependent lookup).
static char* toString(const Rational& v) { return qstrdup(granota::toString(v).c_str()); }
namespace granota {
static char* toString(const Polynomial<Rational>& p) { return qstrdup(toText(p).c_str()); }
static char* toString(const Vec2<Rational>& p)
{
    return qstrdup(("(" + granota::toString(p.x) + ", " + granota::toString(p.y) + ")").c_str());
}
static char* toString(const Vec2<Polynomial<Rational>>& p) { return qstrdup(toText(p, "s").c_str()); }
} // namespace granota

Q_DECLARE_METATYPE(granota::CatmullRomMode)

namespace {

using RP = Polynomial<Rational>;
using RSeg = Vec2<RP>;
using DSeg = Vec2<Polynomial<double>>;

Rational q(long n, long d = 1)
{
    Rational v(n, d);
    v.canonicalize();
    return v;
}
RPoint rp(long x, long y) { return RPoint(q(x), q(y)); }

/// "0 1 0 0; -1/2 0 1/2 0" → the numbers in reading order.
std::vector<Rational> values(const QString& text)
{
    std::vector<Rational> out;
    for (const QString& part : QString(text).replace(';', ' ').split(' ', Qt::SkipEmptyParts)) {
        const auto v = parseRational(part.toStdString());
        if (!v)
            qFatal("bad number in test data: %s", qPrintable(part));
        out.push_back(*v);
    }
    return out;
}
/// Ascending coefficients: "3 1/2 -5 7/2" → 3 + 1/2 t − 5t² + 7/2 t³.
RP poly(const QString& text) { return RP(values(text)); }
RSeg seg(const QString& x, const QString& y) { return RSeg(poly(x), poly(y)); }

template <class S> Vec2<S> at(const Vec2<Polynomial<S>>& p, const S& s) { return Vec2<S>(p.x(s), p.y(s)); }
template <class S> Vec2<Polynomial<S>> derivative(const Vec2<Polynomial<S>>& p)
{
    return Vec2<Polynomial<S>>(p.x.derivative(), p.y.derivative());
}

// Ex 2.13: q_0..q_4.
std::vector<RPoint> ex213Points() { return {rp(3, 5), rp(2, 2), rp(6, 0), rp(8, 3), rp(7, 5)}; }
// An irregular hexagon-ish set with negative coordinates and uneven spacing.
std::vector<RPoint> irregular() { return {rp(0, 0), rp(4, 1), rp(5, 5), rp(1, 7), rp(-3, 4), rp(-2, -1)}; }

std::vector<Point> uneven() { return {{0, 0}, {10, 0}, {11, 1}, {11, 11}, {0, 12}, {-1, 3}, {-0.5, 2.5}}; }

bool allFinite(const std::vector<DSeg>& segments)
{
    for (const auto& s : segments)
        for (const auto* p : {&s.x, &s.y})
            for (double c : p->coefficients())
                if (!std::isfinite(c))
                    return false;
    return true;
}

bool near(const Point& a, const Point& b, double scale)
{
    return std::fabs(a.x - b.x) <= 1e-12 * scale && std::fabs(a.y - b.y) <= 1e-12 * scale;
}

/// Segment i runs from q_i to q_{(i+1) mod (n+1)} in every mode.
template <class S>
void checkInterpolates(const std::vector<Vec2<Polynomial<S>>>& segments, const std::vector<Vec2<S>>& points, double scale = 1)
{
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const Vec2<S>& a = points[i];
        const Vec2<S>& b = points[(i + 1) % points.size()];
        if constexpr (std::is_same_v<S, Rational>) {
            QCOMPARE(at(segments[i], Rational(0)), a);
            QCOMPARE(at(segments[i], Rational(1)), b);
        } else {
            QVERIFY2(near(at(segments[i], 0.0), a, scale), qPrintable(QString("segment %1 start").arg(i)));
            QVERIFY2(near(at(segments[i], 1.0), b, scale), qPrintable(QString("segment %1 end").arg(i)));
        }
    }
}

} // namespace

class TestCatmullRom : public QObject {
    Q_OBJECT
private slots:
    // Lemma 2.3's matrix and Ex 2.11 as printed: M(τ), the coefficient matrix M(τ)·P and the
    // segment p(t) for p_0 = (1,1), p_1 = (3,4), p_2 = (2,−1), p_3 = (5,1).
    void ex211_data()
    {
        QTest::addColumn<QString>("tau");
        QTest::addColumn<QString>("matrix");       // rows of M(τ)
        QTest::addColumn<QString>("coefficients"); // rows [c_r.x c_r.y]
        QTest::addColumn<QString>("x");            // ascending powers of t
        QTest::addColumn<QString>("y");
        QTest::newRow("tau 0") << "0"
                               << "0 1 0 0; 0 0 0 0; 0 -3 3 0; 0 2 -2 0"
                               << "3 4; 0 0; -3 -15; 2 10"
                               << "3 0 -3 2"
                               << "4 0 -15 10";
        QTest::newRow("tau 1/2") << "1/2"
                                 << "0 1 0 0; -1/2 0 1/2 0; 1 -5/2 2 -1/2; -1/2 3/2 -3/2 1/2"
                                 << "3 4; 1/2 -1; -5 -23/2; 7/2 15/2"
                                 << "3 1/2 -5 7/2"
                                 << "4 -1 -23/2 15/2";
        QTest::newRow("tau 2") << "2"
                               << "0 1 0 0; -2 0 2 0; 4 -1 -1 -2; -2 0 0 2"
                               << "3 4; 2 -4; -11 -1; 8 0"
                               << "3 2 -11 8"
                               << "4 -4 -1";
    }
    void ex211()
    {
        QFETCH(QString, tau);
        QFETCH(QString, matrix);
        QFETCH(QString, coefficients);
        QFETCH(QString, x);
        QFETCH(QString, y);
        const Rational t = values(tau).at(0);
        const auto m = catmullRomMatrix(t);
        const auto expectedM = values(matrix);
        for (std::size_t r = 0; r < 4; ++r)
            for (std::size_t c = 0; c < 4; ++c)
                QCOMPARE(m[r][c], expectedM[4 * r + c]);

        const RPoint p0 = rp(1, 1), p1 = rp(3, 4), p2 = rp(2, -1), p3 = rp(5, 1);
        const auto c = catmullRomCoefficients(p0, p1, p2, p3, t);
        const auto expectedC = values(coefficients);
        for (std::size_t r = 0; r < 4; ++r)
            QCOMPARE(c[r], RPoint(expectedC[2 * r], expectedC[2 * r + 1]));
        QCOMPARE(catmullRomSegment(p0, p1, p2, p3, t), seg(x, y));
    }

    void matrixSymbolic()
    {
        // Lemma 2.3 with τ as a symbol: M(τ) over Polynomial<Rational> in τ reads
        // [0 1 0 0; −τ 0 τ 0; 2τ τ−3 3−2τ −τ; −τ 2−τ τ−2 τ].
        const RP tau = RP::identity();
        const auto m = catmullRomMatrix(tau);
        const char* expected[4][4] = {
            {"0", "1", "0", "0"}, {"0 -1", "0", "0 1", "0"}, {"0 2", "-3 1", "3 -2", "0 -1"}, {"0 -1", "2 -1", "-2 1", "0 1"}};
        for (std::size_t r = 0; r < 4; ++r)
            for (std::size_t c = 0; c < 4; ++c)
                QCOMPARE(m[r][c], poly(expected[r][c]));
    }

    // Ex 2.12: the blending functions (Cor 2.1) as printed, ascending powers of t.
    void ex212_data()
    {
        QTest::addColumn<QString>("tau");
        QTest::addColumn<QString>("w0");
        QTest::addColumn<QString>("w1");
        QTest::addColumn<QString>("w2");
        QTest::addColumn<QString>("w3");
        QTest::newRow("tau -2") << "-2"
                                << "0 2 -4 2"
                                << "1 0 -5 4"
                                << "0 -2 7 -4"
                                << "0 0 2 -2";
        QTest::newRow("tau 0") << "0"
                               << ""
                               << "1 0 -3 2"
                               << "0 0 3 -2"
                               << "";
        QTest::newRow("tau 1/2") << "1/2"
                                 << "0 -1/2 1 -1/2"
                                 << "1 0 -5/2 3/2"
                                 << "0 1/2 2 -3/2"
                                 << "0 0 -1/2 1/2";
        QTest::newRow("tau 2") << "2"
                               << "0 -2 4 -2"
                               << "1 0 -1"
                               << "0 2 -1"
                               << "0 0 -2 2";
    }
    void ex212()
    {
        QFETCH(QString, tau);
        QFETCH(QString, w0);
        QFETCH(QString, w1);
        QFETCH(QString, w2);
        QFETCH(QString, w3);
        const auto w = blendingFunctions(values(tau).at(0));
        QCOMPARE(w[0], poly(w0));
        QCOMPARE(w[1], poly(w1));
        QCOMPARE(w[2], poly(w2));
        QCOMPARE(w[3], poly(w3));
    }

    void blendingIsTheSegment()
    {
        // Def 2.9: p(t) = Σ w_j(t) p_j — the blending functions rebuild Lemma 2.3's segment.
        const Rational tau = q(3, 7);
        const RPoint p[4] = {rp(1, 1), rp(3, 4), rp(2, -1), rp(5, 1)};
        const auto w = blendingFunctions(tau);
        RSeg sum{RP(), RP()};
        for (std::size_t j = 0; j < 4; ++j) {
            sum.x += w[j] * RP(p[j].x);
            sum.y += w[j] * RP(p[j].y);
        }
        QCOMPARE(sum, catmullRomSegment(p[0], p[1], p[2], p[3], tau));
    }

    void partitionOfUnity_data()
    {
        QTest::addColumn<QString>("tau");
        for (const char* t : {"-10", "-2", "0", "1/3", "1/2", "1", "2", "10"})
            QTest::newRow(t) << t;
    }
    void partitionOfUnity()
    {
        // Σ w_j(t, τ) = 1 for every t: a segment of four equal points is that point.
        QFETCH(QString, tau);
        const auto w = blendingFunctions(values(tau).at(0));
        QCOMPARE(w[0] + w[1] + w[2] + w[3], RP(1));
        // … and Def 2.8 at the ends: w_j(0) = δ_{j1}, w_j(1) = δ_{j2}.
        for (std::size_t j = 0; j < 4; ++j) {
            QCOMPARE(w[j](Rational(0)), Rational(j == 1 ? 1 : 0));
            QCOMPARE(w[j](Rational(1)), Rational(j == 2 ? 1 : 0));
        }
    }

    // Ex 2.13 with τ = 1/2: p_2 and p_3 (the same in both versions) and the ends.
    void ex213_data()
    {
        QTest::addColumn<CatmullRomMode>("mode");
        QTest::addColumn<QStringList>("segments"); // x, y of p_1..p_n, ascending powers of s
        const QStringList p2{"2 3/2 6 -7/2", "2 -5/2 -3/2 2"};
        const QStringList p3{"6 3 -1/2 -1/2", "0 1/2 11/2 -3"};
        const QStringList p1c{"3 -5/2 1/2 1", "5 -3/2 -7/2 2"};
        const QStringList p4c{"8 1/2 -3/2", "3 5/2 0 -1/2"};
        const QStringList p1n{"3 -1/2 -7/2 3", "5 -3/2 -7/2 2"};
        const QStringList p4n{"8 1/2 -7/2 2", "3 5/2 0 -1/2"};
        // The closing segment q_4 → q_0 from (q_3, q_4, q_0, q_1), computed by hand:
        // c_1 = ½((3,5) − (8,3)), c_2 = (8,3) − 5/2(7,5) + 2(3,5) − ½(2,2), c_3 = −½(8,3) + 3/2(7,5) − 3/2(3,5) + ½(2,2).
        const QStringList p5{"7 -5/2 -9/2 3", "5 1 -1/2 -1/2"};
        QTest::newRow("cyclic") << CatmullRomMode::Cyclic << (p1c + p2 + p3 + p4c);
        QTest::newRow("open") << CatmullRomMode::Open << (p1n + p2 + p3 + p4n);
        QTest::newRow("closed") << CatmullRomMode::Closed << (p1c + p2 + p3 + p4c + p5);
    }
    void ex213()
    {
        QFETCH(CatmullRomMode, mode);
        QFETCH(QStringList, segments);
        const auto curve = catmullRomSegments(ex213Points(), q(1, 2), mode);
        QVERIFY(curve.ok());
        QCOMPARE(static_cast<int>(curve->size()), segments.size() / 2);
        for (std::size_t i = 0; i < curve->size(); ++i)
            QCOMPARE((*curve)[i], seg(segments[2 * int(i)], segments[2 * int(i) + 1]));
    }
    void ex213CoefficientMatrices()
    {
        // The middle matrices printed for p_2 and p_1^n.
        const auto pts = ex213Points();
        const auto c2 = catmullRomCoefficients(pts[0], pts[1], pts[2], pts[3], q(1, 2));
        const auto e2 = values("2 2; 3/2 -5/2; 6 -3/2; -7/2 2");
        const auto c1 = catmullRomCoefficients(pts[0], pts[0], pts[1], pts[2], q(1, 2));
        const auto e1 = values("3 5; -1/2 -3/2; -7/2 -7/2; 3 2");
        for (std::size_t r = 0; r < 4; ++r) {
            QCOMPARE(c2[r], RPoint(e2[2 * r], e2[2 * r + 1]));
            QCOMPARE(c1[r], RPoint(e1[2 * r], e1[2 * r + 1]));
        }
    }

    void quadruples()
    {
        using Q = std::vector<std::array<int, 4>>;
        QCOMPARE(*catmullRomQuadruples(5, CatmullRomMode::Open), (Q{{0, 0, 1, 2}, {0, 1, 2, 3}, {1, 2, 3, 4}, {2, 3, 4, 4}}));
        QCOMPARE(*catmullRomQuadruples(5, CatmullRomMode::Cyclic), (Q{{4, 0, 1, 2}, {0, 1, 2, 3}, {1, 2, 3, 4}, {2, 3, 4, 0}}));
        QCOMPARE(*catmullRomQuadruples(5, CatmullRomMode::Closed),
                 (Q{{4, 0, 1, 2}, {0, 1, 2, 3}, {1, 2, 3, 4}, {2, 3, 4, 0}, {3, 4, 0, 1}}));
        QCOMPARE(*catmullRomQuadruples(2, CatmullRomMode::Open), (Q{{0, 0, 1, 1}}));
        QCOMPARE(*catmullRomQuadruples(3, CatmullRomMode::Closed), (Q{{2, 0, 1, 2}, {0, 1, 2, 0}, {1, 2, 0, 1}}));
    }

    void twoPoints()
    {
        // One segment from (q_0, q_0, q_1, q_1): c_1 = τΔ, c_2 = 3(1−τ)Δ, c_3 = −2(1−τ)Δ.
        const std::vector<RPoint> pts{rp(0, 0), rp(2, 4)};
        const auto half = catmullRomSegments(pts, q(1, 2), CatmullRomMode::Open);
        QVERIFY(half.ok());
        QCOMPARE(half->size(), std::size_t(1));
        QCOMPARE(half->front(), seg("0 1 3 -2", "0 2 6 -4"));
        // τ = 1: the straight segment at constant speed.
        const auto one = catmullRomSegments(pts, q(1), CatmullRomMode::Open);
        QCOMPARE(one->front(), seg("0 2", "0 4"));
    }

    void properties_data()
    {
        QTest::addColumn<CatmullRomMode>("mode");
        QTest::addColumn<QString>("tau");
        QTest::addColumn<bool>("irregularPoints");
        for (auto mode : {CatmullRomMode::Open, CatmullRomMode::Cyclic, CatmullRomMode::Closed})
            for (const char* tau : {"-2", "0", "1/2", "1", "2", "7/3"})
                for (bool irregularPoints : {false, true})
                    QTest::addRow("%s tau=%s %s", toString(mode).c_str(), tau, irregularPoints ? "irregular" : "Ex 2.13")
                        << mode << QString(tau) << irregularPoints;
    }
    void properties()
    {
        QFETCH(CatmullRomMode, mode);
        QFETCH(QString, tau);
        QFETCH(bool, irregularPoints);
        const Rational t = values(tau).at(0);
        const auto pts = irregularPoints ? irregular() : ex213Points();
        const int count = static_cast<int>(pts.size());
        const int n = count - 1;
        const auto curve = catmullRomSegments(pts, t, mode);
        QVERIFY(curve.ok());
        QCOMPARE(static_cast<int>(curve->size()), mode == CatmullRomMode::Closed ? n + 1 : n);

        // Every segment interpolates its two points.
        checkInterpolates(*curve, pts);

        // Prop 2.3: C¹ at every knot, with the tangent τ(q_{m+1} − q_{m−1}).
        const bool closed = mode == CatmullRomMode::Closed;
        const auto joins = checkSegmentJoins(*curve, 1, closed);
        QVERIFY2(joins.ok(), joins.describe().c_str());
        QCOMPARE(joins.joins, closed ? n + 1 : n - 1);
        const auto point = [&](int m) { return pts[static_cast<std::size_t>(((m % count) + count) % count)]; };
        for (std::size_t i = 0; i < curve->size(); ++i) {
            const int m = static_cast<int>(i); // segment i runs q_m → q_{m+1}
            const RPoint startTangent = at(derivative((*curve)[i]), Rational(0));
            const RPoint endTangent = at(derivative((*curve)[i]), Rational(1));
            if (mode == CatmullRomMode::Open && m == 0)
                QCOMPARE(startTangent, t * (point(1) - point(0))); // Def 2.10 option 2
            else
                QCOMPARE(startTangent, t * (point(m + 1) - point(m - 1)));
            if (mode == CatmullRomMode::Open && m == n - 1)
                QCOMPARE(endTangent, t * (point(n) - point(n - 1)));
            else
                QCOMPARE(endTangent, t * (point(m + 2) - point(m)));
        }
        if (closed) {
            // The closed curve closes: it ends where it starts, and C¹ there too.
            QCOMPARE(at(curve->back(), Rational(1)), pts.front());
        } else if (mode == CatmullRomMode::Cyclic) {
            // "quasi cíclica": the cyclic curve stops at q_n, the loop is open.
            const auto loop = checkSegmentJoins(*curve, 1, true);
            QVERIFY(!loop.ok());
            QCOMPARE(loop.continuityOrder(), -1);
            QCOMPARE(loop.defects.front().fromSegment, n - 1);
            QCOMPARE(loop.defects.front().toSegment, 0);
        }
    }

    void onlyC1()
    {
        // §2.3: C¹ is all one can promise. Ex 2.13 (open): p_2″(1) = (−9, 9) but p_3″(0) = (−1, 11).
        const auto curve = catmullRomSegments(ex213Points(), q(1, 2), CatmullRomMode::Open);
        const auto report = checkSegmentJoins(*curve, 2, false);
        QCOMPARE(report.continuityOrder(), 1);
        bool found = false;
        for (const auto& d : report.defects) {
            QCOMPARE(d.order, 2);
            if (d.fromSegment == 1) {
                found = true;
                QCOMPARE(d.toSegment, 2);
                QCOMPARE(d.left, rp(-9, 9));
                QCOMPARE(d.right, rp(-1, 11));
            }
        }
        QVERIFY(found);
    }

    void joinCheckerFindsKink()
    {
        auto curve = *catmullRomSegments(ex213Points(), q(1, 2), CatmullRomMode::Open);
        curve[2].y += RP{q(0), q(1), q(-1)}; // p_3 gets s − s²: same ends, tangents change at both ends
        const auto report = checkSegmentJoins(curve, 1, false);
        QCOMPARE(report.continuityOrder(), 0);
        QCOMPARE(static_cast<int>(report.defects.size()), 2);
        QCOMPARE(report.defects[0].join, 1); // p_2 → p_3
        QCOMPARE(report.defects[0].order, 1);
        QCOMPARE(report.defects[0].jump(), rp(0, 1));
        QCOMPARE(report.defects[1].join, 2); // p_3 → p_4
        QCOMPARE(report.defects[1].jump(), rp(0, 1));
        QVERIFY(QString::fromStdString(report.describe()).contains("p' jumps at the join of p_2 and p_3"));
    }

    void uniformDoublesAreExact_data()
    {
        QTest::addColumn<CatmullRomMode>("mode");
        QTest::addColumn<double>("tau");
        for (auto mode : {CatmullRomMode::Open, CatmullRomMode::Cyclic, CatmullRomMode::Closed})
            for (double tau : {0.0, 0.5, 2.0, -1.0, 0.75})
                QTest::addRow("%s tau=%g", toString(mode).c_str(), tau) << mode << tau;
    }
    void uniformDoublesAreExact()
    {
        // α = 0 is the thesis's curve: with small integers and dyadic τ every double
        // operation is exact, so the double path must equal the exact one bit for bit.
        QFETCH(CatmullRomMode, mode);
        QFETCH(double, tau);
        for (const auto& pts : {ex213Points(), irregular()}) {
            const auto exact = catmullRomSegments(pts, exactRational(tau), mode);
            const auto fast = catmullRomSegments(toDouble(pts), tau, mode, 0.0);
            QVERIFY(exact.ok() && fast.ok());
            QCOMPARE(fast->size(), exact->size());
            for (std::size_t i = 0; i < exact->size(); ++i)
                for (int k = 0; k <= 3; ++k) {
                    QCOMPARE((*fast)[i].x.coefficient(k), (*exact)[i].x.coefficient(k).get_d());
                    QCOMPARE((*fast)[i].y.coefficient(k), (*exact)[i].y.coefficient(k).get_d());
                }
        }
    }

    void nonUniform_data()
    {
        QTest::addColumn<CatmullRomMode>("mode");
        QTest::addColumn<double>("alpha");
        QTest::addColumn<double>("tau");
        for (auto mode : {CatmullRomMode::Open, CatmullRomMode::Cyclic, CatmullRomMode::Closed})
            for (double alpha : {0.5, 1.0, 0.25})
                for (double tau : {0.5, 1.0, 2.0})
                    QTest::addRow("%s alpha=%g tau=%g", toString(mode).c_str(), alpha, tau) << mode << alpha << tau;
    }
    void nonUniform()
    {
        QFETCH(CatmullRomMode, mode);
        QFETCH(double, alpha);
        QFETCH(double, tau);
        const auto pts = uneven();
        const auto curve = catmullRomSegments(pts, tau, mode, alpha);
        QVERIFY(curve.ok());
        QVERIFY(allFinite(*curve));
        checkInterpolates(*curve, pts, 12);
        // Tangents at the joins are parallel and point the same way (G¹); more: in the
        // global knot parameter (segment i has length h_i = |q_{i+1} − q_i|^α) they are equal.
        const std::size_t count = curve->size();
        const std::size_t joins = mode == CatmullRomMode::Closed ? count : count - 1;
        for (std::size_t i = 0; i < joins; ++i) {
            const std::size_t j = (i + 1) % count;
            const Point left = at(derivative((*curve)[i]), 1.0);
            const Point right = at(derivative((*curve)[j]), 0.0);
            QVERIFY(std::fabs(cross(left, right)) <= 1e-12 * norm(left) * norm(right));
            QVERIFY(dot(left, right) > 0);
            const double hi = std::pow(distance(pts[i], pts[(i + 1) % pts.size()]), alpha);
            const double hj = std::pow(distance(pts[j], pts[(j + 1) % pts.size()]), alpha);
            QVERIFY(near(Point(left.x / hi, left.y / hi), Point(right.x / hj, right.y / hj), 10));
        }
        // Uneven spacing: not the uniform curve.
        const auto uniform = catmullRomSegments(pts, tau, mode, 0.0);
        QVERIFY((*uniform)[1].x != (*curve)[1].x || (*uniform)[1].y != (*curve)[1].y);
    }

    void nonUniformReference()
    {
        // Independent reference: the Barry–Goldman form of the non-uniform tangent,
        // m_i = (q_i − q_{i−1})/h_{i−1} − (q_{i+1} − q_{i−1})/(h_{i−1} + h_i) + (q_{i+1} − q_i)/h_i,
        // and the cubic Hermite basis. τ = 1/2, interior segments of an open curve.
        const std::vector<Point> pts{{0, 0}, {3, 0}, {3, 4}, {4, 4}, {10, 12}};
        for (double alpha : {0.5, 1.0}) {
            const auto curve = catmullRomSegments(pts, 0.5, CatmullRomMode::Open, alpha);
            QVERIFY(curve.ok());
            const auto h = [&](std::size_t i) { return std::pow(distance(pts[i], pts[i + 1]), alpha); };
            const auto m = [&](std::size_t i) {
                const double a = h(i - 1), b = h(i);
                return (1.0 / a) * (pts[i] - pts[i - 1]) - (1.0 / (a + b)) * (pts[i + 1] - pts[i - 1]) +
                       (1.0 / b) * (pts[i + 1] - pts[i]);
            };
            for (std::size_t i = 1; i + 2 < pts.size(); ++i) {
                const Point t0 = h(i) * m(i), t1 = h(i) * m(i + 1);
                for (double s : {0.0, 0.25, 0.5, 0.75, 1.0}) {
                    const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
                    const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
                    const Point expected = h00 * pts[i] + h10 * t0 + h01 * pts[i + 1] + h11 * t1;
                    QVERIFY2(near(at((*curve)[i], s), expected, 12),
                             qPrintable(QString("alpha %1 segment %2 s %3").arg(alpha).arg(i).arg(s)));
                }
            }
        }
    }

    // The knot spacing the tab hands to the knot-continuity check: one h_i per segment, from
    // the chord lengths alone (a 3-4-5 triangle and a repeated point), and with it the
    // derivatives in the global parameter, p_i′(1)/h_i and p_{i+1}′(0)/h_{i+1}, agree.
    void intervalsPerSegment()
    {
        const std::vector<Point> triangle{{0, 0}, {3, 0}, {3, 4}};
        using V = std::vector<double>;
        QCOMPARE(catmullRomIntervals(triangle, CatmullRomMode::Open, 1.0), (V{3, 4}));
        QCOMPARE(catmullRomIntervals(triangle, CatmullRomMode::Cyclic, 1.0), (V{3, 4}));
        QCOMPARE(catmullRomIntervals(triangle, CatmullRomMode::Closed, 1.0), (V{3, 4, 5}));
        const V centripetal = catmullRomIntervals(triangle, CatmullRomMode::Closed, 0.5);
        QCOMPARE(centripetal.size(), std::size_t(3));
        QCOMPARE(centripetal[0], std::sqrt(3.0));
        QCOMPARE(centripetal[2], std::sqrt(5.0));
        QCOMPARE(catmullRomIntervals(triangle, CatmullRomMode::Closed, 0.0), (V{1, 1, 1}));
        const std::vector<Point> repeated{{0, 0}, {2, 0}, {2, 0}, {2, 1}};
        QCOMPARE(catmullRomIntervals(repeated, CatmullRomMode::Open, 1.0), (V{2, 0, 1}));
        // Refused as catmullRomSegments refuses them.
        QVERIFY(catmullRomIntervals({{0, 0}}, CatmullRomMode::Open, 0.5).empty());
        QVERIFY(catmullRomIntervals({{0, 0}, {1, 1}}, CatmullRomMode::Cyclic, 0.5).empty());
        QVERIFY(catmullRomIntervals(triangle, CatmullRomMode::Open, 2.0).empty());
        QVERIFY(catmullRomIntervals({{0, 0}, {std::numeric_limits<double>::quiet_NaN(), 1}}, CatmullRomMode::Open, 0.5).empty());

        const auto pts = uneven();
        for (auto mode : {CatmullRomMode::Open, CatmullRomMode::Closed})
            for (double alpha : {0.5, 1.0}) {
                const auto curve = catmullRomSegments(pts, 0.5, mode, alpha);
                const V h = catmullRomIntervals(pts, mode, alpha);
                QVERIFY(curve.ok());
                QCOMPARE(h.size(), curve->size());
                const std::size_t joins = mode == CatmullRomMode::Closed ? h.size() : h.size() - 1;
                for (std::size_t i = 0; i < joins; ++i) {
                    const std::size_t j = (i + 1) % h.size();
                    const Point left = at(derivative((*curve)[i]), 1.0), right = at(derivative((*curve)[j]), 0.0);
                    QVERIFY(near(Point(left.x / h[i], left.y / h[i]), Point(right.x / h[j], right.y / h[j]), 10));
                    if (std::fabs(h[i] - h[j]) > 1e-3 * h[i]) // unequal spacing: the local tangents differ
                        QVERIFY(!near(left, right, 10));
                }
            }
    }

    void equalSpacingIsUniform()
    {
        // All chords equal (a square): every h_i is the same, so α changes nothing.
        const std::vector<Point> square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
        for (auto mode : {CatmullRomMode::Open, CatmullRomMode::Cyclic, CatmullRomMode::Closed}) {
            const auto uniform = catmullRomSegments(square, 0.5, mode);
            for (double alpha : {0.5, 1.0}) {
                const auto curve = catmullRomSegments(square, 0.5, mode, alpha);
                QCOMPARE(curve->size(), uniform->size());
                for (std::size_t i = 0; i < curve->size(); ++i)
                    for (int k = 0; k <= 3; ++k) {
                        QVERIFY(std::fabs((*curve)[i].x.coefficient(k) - (*uniform)[i].x.coefficient(k)) < 1e-14);
                        QVERIFY(std::fabs((*curve)[i].y.coefficient(k) - (*uniform)[i].y.coefficient(k)) < 1e-14);
                    }
            }
        }
    }

    void coincidentPoints_data()
    {
        QTest::addColumn<CatmullRomMode>("mode");
        QTest::addColumn<double>("alpha");
        QTest::addColumn<double>("tau");
        for (auto mode : {CatmullRomMode::Open, CatmullRomMode::Cyclic, CatmullRomMode::Closed})
            for (double alpha : {0.0, 0.5, 1.0})
                for (double tau : {0.5, 2.0})
                    QTest::addRow("%s alpha=%g tau=%g", toString(mode).c_str(), alpha, tau) << mode << alpha << tau;
    }
    void coincidentPoints()
    {
        QFETCH(CatmullRomMode, mode);
        QFETCH(double, alpha);
        QFETCH(double, tau);
        const std::vector<Point> pts{{0, 0}, {0, 0}, {1, 1}, {1, 1}, {1, 1}, {2, 0}, {0, 0}};
        const auto curve = catmullRomSegments(pts, tau, mode, alpha);
        QVERIFY(curve.ok());
        QVERIFY(allFinite(*curve));
        checkInterpolates(*curve, pts, 2);
        for (const Point& p : sampleSegments(*curve, 9))
            QVERIFY(isFinite(p));
        // All points equal: every segment stays at the point.
        const std::vector<Point> same(4, Point(3, -1));
        const auto still = catmullRomSegments(same, tau, mode, alpha);
        QVERIFY(still.ok());
        for (const auto& s : *still)
            QVERIFY(s.x == Polynomial<double>(3.0) && s.y == Polynomial<double>(-1.0));
    }

    void extremeInput_data()
    {
        QTest::addColumn<double>("scale");
        QTest::addColumn<double>("tau");
        QTest::addColumn<double>("alpha");
        for (double alpha : {0.0, 0.5, 1.0}) {
            for (double tau : {-10.0, 10.0})
                QTest::addRow("tau=%g alpha=%g", tau, alpha) << 1.0 << tau << alpha;
            for (double scale : {1e9, 1e-9})
                QTest::addRow("scale=%g alpha=%g", scale, alpha) << scale << 0.5 << alpha;
        }
    }
    void extremeInput()
    {
        QFETCH(double, scale);
        QFETCH(double, tau);
        QFETCH(double, alpha);
        std::vector<Point> unit = uneven();
        std::vector<Point> pts;
        for (const Point& p : unit)
            pts.push_back(scale * p);
        for (auto mode : {CatmullRomMode::Open, CatmullRomMode::Cyclic, CatmullRomMode::Closed}) {
            const auto curve = catmullRomSegments(pts, tau, mode, alpha);
            QVERIFY(curve.ok());
            QVERIFY(allFinite(*curve));
            checkInterpolates(*curve, pts, 12 * scale);
            // The construction commutes with scaling: the curve of scale·q is scale times the curve of q.
            const auto reference = catmullRomSegments(unit, tau, mode, alpha);
            for (std::size_t i = 0; i < curve->size(); ++i)
                for (double s : {0.0, 0.3, 0.7, 1.0})
                    QVERIFY(near(at((*curve)[i], s), scale * at((*reference)[i], s), 1e3 * scale));
        }
    }

    void rejects_data()
    {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        QTest::addColumn<CatmullRomMode>("mode");
        QTest::addColumn<int>("count"); // points taken from Ex 2.13
        QTest::addColumn<int>("badIndex");
        QTest::addColumn<double>("badValue");
        QTest::addColumn<double>("tau");
        QTest::addColumn<double>("alpha");
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("mentions");
        const auto open = CatmullRomMode::Open;
        QTest::newRow("NaN point") << open << 5 << 2 << nan << 0.5 << 0.0 << int(ErrorCode::InvalidInput) << "q_2";
        QTest::newRow("inf point") << open << 5 << 4 << inf << 0.5 << 0.5 << int(ErrorCode::InvalidInput) << "q_4";
        QTest::newRow("-inf point") << CatmullRomMode::Closed << 5 << 0 << -inf << 0.5 << 1.0 << int(ErrorCode::InvalidInput)
                                    << "q_0";
        QTest::newRow("NaN tension") << open << 5 << -1 << 0.0 << nan << 0.0 << int(ErrorCode::InvalidInput) << "tension";
        QTest::newRow("inf tension") << open << 5 << -1 << 0.0 << inf << 0.5 << int(ErrorCode::InvalidInput) << "tension";
        QTest::newRow("alpha < 0") << open << 5 << -1 << 0.0 << 0.5 << -0.1 << int(ErrorCode::OutOfRange) << "α";
        QTest::newRow("alpha > 1") << open << 5 << -1 << 0.0 << 0.5 << 1.5 << int(ErrorCode::OutOfRange) << "α";
        QTest::newRow("alpha NaN") << open << 5 << -1 << 0.0 << 0.5 << nan << int(ErrorCode::OutOfRange) << "α";
        QTest::newRow("open, 1 point") << open << 1 << -1 << 0.0 << 0.5 << 0.0 << int(ErrorCode::TooFewPoints) << "2";
        QTest::newRow("open, none") << open << 0 << -1 << 0.0 << 0.5 << 0.5 << int(ErrorCode::TooFewPoints) << "2";
        QTest::newRow("cyclic, 2 points") << CatmullRomMode::Cyclic << 2 << -1 << 0.0 << 0.5 << 0.0
                                          << int(ErrorCode::TooFewPoints) << "3";
        QTest::newRow("closed, 2 points") << CatmullRomMode::Closed << 2 << -1 << 0.0 << 0.5 << 1.0
                                          << int(ErrorCode::TooFewPoints) << "3";
    }
    void rejects()
    {
        QFETCH(CatmullRomMode, mode);
        QFETCH(int, count);
        QFETCH(int, badIndex);
        QFETCH(double, badValue);
        QFETCH(double, tau);
        QFETCH(double, alpha);
        QFETCH(int, code);
        QFETCH(QString, mentions);
        std::vector<Point> pts = toDouble(ex213Points());
        pts.resize(static_cast<std::size_t>(count));
        if (badIndex >= 0)
            pts[static_cast<std::size_t>(badIndex)].y = badValue;
        const auto curve = catmullRomSegments(pts, tau, mode, alpha);
        QVERIFY(!curve.ok());
        QCOMPARE(int(curve.error().code), code);
        QVERIFY2(QString::fromStdString(curve.error().message).contains(mentions), curve.error().message.c_str());
        if (code == int(ErrorCode::TooFewPoints)) { // the exact path agrees
            std::vector<RPoint> exact = ex213Points();
            exact.resize(static_cast<std::size_t>(count));
            const auto e = catmullRomSegments(exact, q(1, 2), mode);
            QVERIFY(!e.ok());
            QCOMPARE(e.error().code, ErrorCode::TooFewPoints);
        }
    }

    void overflowIsAnError()
    {
        // Finite input whose curve overflows: an error, never inf/NaN coefficients.
        const std::vector<Point> pts{{-1e308, 0}, {1e308, 0}, {-1e308, 1}};
        for (double alpha : {0.0, 0.5}) {
            const auto curve = catmullRomSegments(pts, 10.0, CatmullRomMode::Open, alpha);
            QVERIFY(!curve.ok());
            QCOMPARE(curve.error().code, ErrorCode::OutOfRange);
        }
    }

    void sampling_data()
    {
        QTest::addColumn<int>("samples");
        QTest::newRow("2") << 2;
        QTest::newRow("5") << 5;
        QTest::newRow("101") << 101;
    }
    void sampling()
    {
        QFETCH(int, samples);
        const std::vector<Point> pts = toDouble(ex213Points());
        for (auto mode : {CatmullRomMode::Open, CatmullRomMode::Closed}) {
            const auto curve = catmullRomSegments(pts, 0.5, mode);
            const std::vector<Point> out = sampleSegments(*curve, samples);
            QCOMPARE(out.size(), curve->size() * static_cast<std::size_t>(samples));
            const auto S = static_cast<std::size_t>(samples);
            for (std::size_t i = 0; i < curve->size(); ++i) {
                QVERIFY(out[i * S] == pts[i]);
                QVERIFY(out[i * S + S - 1] == pts[(i + 1) % pts.size()]);
                if (samples % 2 == 1) // the middle sample is s = 1/2
                    QVERIFY(near(out[i * S + S / 2], at((*curve)[i], 0.5), 10));
            }
        }
    }

    void parseMode_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("mode"); // -1: rejected
        QTest::newRow("open") << "open" << int(CatmullRomMode::Open);
        QTest::newRow("cyclic") << "cyclic" << int(CatmullRomMode::Cyclic);
        QTest::newRow("closed") << "closed" << int(CatmullRomMode::Closed);
        QTest::newRow("case and spaces") << "  Closed " << int(CatmullRomMode::Closed);
        QTest::newRow("empty") << "" << -1;
        QTest::newRow("close") << "close" << -1;
        QTest::newRow("cyclical") << "cyclical" << -1;
    }
    void parseMode()
    {
        QFETCH(QString, text);
        QFETCH(int, mode);
        const auto parsed = parseCatmullRomMode(text.toStdString());
        if (mode < 0) {
            QVERIFY(!parsed.has_value());
            return;
        }
        QVERIFY(parsed.has_value());
        QCOMPARE(int(*parsed), mode);
        QCOMPARE(parseCatmullRomMode(toString(*parsed)), parsed); // round trip
    }

    void curveTightness_data()
    {
        QTest::addColumn<double>("s");
        for (double s : {-1.0, 0.0, 0.5, 1.0, 2.0})
            QTest::addRow("s=%g", s) << s;
    }
    void curveTightness()
    {
        // Processing's curve basis for curveTightness(s), rows for t³, t², t, 1:
        //   (s−1)/2 (s+3)/2 (−3−s)/2 (1−s)/2 | 1−s (−5−s)/2 s+2 (s−1)/2 | (s−1)/2 0 (1−s)/2 0 | 0 1 0 0
        // must be M(τ) with τ = (1 − s)/2, rows reversed.
        QFETCH(double, s);
        const double processing[4][4] = {{(s - 1) / 2, (s + 3) / 2, (-3 - s) / 2, (1 - s) / 2},
                                         {1 - s, (-5 - s) / 2, s + 2, (s - 1) / 2},
                                         {(s - 1) / 2, 0, (1 - s) / 2, 0},
                                         {0, 1, 0, 0}};
        const double tau = curveTightnessToTau(s);
        const auto m = catmullRomMatrix(tau);
        for (std::size_t r = 0; r < 4; ++r)
            for (std::size_t c = 0; c < 4; ++c)
                QVERIFY(m[r][c] == processing[3 - r][c]);
        QCOMPARE(tauToCurveTightness(tau), s);
        QCOMPARE(curveTightnessToTau(0.0), 0.5); // Processing's default is the thesis's usual τ
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestCatmullRom)
#include "test_catmull_rom.moc"
