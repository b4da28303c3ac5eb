// Sums of square roots and their quotients (core/exact/radical_sum.h): the chord-length
// parameters of Ex 2.9 and Ex 2.10 in radicals, against the ones the thesis prints.
#include "core/curves/fitting/parametrization.h"
#include "core/exact/radical_sum.h"
#include "core/io/worked_examples.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>

using namespace granota;

namespace {

RadicalSum root(long coefficient, long radicand)
{
    return RadicalSum(SimplifiedSquareRoot{Rational(coefficient), mpz_class(radicand)});
}

std::vector<RPoint> ex29Points() { return findWorkedExample("2.9")->points; }

} // namespace

class TestRadicalSum : public QObject {
    Q_OBJECT
private slots:
    void arithmetic()
    {
        // (√2 + √3)(√2 − √3) = 2 − 3 = −1; √6·√10 = √60 = 2√15; √5 + 2√5 − 3√5 = 0.
        const RadicalSum product = (root(1, 2) + root(1, 3)) * (root(1, 2) - root(1, 3));
        QCOMPARE(product.rational().value_or(Rational(99)), Rational(-1));
        QVERIFY(root(1, 6) * root(1, 10) == root(2, 15));
        QVERIFY((root(1, 5) + root(2, 5) - root(3, 5)).isZero());
    }

    void writes_data()
    {
        QTest::addColumn<int>("which");
        QTest::addColumn<QString>("text");
        QTest::newRow("zero") << 0 << "0";
        QTest::newRow("one root") << 1 << "7√2";
        QTest::newRow("over a denominator") << 2 << "√10/2";
        QTest::newRow("negative") << 3 << "−√5";
        QTest::newRow("radicals first, rational last") << 4 << "(11√5 − 10)/101";
        QTest::newRow("integers") << 5 << "3√2 + 1";
    }
    void writes()
    {
        QFETCH(int, which);
        QFETCH(QString, text);
        const RadicalSum sums[] = {RadicalSum(),
                                   root(7, 2),
                                   RadicalSum(SimplifiedSquareRoot{Rational(1, 2), mpz_class(10)}),
                                   root(-1, 5),
                                   RadicalSum(SimplifiedSquareRoot{Rational(11, 101), mpz_class(5)}) +
                                       RadicalSum(Rational(-10, 101)),
                                   root(3, 2) + RadicalSum(Rational(1))};
        QCOMPARE(QString::fromStdString(toString(sums[which])), text);
    }

    // Ex 2.9/2.10 with the data's d_4 = 7√2: d_T = 2√10 + 11√2 and, by hand,
    // t_1 = √10/(√2(2√5 + 11)) = √5(11 − 2√5)/(121 − 20) = (11√5 − 10)/101, t_2 = 2t_1,
    // t_3 = (2√10 + 4√2)/d_T = (2√5 + 4)(11 − 2√5)/101 = (14√5 + 24)/101 (sympy's radsimp
    // agrees: docs/thesis-errata-checks.py).
    void ex29ParametersInRadicals()
    {
        const auto t = radicalParameters(ex29Points(), Parametrization::ChordLength);
        QVERIFY(t.has_value());
        QStringList texts;
        for (const RadicalQuotient& q : *t) {
            QVERIFY(q.rationalised());
            texts << QString::fromStdString(toString(q));
        }
        QCOMPARE(texts, (QStringList{"0", "(11√5 − 10)/101", "(22√5 − 20)/101", "(14√5 + 24)/101", "1"}));
        // The decimals against the double parameters the fit uses (parametrization.cpp sums
        // the distances in doubles): the same to rounding.
        std::vector<Point> q;
        for (const RPoint& p : ex29Points())
            q.emplace_back(p.x.get_d(), p.y.get_d());
        const std::vector<double> doubles = parameters(q, Parametrization::ChordLength);
        for (std::size_t i = 0; i < doubles.size(); ++i)
            QVERIFY2(std::abs((*t)[i].toDouble() - doubles[i]) < 1e-15, qPrintable(QString::number(i)));
        QVERIFY(std::abs((*t)[1].toDouble() - 0.144522254975) < 1e-12); // sympy, 12 digits
    }

