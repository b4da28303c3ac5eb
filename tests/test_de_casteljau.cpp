// De Casteljau's algorithm (Def 2.4): the tables of Ex 2.2 and Ex 2.3 exactly as printed,
// tangent, split, degree elevation, the power basis, and accuracy at degree 40.
#include "core/curves/bezier/bernstein.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bezier/degree_elevation.h"
#include "core/curves/bezier/power_basis.h"
#include "core/exact/polynomial_text.h"
#include "rational_points.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <random>

using namespace granota;
using granota::testing::pts;
using RPoly = Polynomial<Rational>;
using PolyPoint = Vec2<RPoly>;

Q_DECLARE_METATYPE(std::vector<RPoint>)

namespace {

RPoly poly(const char* text)
{
    auto p = parsePolynomial(text);
    if (!p)
        qFatal("bad polynomial in test: %s", text);
    return *p;
}

/// The symbolic table: every P_i^r(t) as a polynomial (Def 2.4 with t the identity).
DeCasteljauTable<RPoly> symbolicTable(const std::vector<RPoint>& points)
{
    std::vector<PolyPoint> p;
    for (const auto& q : points)
        p.emplace_back(RPoly(q.x), RPoly(q.y));
    return deCasteljau(p, RPoly::identity());
}

struct Entry {
    int r, i;
    const char* x;
    const char* y;
};

} // namespace

class TestDeCasteljau : public QObject {
    Q_OBJECT
private slots:
    // Ex 2.2 and Ex 2.3: the whole triangle of P_i^r(t), transcribed from the thesis.
    void thesisTables_data()
    {
        QTest::addColumn<std::vector<RPoint>>("points");
        QTest::addColumn<QStringList>("entries"); // "r|i|x|y"
        const auto row = [](const std::vector<Entry>& e) {
            QStringList l;
            for (const auto& x : e)
                l << QString("%1|%2|%3|%4").arg(x.r).arg(x.i).arg(x.x, x.y);
            return l;
        };
        QTest::newRow("Ex 2.2") << pts({{2, 3}, {-1, 8}, {-5, -3}, {3, 0}, {-7, -2}})
                                << row({{1, 0, "2 - 3t", "3 + 5t"},
                                        {1, 1, "-1 - 4t", "8 - 11t"},
                                        {1, 2, "-5 + 8t", "-3 + 3t"},
                                        {1, 3, "3 - 10t", "-2t"},
                                        {2, 0, "2 - 6t - t^2", "3 + 10t - 16t^2"},
                                        {2, 1, "-1 - 8t + 12t^2", "8 - 22t + 14t^2"},
                                        {2, 2, "-5 + 16t - 18t^2", "-3 + 6t - 5t^2"},
                                        {3, 0, "2 - 9t - 3t^2 + 13t^3", "3 + 15t - 48t^2 + 30t^3"},
                                        {3, 1, "-1 - 12t + 36t^2 - 30t^3", "8 - 33t + 42t^2 - 19t^3"},
                                        {4, 0, "2 - 12t - 6t^2 + 52t^3 - 43t^4", "3 + 20t - 96t^2 + 120t^3 - 49t^4"}});
        QTest::newRow("Ex 2.3") << pts({{1, 7}, {0, -3}, {-4, -2}, {8, 0}, {1, 7}})
                                << row({{1, 0, "1 - t", "7 - 10t"},
                                        {1, 1, "-4t", "-3 + t"},
                                        {1, 2, "-4 + 12t", "-2 + 2t"},
                                        {1, 3, "8 - 7t", "7t"},
                                        {2, 0, "1 - 2t - 3t^2", "7 - 20t + 11t^2"},
                                        {2, 1, "-8t + 16t^2", "-3 + 2t + t^2"},
                                        {2, 2, "-4 + 24t - 19t^2", "-2 + 4t + 5t^2"},
                                        {3, 0, "1 - 3t - 9t^2 + 19t^3", "7 - 30t + 33t^2 - 10t^3"},
                                        {3, 1, "-12t + 48t^2 - 35t^3", "-3 + 3t + 3t^2 + 4t^3"},
                                        {4, 0, "1 - 4t - 18t^2 + 76t^3 - 54t^4", "7 - 40t + 66t^2 - 40t^3 + 14t^4"}});
    }
    void thesisTables()
    {
        QFETCH(std::vector<RPoint>, points);
        QFETCH(QStringList, entries);
        const auto table = symbolicTable(points);
        QCOMPARE(table.degree(), 4);
        for (int r = 0; r <= 4; ++r)
            QCOMPARE(int(table.levels[r].size()), 5 - r);
        // Level 0 is the control points themselves.
        for (int i = 0; i <= 4; ++i) {
            QCOMPARE(table.levels[0][i].x, RPoly(points[i].x));
            QCOMPARE(table.levels[0][i].y, RPoly(points[i].y));
        }
        for (const QString& e : entries) {
            const QStringList f = e.split('|');
            const int r = f[0].toInt(), i = f[1].toInt();
            const auto& got = table.levels[r][i];
            QVERIFY2(got.x == poly(f[2].toLatin1()),
                     qPrintable(
                         QString("P_%1^%2 x: got %3, thesis %4").arg(i).arg(r).arg(QString::fromStdString(toText(got.x)), f[2])));
            QVERIFY2(got.y == poly(f[3].toLatin1()),
                     qPrintable(
                         QString("P_%1^%2 y: got %3, thesis %4").arg(i).arg(r).arg(QString::fromStdString(toText(got.y)), f[3])));
        }
        // The printed text matches character for character for c(t) too.
        const auto& c = table.point();
        QCOMPARE(QString::fromStdString(toText(c.x)), entries.last().split('|')[2]);
        QCOMPARE(QString::fromStdString(toText(c.y)), entries.last().split('|')[3]);
        // And the power-basis conversion agrees with the symbolic construction.
        const auto power = bezierToPowerBasis(points);
        QCOMPARE(power.x, c.x);
        QCOMPARE(power.y, c.y);
    }

