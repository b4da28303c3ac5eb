// Catmull-Rom segments as cubic Bézier curves (beyond the thesis: the Bernstein form of the
// segments of Lemma 2.3 / Def 2.10, Farin): the Bézier form traces the same points exactly,
// the uniform control points are p_1 + τ(p_2 − p_0)/3 and p_2 − τ(p_3 − p_1)/3, and the
// thesis's Ex 2.11–2.13 convert to the control points worked out by hand below.
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/splines/bezier_segments.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/exact/rational.h"

#include <QRandomGenerator>
#include <QtTest>
#include "tests/test_main.h"

#include <cmath>

using namespace granota;

namespace granota {
static char* toString(const Vec2<Rational>& p)
{
    return qstrdup(("(" + granota::toString(p.x) + ", " + granota::toString(p.y) + ")").c_str());
}
} // namespace granota

Q_DECLARE_METATYPE(granota::CatmullRomMode)
Q_DECLARE_METATYPE(granota::RPoint)
/// The inner control points b_1, b_2 of each segment, as one named type: QTest's column of a
/// QVector<RPoint> has a type name Qt's debug build refuses as not normalized.
struct InnerPoints {
    QVector<granota::RPoint> points;
};
Q_DECLARE_METATYPE(InnerPoints)

namespace {

RPoint rp(long x, long y) { return RPoint(Rational(x), Rational(y)); }
RPoint rq(long xn, long xd, long yn, long yd) { return RPoint(frac(xn, xd), frac(yn, yd)); }

template <class S> Vec2<S> at(const Vec2<Polynomial<S>>& p, const S& s) { return Vec2<S>(p.x(s), p.y(s)); }
template <class S> std::vector<Vec2<S>> controls(const BezierSegment<S>& b) { return {b[0], b[1], b[2], b[3]}; }

std::vector<RPoint> ex213Points() { return {rp(3, 5), rp(2, 2), rp(6, 0), rp(8, 3), rp(7, 5)}; }

Rational randomRational(QRandomGenerator& g)
{
    return frac(static_cast<long>(g.bounded(-200, 201)), static_cast<long>(g.bounded(1, 37)));
}

} // namespace

class TestBezierSegments : public QObject {
    Q_OBJECT
private slots:
    // The Bézier form and the power form are the same cubic: equal at many rational s.
    void samePointsExactly_data()
    {
        QTest::addColumn<CatmullRomMode>("mode");
        QTest::addColumn<QString>("tau");
        for (CatmullRomMode mode : {CatmullRomMode::Open, CatmullRomMode::Cyclic, CatmullRomMode::Closed})
            for (const char* tau : {"0", "1/2", "1", "2", "-1/3"})
                QTest::addRow("%s tau=%s", toString(mode).c_str(), tau) << mode << QString(tau);
    }
    void samePointsExactly()
    {
        QFETCH(CatmullRomMode, mode);
        QFETCH(QString, tau);
        const auto t = parseRational(tau.toStdString());
        QVERIFY(t.has_value());
        const std::vector<RPoint> pts{rp(0, 0), rp(4, 1), rp(5, 5), rp(1, 7), rp(-3, 4), rp(-2, -1)};
        const auto segs = catmullRomSegments(pts, *t, mode);
        QVERIFY(segs.ok());
        const auto bez = bezierSegments(*segs);
        QCOMPARE(bez.size(), segs->size());
        for (std::size_t i = 0; i < bez.size(); ++i)
            for (int j = 0; j <= 24; ++j) {
                const Rational s = frac(j - 2, 20); // includes s < 0 and s > 1: the same cubic
                QCOMPARE(deCasteljauPoint(controls(bez[i]), s), at((*segs)[i], s));
            }
    }