    // The thesis's printed t_i (chapter2.json, "t_as_printed") are its quotients with
    // d_4 = √85 rationalised: our division of √10 by 2√10 + 4√2 + √85 (three coprime
    // factors 2, 5, 17) gives exactly its t_1, and its value is √10/(2√10 + 4√2 + √85) in
    // doubles; printed − right = 0.004635073328 (sympy).
    void printedParametersAreTheThesissQuotients()
    {
        const std::vector<RadicalSum>& printed = findWorkedExample("2.9")->printedParameters;
        QCOMPARE(printed.size(), std::size_t(5));
        const RadicalSum denominator = root(2, 10) + root(4, 2) + root(1, 85);
        const auto t1 = divide(root(1, 10), denominator);
        QVERIFY(t1 && t1->rationalised());
        QVERIFY(t1->numerator == printed[1]);
        const auto t3 = divide(root(2, 10) + root(4, 2), denominator);
        QVERIFY(t3 && t3->numerator == printed[3]);
        const double d = 2 * std::sqrt(10.0) + 4 * std::sqrt(2.0) + std::sqrt(85.0);
        QVERIFY(std::abs(printed[1].toDouble() - std::sqrt(10.0) / d) < 1e-15);
        QVERIFY(std::abs(printed[2].toDouble() - 2 * std::sqrt(10.0) / d) < 1e-15);
        QVERIFY(printed[0].isZero());
        QCOMPARE(printed[4].rational().value_or(Rational(0)), Rational(1));
        const auto right = radicalParameters(ex29Points(), Parametrization::ChordLength);
        QVERIFY(std::abs((printed[1] - (*right)[1].numerator).toDouble() - 0.004635073328) < 1e-12);
    }

    // Annex III's BezParamProp measures |Q_{i−1}|: t = 0, 0, 0.19913, 0.48074, 1 (the thesis's
    // Figs 2.7/2.8), the same as the double parameters.
    void annexIIIInRadicals()
    {
        const auto t = radicalParameters(ex29Points(), Parametrization::AnnexIII);
        QVERIFY(t.has_value());
        QCOMPARE(QString::fromStdString(toString((*t)[1])), QStringLiteral("0"));
        QVERIFY(std::abs((*t)[2].toDouble() - 0.199128) < 5e-7);
        QVERIFY(std::abs((*t)[3].toDouble() - 0.480738) < 5e-7);
    }

    // Distances √2, √5, √13, √17, √29, √37: six coprime radicands, beyond
    // kMaxRadicalGenerators, so the quotients stay as they are — with the right values.
    void manyRadicandsStayAQuotient()
    {
        const std::vector<RPoint> q{{0, 0}, {1, 1}, {2, 3}, {4, 6}, {5, 10}, {7, 15}, {8, 21}};
        const auto t = radicalParameters(q, Parametrization::ChordLength);
        QVERIFY(t.has_value());
        QCOMPARE(QString::fromStdString(toString((*t)[0])), QStringLiteral("0"));
        QCOMPARE(QString::fromStdString(toString((*t)[6])), QStringLiteral("1"));
        QVERIFY(!(*t)[1].rationalised());
        QCOMPARE(QString::fromStdString(toString((*t)[1])), QStringLiteral("√2/(√2 + √5 + √13 + √17 + √29 + √37)"));
        const double total = std::sqrt(2.0) + std::sqrt(5.0) + std::sqrt(13.0) + std::sqrt(17.0) + std::sqrt(29.0) +
                             std::sqrt(37.0);
        QVERIFY(std::abs((*t)[2].toDouble() - (std::sqrt(2.0) + std::sqrt(5.0)) / total) < 1e-15);
    }

    void refusals()
    {
        QVERIFY(!divide(root(1, 2), RadicalSum()).has_value());
        QVERIFY(!radicalParameters(ex29Points(), Parametrization::Uniform));
        QVERIFY(!radicalParameters(ex29Points(), Parametrization::Centripetal));             // fourth roots
        QVERIFY(!radicalParameters({{1, 1}, {1, 1}, {1, 1}}, Parametrization::ChordLength)); // all coincide
        std::vector<RPoint> many;
        for (std::size_t i = 0; i <= kMaxRadicalPoints; ++i)
            many.emplace_back(Rational(static_cast<long>(i)), Rational(static_cast<long>(i * i)));
        QVERIFY(!radicalParameters(many, Parametrization::ChordLength));
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestRadicalSum)
#include "test_radical_sum.moc"