    void endpointInterpolation()
    {
        const auto p = pts({{2, 3}, {-1, 8}, {-5, -3}, {3, 0}, {-7, -2}});
        QCOMPARE(deCasteljau(p, Rational(0)).point(), p.front());
        QCOMPARE(deCasteljau(p, Rational(1)).point(), p.back());
        // Ex 2.3 is closed: c(0) = c(1) = (1, 7).
        const auto q = pts({{1, 7}, {0, -3}, {-4, -2}, {8, 0}, {1, 7}});
        QCOMPARE(deCasteljau(q, Rational(1)).point(), deCasteljau(q, Rational(0)).point());
    }

    void exactAtRationalT()
    {
        // c(1/2) of Ex 2.2 from the printed polynomial: x = 2 - 6 - 3/2 + 13/2 - 43/16.
        const auto p = pts({{2, 3}, {-1, 8}, {-5, -3}, {3, 0}, {-7, -2}});
        const Rational t(1, 2);
        const RPoint c = deCasteljau(p, t).point();
        QCOMPARE(c.x, poly("2 - 12t - 6t^2 + 52t^3 - 43t^4")(t));
        QCOMPARE(c.y, poly("3 + 20t - 96t^2 + 120t^3 - 49t^4")(t));
    }

    void tangentIsDerivative()
    {
        // c'(t) = n (P_1^{n-1} - P_0^{n-1}) equals the derivative of the power form.
        const auto p = pts({{2, 3}, {-1, 8}, {-5, -3}, {3, 0}, {-7, -2}});
        const auto c = bezierToPowerBasis(p);
        for (const Rational& t : {Rational(0), Rational(1, 3), Rational(3, 4), Rational(1)}) {
            const RPoint d = deCasteljau(p, t).tangent();
            QCOMPARE(d.x, c.x.derivative()(t));
            QCOMPARE(d.y, c.y.derivative()(t));
        }
        // At the ends the tangent is n(P_1 - P_0) and n(P_n - P_{n-1}).
        QCOMPARE(deCasteljau(p, Rational(0)).tangent(), Rational(4) * (p[1] - p[0]));
        QCOMPARE(deCasteljau(p, Rational(1)).tangent(), Rational(4) * (p[4] - p[3]));
    }

