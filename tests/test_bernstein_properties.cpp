// The live property checks of the Bernstein tab (core/curves/bezier/bernstein_properties.h): partition of
// unity, symmetry and Lemma 2.1 as residuals and as exact identities, and Def 2.6 written
// term by term as in Ex 2.5 and Ex 2.6.
#include "core/curves/bezier/bernstein.h"
#include "core/curves/bezier/bernstein_properties.h"
#include "core/exact/polynomial_text.h"
#include "core/curves/bezier/power_basis.h"

#include <QtTest>
#include "tests/test_main.h"

using namespace granota;
using RPoly = Polynomial<Rational>;

class TestBernsteinProperties : public QObject {
    Q_OBJECT
private slots:
    void closedFormMatchesRecursion()
    {
        for (int n : {0, 1, 5, 17, 30})
            for (double t : {0.0, 0.2, 0.5, 0.9, 1.0}) {
                const auto b = bernsteinAll(n, t);
                for (int i = 0; i <= n; ++i)
                    QVERIFY(std::fabs(bernsteinClosedForm(i, n, t) - b[static_cast<std::size_t>(i)]) < 1e-14);
            }
        QCOMPARE(bernsteinClosedForm(-1, 3, 0.5), 0.0);
        QCOMPARE(bernsteinClosedForm(4, 3, 0.5), 0.0);
        // Def 2.5 at a known value: B_1^3(1/2) = 3/8.
        QCOMPARE(bernsteinClosedForm(1, 3, 0.5), 0.375);
    }

    // Tolerance 1e-12 for n ≤ 30 (the tab's range), 1e-10 up to the degree limit 60.
    void checksHold_data()
    {
        QTest::addColumn<int>("n");
        QTest::addColumn<double>("t");
        QTest::addColumn<double>("tolerance");
        for (int n : {0, 1, 2, 5, 12, 30})
            for (double t : {0.0, 0.125, 1.0 / 3.0, 0.5, 0.77, 1.0})
                QTest::newRow(qPrintable(QString("n=%1 t=%2").arg(n).arg(t))) << n << t << 1e-12;
        QTest::newRow("n=60 t=0.3") << 60 << 0.3 << 1e-10;
    }
    void checksHold()
    {
        QFETCH(int, n);
        QFETCH(double, t);
        QFETCH(double, tolerance);
        const BernsteinChecks c = checkBernsteinProperties(n, t);
        QVERIFY(c.partitionOfUnity.exact);
        QVERIFY(c.symmetry.exact);
        QVERIFY(c.recursion.exact);
        QVERIFY2(c.partitionOfUnity.residual < tolerance, qPrintable(QString::number(c.partitionOfUnity.residual)));
        QVERIFY2(c.symmetry.residual < tolerance, qPrintable(QString::number(c.symmetry.residual)));
        QVERIFY2(c.recursion.residual < tolerance, qPrintable(QString::number(c.recursion.residual)));
        QCOMPARE(c.recursion.applies, n >= 1);
    }

    // The residual measures something: outside [0,1] the closed form is still a polynomial
    // and still sums to 1, but at t = 40 the cancellation is visible.
    void residualIsNotAlwaysZero()
    {
        const BernsteinChecks c = checkBernsteinProperties(30, 40.0);
        QVERIFY(c.partitionOfUnity.residual > 1e-6);
        QVERIFY(c.partitionOfUnity.exact); // the identity itself holds for every t
    }

    // The conditioning of the power basis against its definition: the matrix of
    // bezierToPowerBasis applied to unit control points, and its inverse, by brute force.
    void powerBasisConditionMatchesMatrix_data()
    {
        QTest::addColumn<int>("n");
        for (int n : {0, 1, 2, 4, 7, 10})
            QTest::newRow(qPrintable(QString::number(n))) << n;
    }
    void powerBasisConditionMatchesMatrix()
    {
        QFETCH(int, n);
        double normM = 0.0;
        std::vector<double> rowSums(static_cast<std::size_t>(n + 1), 0.0);
        for (int i = 0; i <= n; ++i) {
            std::vector<RPoint> unit(static_cast<std::size_t>(n + 1), RPoint(Rational(0), Rational(0)));
            unit[static_cast<std::size_t>(i)].x = 1;
            const auto column = bezierToPowerBasis(unit).x; // column i of M
            for (int k = 0; k <= n; ++k)
                rowSums[static_cast<std::size_t>(k)] += std::fabs(column.coefficient(k).get_d());
        }
        for (double s : rowSums)
            normM = std::max(normM, s);
        // M⁻¹ writes t^k in the Bernstein basis: t^k = Σ_i C(i,k)/C(n,k) B_i^n.
        double normInverse = 0.0;
        for (int i = 0; i <= n; ++i) {
            double s = 0.0;
            for (int k = 0; k <= i; ++k)
                s += Rational(binomial(i, k) / binomial(n, k)).get_d();
            normInverse = std::max(normInverse, s);
        }
        QCOMPARE(powerBasisCondition(n), normM * normInverse);
        if (n == 4)
            QCOMPARE(powerBasisCondition(4), 160.0);
    }

    // Ex 2.5: the five terms as the thesis prints them, and their sum.
    void example25Terms()
    {
        const std::vector<RPoint> p = {{Rational(2), Rational(3)},
                                       {Rational(-1), Rational(8)},
                                       {Rational(-5), Rational(-3)},
                                       {Rational(3), Rational(0)},
                                       {Rational(-7), Rational(-2)}};
        const auto terms = bernsteinTerms(p);
        QCOMPARE(terms.size(), std::size_t(5));
        QCOMPARE(QString::fromStdString(toText(terms[0])),
                 QString("(2 - 8t + 12t^2 - 8t^3 + 2t^4, 3 - 12t + 18t^2 - 12t^3 + 3t^4)"));
        QCOMPARE(QString::fromStdString(toText(terms[1])), QString("(-4t + 12t^2 - 12t^3 + 4t^4, 32t - 96t^2 + 96t^3 - 32t^4)"));
        QCOMPARE(QString::fromStdString(toText(terms[2])), QString("(-30t^2 + 60t^3 - 30t^4, -18t^2 + 36t^3 - 18t^4)"));
        QCOMPARE(QString::fromStdString(toText(terms[3])), QString("(12t^3 - 12t^4, 0)"));
        QCOMPARE(QString::fromStdString(toText(terms[4])), QString("(-7t^4, -2t^4)"));
        QCOMPARE(QString::fromStdString(toText(bernsteinSum(p))),
                 QString("(2 - 12t - 6t^2 + 52t^3 - 43t^4, 3 + 20t - 96t^2 + 120t^3 - 49t^4)"));
    }

    // Ex 2.6, and Def 2.6 agrees with the power basis of De Casteljau's curve.
    void example26Sum()
    {
        const std::vector<RPoint> p = {{Rational(1), Rational(7)},
                                       {Rational(0), Rational(-3)},
                                       {Rational(-4), Rational(-2)},
                                       {Rational(8), Rational(0)},
                                       {Rational(1), Rational(7)}};
        QCOMPARE(QString::fromStdString(toText(bernsteinTerms(p)[1])), QString("(0, -12t + 36t^2 - 36t^3 + 12t^4)"));
        QCOMPARE(QString::fromStdString(toText(bernsteinSum(p))),
                 QString("(1 - 4t - 18t^2 + 76t^3 - 54t^4, 7 - 40t + 66t^2 - 40t^3 + 14t^4)"));
        QVERIFY(bernsteinSum(p) == bezierToPowerBasis(p));
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestBernsteinProperties)
#include "test_bernstein_properties.moc"