    // b_1 = p_1 + τ(p_2 − p_0)/3, b_2 = p_2 − τ(p_3 − p_1)/3, b_0 = p_1, b_3 = p_2 (Def 2.8).
    void uniformFormula()
    {
        QRandomGenerator g(20261202);
        for (int trial = 0; trial < 200; ++trial) {
            RPoint p[4];
            for (auto& v : p)
                v = RPoint(randomRational(g), randomRational(g));
            const Rational tau = randomRational(g);
            const auto bez = bezierSegments(std::vector{catmullRomSegment(p[0], p[1], p[2], p[3], tau)});
            QCOMPARE(bez.size(), std::size_t(1));
            const Rational third = frac(1, 3);
            QCOMPARE(bez[0][0], p[1]);
            QCOMPARE(bez[0][1], p[1] + Rational(tau * third) * (p[2] - p[0]));
            QCOMPARE(bez[0][2], p[2] - Rational(tau * third) * (p[3] - p[1]));
            QCOMPARE(bez[0][3], p[2]);
        }
    }

    // Ex 2.11 (p_0 = (1,1), p_1 = (3,4), p_2 = (2,−1), p_3 = (5,1)), by hand from the formula:
    // τ = 0 gives b_1 = p_1, b_2 = p_2; τ = 1/2: (3,4) + (1,−2)/6, (2,−1) − (2,−3)/6;
    // τ = 2: (3,4) + 2(1,−2)/3, (2,−1) − 2(2,−3)/3.
    void ex211_data()
    {
        QTest::addColumn<QString>("tau");
        QTest::addColumn<RPoint>("b1");
        QTest::addColumn<RPoint>("b2");
        QTest::newRow("tau 0") << "0" << rp(3, 4) << rp(2, -1);
        QTest::newRow("tau 1/2") << "1/2" << rq(19, 6, 11, 3) << rq(5, 3, -1, 2);
        QTest::newRow("tau 2") << "2" << rq(11, 3, 8, 3) << rq(2, 3, 1, 1);
    }
    void ex211()
    {
        QFETCH(QString, tau);
        QFETCH(RPoint, b1);
        QFETCH(RPoint, b2);
        const auto t = parseRational(tau.toStdString());
        QVERIFY(t.has_value());
        const auto bez = bezierSegments(std::vector{catmullRomSegment(rp(1, 1), rp(3, 4), rp(2, -1), rp(5, 1), *t)});
        QCOMPARE(bez[0][0], rp(3, 4));
        QCOMPARE(bez[0][1], b1);
        QCOMPARE(bez[0][2], b2);
        QCOMPARE(bez[0][3], rp(2, -1));
    }

    // Ex 2.12's blending functions (Cor 2.1) in the Bernstein basis: w_0 = (0, −τ/3, 0, 0),
    // w_1 = (1, 1, τ/3, 0), w_2 = (0, τ/3, 1, 1), w_3 = (0, 0, −τ/3, 0) — the uniform formula
    // read one point at a time. τ = 1/2.
    void ex212Blending()
    {
        const Rational tau = frac(1, 2), t3 = frac(1, 6);
        const auto w = blendingFunctions(tau);
        const Rational expected[4][4] = {
            {Rational(0), Rational(-t3), Rational(0), Rational(0)},
            {Rational(1), Rational(1), t3, Rational(0)},
            {Rational(0), t3, Rational(1), Rational(1)},
            {Rational(0), Rational(0), Rational(-t3), Rational(0)},
        };
        for (int j = 0; j < 4; ++j) {
            const auto bez = bezierSegments(std::vector{Vec2<Polynomial<Rational>>(w[j], Polynomial<Rational>())});
            for (int k = 0; k < 4; ++k)
                QCOMPARE(bez[0][k], RPoint(expected[j][k], Rational(0)));
        }
    }