    void splitReproducesTheCurve()
    {
        // The halves' control points (the triangle's edges) trace c on [0,t] and [t,1].
        const auto p = pts({{1, 7}, {0, -3}, {-4, -2}, {8, 0}, {1, 7}});
        const Rational t(2, 5);
        const auto table = deCasteljau(p, t);
        const auto left = table.leftHalf(), right = table.rightHalf();
        QCOMPARE(left.front(), p.front());
        QCOMPARE(left.back(), table.point());
        QCOMPARE(right.front(), table.point());
        QCOMPARE(right.back(), p.back());
        for (const Rational& s : {Rational(0), Rational(1, 7), Rational(1, 2), Rational(9, 10), Rational(1)}) {
            QCOMPARE(deCasteljau(left, s).point(), deCasteljau(p, Rational(t * s)).point());
            QCOMPARE(deCasteljau(right, s).point(), deCasteljau(p, Rational(t + (1 - t) * s)).point());
        }
    }

    void degreeElevationKeepsTheCurve()
    {
        const auto p = pts({{2, 3}, {-1, 8}, {-5, -3}, {3, 0}, {-7, -2}});
        auto q = elevateDegree(p);
        QCOMPARE(int(q.size()), 6);
        const auto a = bezierToPowerBasis(p), b = bezierToPowerBasis(q);
        QCOMPARE(b.x, a.x); // identical polynomial, so identical curve
        QCOMPARE(b.y, a.y);
        q = elevateDegree(elevateDegree(q));
        QCOMPARE(bezierToPowerBasis(q).x, a.x);
        // Elevating a degree-4 curve moves the interior control points.
        QVERIFY(elevateDegree(p)[1] != p[1]);
    }

    void matlabSampling()
    {
        // De_Casteljau(P, part) samples t = (k-1)/part; ends exactly P_0 and P_n.
        const std::vector<Point> p{{2, 3}, {-1, 8}, {-5, -3}, {3, 0}, {-7, -2}};
        const auto s = sampleBezier(p, 11);
        QCOMPARE(int(s.size()), 11);
        QCOMPARE(s.front(), p.front());
        QCOMPARE(s.back(), p.back());
        const auto c = bezierToPowerBasis(toRational(p));
        for (int k = 0; k <= 10; ++k) {
            const Rational t(k, 10);
            QVERIFY(std::abs(s[k].x - c.x(t).get_d()) < 1e-13);
            QVERIFY(std::abs(s[k].y - c.y(t).get_d()) < 1e-13);
        }
    }

    // A degree-40 Bézier evaluates to within 1e-12 of the exact value, while Horner on the
    // power basis (same data, same doubles) does not: the lesson of docs/work-precision.md.
    void degree40IsAccurate()
    {
        std::mt19937 rng(2024);
        std::uniform_real_distribution<double> coord(-1.0, 1.0);
        std::vector<Point> p;
        for (int i = 0; i <= 40; ++i)
            p.emplace_back(coord(rng), coord(rng));
        const auto exactPoints = toRational(p);
        const auto powerDouble = bezierToPowerBasis(p);
        double worstCasteljau = 0, worstBernstein = 0, worstHorner = 0;
        for (int k = 0; k <= 64; ++k) {
            const double t = k / 64.0; // exactly representable, so the reference is exact
            const RPoint exact = deCasteljau(exactPoints, exactRational(t)).point();
            const Point a = deCasteljauPoint(p, t);
            const Point b = bezierBernstein(p, t);
            const Point h = evaluateHorner(powerDouble, t);
            worstCasteljau = std::max({worstCasteljau, std::abs(a.x - exact.x.get_d()), std::abs(a.y - exact.y.get_d())});
            worstBernstein = std::max({worstBernstein, std::abs(b.x - exact.x.get_d()), std::abs(b.y - exact.y.get_d())});
            worstHorner = std::max({worstHorner, std::abs(h.x - exact.x.get_d()), std::abs(h.y - exact.y.get_d())});
        }
        qInfo("degree 40, max error: De Casteljau %.3g, Bernstein (Lemma 2.1) %.3g, Horner on power basis %.3g", worstCasteljau,
              worstBernstein, worstHorner);
        QVERIFY(worstCasteljau < 1e-12);
        QVERIFY(worstBernstein < 1e-12);
        QVERIFY(worstHorner > 1e-6); // the power basis visibly loses digits
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestDeCasteljau)
#include "test_de_casteljau.moc"
