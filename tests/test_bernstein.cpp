// Bernstein polynomials (Def 2.5): Ex 2.4's expansions, Lemma 2.1, partition of unity,
// symmetry, Prop 2.1 (De Casteljau = Bernstein) and Ex 2.5/2.6 (Def 2.6).
#include "core/curves/bezier/bernstein.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/exact/polynomial_text.h"

#include <QtTest>
#include "tests/test_main.h"

#include <random>

using namespace granota;
using RPoly = Polynomial<Rational>;

class TestBernstein : public QObject {
    Q_OBJECT
private slots:
    // Ex 2.4, every polynomial for n <= 5, as printed.
    void example24_data()
    {
        QTest::addColumn<int>("n");
        QTest::addColumn<int>("i");
        QTest::addColumn<QString>("printed");
        const char* table[][6] = {
            {"1"},
            {"1 - t", "t"},
            {"1 - 2t + t^2", "2t - 2t^2", "t^2"},
            {"1 - 3t + 3t^2 - t^3", "3t - 6t^2 + 3t^3", "3t^2 - 3t^3", "t^3"},
            {"1 - 4t + 6t^2 - 4t^3 + t^4", "4t - 12t^2 + 12t^3 - 4t^4", "6t^2 - 12t^3 + 6t^4", "4t^3 - 4t^4", "t^4"},
            {"1 - 5t + 10t^2 - 10t^3 + 5t^4 - t^5", "5t - 20t^2 + 30t^3 - 20t^4 + 5t^5", "10t^2 - 30t^3 + 30t^4 - 10t^5",
             "10t^3 - 20t^4 + 10t^5", "5t^4 - 5t^5", "t^5"},
        };
        for (int n = 0; n <= 5; ++n)
            for (int i = 0; i <= n; ++i)
                QTest::newRow(qPrintable(QString("B_%1^%2").arg(i).arg(n))) << n << i << QString(table[n][i]);
    }
    void example24()
    {
        QFETCH(int, n);
        QFETCH(int, i);
        QFETCH(QString, printed);
        QCOMPARE(QString::fromStdString(toText(bernsteinPolynomial(i, n))), printed);
        // The recursion of Lemma 2.1, run on polynomials, gives the same expansion.
        const auto viaRecursion = bernsteinAll(n, RPoly::identity());
        QCOMPARE(viaRecursion[i], bernsteinPolynomial(i, n));
    }

    void outsideRangeIsZero()
    {
        QVERIFY(bernsteinPolynomial(-1, 3).isZero());
        QVERIFY(bernsteinPolynomial(4, 3).isZero());
        QCOMPARE(bernstein(5, 3, 0.5), 0.0);
    }

    // Lemma 2.1: B_i^n = (1-t) B_i^{n-1} + t B_{i-1}^{n-1}, as polynomials, n up to 12.
    void lemma21()
    {
        const RPoly t = RPoly::identity(), one(1);
        for (int n = 1; n <= 12; ++n)
            for (int i = 0; i <= n; ++i)
                QCOMPARE(bernsteinPolynomial(i, n),
                         (one - t) * bernsteinPolynomial(i, n - 1) + t * bernsteinPolynomial(i - 1, n - 1));
    }

    void partitionOfUnityAndSymmetry()
    {
        for (int n = 0; n <= 20; ++n) {
            RPoly sum;
            for (int i = 0; i <= n; ++i) {
                sum += bernsteinPolynomial(i, n);
                // B_i^n(t) = B_{n-i}^n(1-t)
                const Rational t(3, 7);
                QCOMPARE(bernsteinPolynomial(i, n)(t), bernsteinPolynomial(n - i, n)(Rational(1 - t)));
            }
            QCOMPARE(sum, RPoly(1));
        }
        // In floating point too, to rounding, for large n.
        for (double t : {0.0, 1e-9, 0.3, 0.5, 0.999, 1.0}) {
            const auto b = bernsteinAll(60, t);
            double s = 0;
            for (double v : b) {
                QVERIFY(v >= 0);
                s += v;
            }
            QVERIFY(std::abs(s - 1.0) < 1e-14);
        }
    }

    void doubleAgreesWithExact()
    {
        for (int n : {3, 10, 30}) {
            const Rational t(2, 9);
            const auto b = bernsteinAll(n, t.get_d());
            for (int i = 0; i <= n; ++i)
                QVERIFY(std::abs(b[i] - bernsteinPolynomial(i, n)(t).get_d()) < 1e-15);
        }
    }

    // Prop 2.1: P_l^r(t) = sum_k B_k^r(t) Q_{l+k}, for every level of the triangle.
    void proposition21()
    {
        std::mt19937 rng(7);
        std::uniform_int_distribution<int> d(-20, 20);
        std::vector<RPoint> q;
        for (int i = 0; i <= 7; ++i)
            q.emplace_back(frac(d(rng), 3), frac(d(rng), 5));
        for (const Rational& t : {Rational(0), Rational(1, 3), Rational(5, 8), Rational(1), Rational(3, 2)}) {
            const auto table = deCasteljau(q, t);
            for (int r = 0; r <= 7; ++r)
                for (int l = 0; l + r <= 7; ++l) {
                    const std::vector<RPoint> window(q.begin() + l, q.begin() + l + r + 1);
                    QCOMPARE(table.levels[r][l], bezierBernstein(window, t));
                }
        }
    }

    // Ex 2.5 and Ex 2.6: the Bernstein route gives the curves of Ex 2.2 and Ex 2.3.
    void examples25and26_data()
    {
        QTest::addColumn<QString>("points");
        QTest::addColumn<QString>("x");
        QTest::addColumn<QString>("y");
        QTest::newRow("Ex 2.5") << "2,3;-1,8;-5,-3;3,0;-7,-2"
                                << "2 - 12t - 6t^2 + 52t^3 - 43t^4"
                                << "3 + 20t - 96t^2 + 120t^3 - 49t^4";
        QTest::newRow("Ex 2.6") << "1,7;0,-3;-4,-2;8,0;1,7"
                                << "1 - 4t - 18t^2 + 76t^3 - 54t^4"
                                << "7 - 40t + 66t^2 - 40t^3 + 14t^4";
    }
    void examples25and26()
    {
        QFETCH(QString, points);
        QFETCH(QString, x);
        QFETCH(QString, y);
        std::vector<Vec2<RPoly>> p;
        for (const QString& pair : points.split(';')) {
            const auto xy = pair.split(',');
            p.emplace_back(RPoly(Rational(xy[0].toInt())), RPoly(Rational(xy[1].toInt())));
        }
        const Vec2<RPoly> alpha = bezierBernstein(p, RPoly::identity());
        QCOMPARE(QString::fromStdString(toText(alpha.x)), x);
        QCOMPARE(QString::fromStdString(toText(alpha.y)), y);
        // Each term B_k^4(t) P_k as printed for Ex 2.5, e.g. B_1^4 P_1 = (-4t + 12t^2 - 12t^3 + 4t^4, ...).
        if (QByteArray(QTest::currentDataTag()) == "Ex 2.5") {
            const RPoly term = bernsteinPolynomial(1, 4) * p[1].y;
            QCOMPARE(QString::fromStdString(toText(term)), QString("32t - 96t^2 + 96t^3 - 32t^4"));
        }
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestBernstein)
#include "test_bernstein.moc"