    // Ex 2.13 (τ = 1/2), control points worked out by hand with the uniform formula.
    void ex213_data()
    {
        QTest::addColumn<CatmullRomMode>("mode");
        QTest::addColumn<InnerPoints>("inner"); // b_1, b_2 of each segment
        const QVector<RPoint> middle{rq(5, 2, 7, 6), rq(5, 1, -1, 6), rq(7, 1, 1, 6), rq(47, 6, 13, 6)};
        // Open: p_1 from (q_0, q_0, q_1, q_2), p_4 from (q_2, q_3, q_4, q_4).
        QTest::newRow("open") << CatmullRomMode::Open
                              << InnerPoints{QVector<RPoint>{rq(17, 6, 9, 2), rq(3, 2, 17, 6)} + middle +
                                             QVector<RPoint>{rq(49, 6, 23, 6), rq(43, 6, 14, 3)}};
        // Cyclic: p_1 from (q_4, q_0, q_1, q_2): (3,5) + ((2,2) − (7,5))/6, (2,2) − ((6,0) − (3,5))/6.
        const QVector<RPoint> first{rq(13, 6, 9, 2), rq(3, 2, 17, 6)};
        // p_4 from (q_2, q_3, q_4, q_0): (8,3) + ((7,5) − (6,0))/6, (7,5) − ((3,5) − (8,3))/6.
        const QVector<RPoint> last{rq(49, 6, 23, 6), rq(47, 6, 14, 3)};
        QTest::newRow("cyclic") << CatmullRomMode::Cyclic << InnerPoints{first + middle + last};
        // Closed adds q_4 → q_0 from (q_3, q_4, q_0, q_1): (7,5) + ((3,5) − (8,3))/6, (3,5) − ((2,2) − (7,5))/6.
        QTest::newRow("closed") << CatmullRomMode::Closed
                                << InnerPoints{first + middle + last + QVector<RPoint>{rq(37, 6, 16, 3), rq(23, 6, 11, 2)}};
    }
    void ex213()
    {
        QFETCH(CatmullRomMode, mode);
        QFETCH(InnerPoints, inner);
        const QVector<RPoint>& b12 = inner.points;
        const auto q = ex213Points();
        const auto segs = catmullRomSegments(q, frac(1, 2), mode);
        QVERIFY(segs.ok());
        const auto bez = bezierSegments(*segs);
        QCOMPARE(int(bez.size()) * 2, b12.size());
        for (std::size_t i = 0; i < bez.size(); ++i) {
            QCOMPARE(bez[i][0], q[i % q.size()]);
            QCOMPARE(bez[i][1], b12[2 * int(i)]);
            QCOMPARE(bez[i][2], b12[2 * int(i) + 1]);
            QCOMPARE(bez[i][3], q[(i + 1) % q.size()]);
        }
    }

    // Centripetal (α = 1/2) segments in doubles: the Bézier form agrees with the polynomial.
    void centripetalDoubles_data()
    {
        QTest::addColumn<CatmullRomMode>("mode");
        QTest::newRow("open") << CatmullRomMode::Open;
        QTest::newRow("cyclic") << CatmullRomMode::Cyclic;
        QTest::newRow("closed") << CatmullRomMode::Closed;
    }
    void centripetalDoubles()
    {
        QFETCH(CatmullRomMode, mode);
        const std::vector<Point> pts{{0, 0}, {4, 1}, {4.5, 1.2}, {1, 7}, {-3, 4}, {-2, -1}};
        const auto segs = catmullRomSegments(pts, 0.5, mode, 0.5);
        QVERIFY(segs.ok());
        const auto bez = bezierSegments(*segs);
        QCOMPARE(bez.size(), segs->size());
        for (std::size_t i = 0; i < bez.size(); ++i) {
            QVERIFY(std::abs(bez[i][0].x - pts[i % pts.size()].x) < 1e-12);
            QVERIFY(std::abs(bez[i][3].y - pts[(i + 1) % pts.size()].y) < 1e-12);
            for (int j = 0; j <= 50; ++j) {
                const double s = j / 50.0;
                const Point a = deCasteljauPoint(controls(bez[i]), s), b = at((*segs)[i], s);
                QVERIFY2(std::abs(a.x - b.x) < 1e-12 && std::abs(a.y - b.y) < 1e-12,
                         qPrintable(QStringLiteral("segment %1 s=%2").arg(i).arg(s)));
            }
        }
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestBezierSegments)
#include "test_bezier_segments.moc"
