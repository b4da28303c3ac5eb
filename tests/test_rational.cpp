// Exact rationals: parsing and printing, the ground every exact example stands on.
#include "core/exact/polynomial.h"
#include "core/exact/polynomial_text.h"
#include "core/exact/rational.h"
#include "core/exact/exact_point.h"
#include "core/exact/number_column.h"
#include "core/exact/rational_approximation.h"
#include "core/exact/round_step.h"

#include <QtTest>
#include "tests/test_main.h"

#include <limits>

using namespace granota;

class TestRational : public QObject {
    Q_OBJECT
private slots:
    void parse_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("exact");
        QTest::newRow("integer") << "-3"
                                 << "-3";
        QTest::newRow("fraction") << "7/2"
                                  << "7/2";
        QTest::newRow("reduces") << "-6/4"
                                 << "-3/2";
        QTest::newRow("decimal is its own rational") << "0.1"
                                                     << "1/10";
        QTest::newRow("exponent") << "1.5e-3"
                                  << "3/2000";
        QTest::newRow("big exponent") << "1e9"
                                      << "1000000000";
        QTest::newRow("spaces") << "  5/10 "
                                << "1/2";
        QTest::newRow("leading dot") << ".25"
                                     << "1/4";
    }
    void parse()
    {
        QFETCH(QString, text);
        QFETCH(QString, exact);
        auto q = parseRational(text.toStdString());
        QVERIFY(q.has_value());
        QCOMPARE(QString::fromStdString(toString(*q)), exact);
    }
    void rejects_data()
    {
        QTest::addColumn<QString>("text");
        for (const char* bad :
             {"", "nan", "inf", "-inf", "1/0", "abc", "1..2", "1e", "1/2/3", "--1", "1e99999999", "0x10", "1,5"})
            QTest::newRow(bad) << QString::fromLatin1(bad);
    }
    void rejects()
    {
        QFETCH(QString, text);
        QVERIFY(!parseRational(text.toStdString()).has_value());
    }
    // A number written right whose exponent is beyond reach is called too large (or too
    // close to zero), not "not a finite number"; anything else has no such reason.
    void numbersBeyondReach_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("reason");
        const QString large = QStringLiteral("is too large (the largest double is about 1.8e308)");
        const QString small = QStringLiteral("is too close to zero to read (exponents go down to -10000)");
        QTest::newRow("1e1000000") << "1e1000000" << large;
        QTest::newRow("-2.5E+10001") << "-2.5E+10001" << large;
        QTest::newRow(" .5e99999999 ") << " .5e99999999 " << large;
        QTest::newRow("1e-1000000") << "1e-1000000" << small;
        QTest::newRow("0e1000000") << "0e1000000" << QString(); // zero: not "too large"
        QTest::newRow("1e10000, read") << "1e10000" << QString();
        QTest::newRow("1e400, read") << "1e400" << QString();
        QTest::newRow("abc") << "abc" << QString();
        QTest::newRow("1e") << "1e" << QString();
        QTest::newRow("1/0") << "1/0" << QString();
        QTest::newRow("e1000000") << "e1000000" << QString();
        QTest::newRow("1x1e1000000") << "1x1e1000000" << QString();
    }
    void numbersBeyondReach()
    {
        QFETCH(QString, text);
        QFETCH(QString, reason);
        const auto why = numberBeyondReach(text.toStdString());
        QCOMPARE(why ? QString::fromStdString(*why) : QString(), reason);
    }
    void exactSqrtOnlyOfSquares()
    {
        QCOMPARE(QString::fromStdString(toString(*exactSqrt(Rational(9, 4)))), QString("3/2"));
        QVERIFY(!exactSqrt(Rational(2)).has_value());
        QVERIFY(!exactSqrt(Rational(-4)).has_value());
    }
    void doublesAreExact()
    {
        QCOMPARE(QString::fromStdString(toString(exactRational(0.375))), QString("3/8"));
        QCOMPARE(exactRational(0.1).get_d(), 0.1);
        QVERIFY(exactRational(0.1) != Rational(1, 10)); // 0.1 is not representable
    }
    void toDoubleIsTheNearestDouble_data()
    {
        // What each text denotes, rounded to nearest as the C++ literal (and strtod) is.
        QTest::addColumn<QString>("text");
        QTest::addColumn<double>("nearest");
        QTest::newRow("0.1 (get_d() truncates it to 0.09999999999999999)") << "0.1" << 0.1;
        QTest::newRow("-0.1") << "-0.1" << -0.1;
        QTest::newRow("0.3") << "0.3" << 0.3;
        QTest::newRow("0.95") << "0.95" << 0.95;
        QTest::newRow("1/3") << "1/3" << 1.0 / 3;
        QTest::newRow("2/3") << "2/3" << 2.0 / 3;
        QTest::newRow("shortest of 1/10 minus an ulp") << "0.09999999999999999" << 0.09999999999999999;
        QTest::newRow("a tie goes to even") << "9007199254740993" << 9007199254740992.0;
        QTest::newRow("the other tie") << "9007199254740995" << 9007199254740996.0;
        QTest::newRow("below the smallest subnormal's half") << "1e-330" << 0.0;
        QTest::newRow("the smallest subnormal") << "4e-324" << 4.9406564584124654e-324;
        QTest::newRow("the largest double") << "1.7976931348623157e308" << 1.7976931348623157e308;
        QTest::newRow("just below halfway to 2^1024") << "1.797693134862315807e308" << 1.7976931348623157e308;
        QTest::newRow("past the largest double") << "1.8e308" << HUGE_VAL;
        QTest::newRow("far past it") << "-1e400" << -HUGE_VAL;
    }
    void toDoubleIsTheNearestDouble()
    {
        // Found by the rational fuzz target (tests/fuzz/regressions/rational): typing 0.1
        // gave 0.09999999999999999, written so by the exports and each retyping smaller.
        QFETCH(QString, text);
        QFETCH(double, nearest);
        const auto q = parseRational(text.toStdString());
        QVERIFY(q);
        const double d = toDouble(*q);
        // Exactly (QCOMPARE on doubles is fuzzy: it takes 0.09999999999999999 for 0.1).
        QVERIFY2(d == nearest, qPrintable(QStringLiteral("%1 instead of %2").arg(d, 0, 'g', 17).arg(nearest, 0, 'g', 17)));
        QCOMPARE(std::signbit(d), std::signbit(nearest));
    }
    void retypingADoubleGivesItBack()
    {
        for (double d : {0.1, 0.3, 1.0 / 3, 0.0015, 5e-324, 1.7976931348623157e308, -2.5e-7})
            QVERIFY2(toDouble(*parseRational(formatDouble(d))) == d, formatDouble(d).c_str());
        QVERIFY(toDouble(*parseRational("-1e-400")) == 0.0);
        QVERIFY(std::signbit(toDouble(*parseRational("-1e-400")))); // −0, as strtod reads it
    }
    void smallFractions()
    {
        QCOMPARE(toString(*smallRational(0.1)), std::string("1/10")); // its nearest double is 0.1
        QCOMPARE(toString(*smallRational(-1.0 / 3)), std::string("-1/3"));
        QVERIFY(!smallRational(0.1 + 1e-9).has_value());
        // Found with the document fuzz target's harness: a point at 1e-320 crashed the
        // point table (1/d overflowed to infinity, and GMP aborts on mpz_class(inf)).
        QVERIFY(!smallRational(1e-320).has_value());
        QVERIFY(!smallRational(-4.9406564584124654e-324).has_value());
        QCOMPARE(toString(*smallRational(0.0)), std::string("0"));
    }
    void smallFractionsOfDoubles_data()
    {
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("fraction"); // empty: none
        QTest::newRow("third") << 1.0 / 3 << "1/3";
        QTest::newRow("negative") << -2.5 << "-5/2";
        QTest::newRow("integer") << 7.0 << "7";
        QTest::newRow("zero") << 0.0 << "0";
        QTest::newRow("no small denominator") << 0.1234567891 << "";
        QTest::newRow("too large") << 1e300 << "";
        QTest::newRow("tiny normal") << 1e-300 << "";
        // Found by the input storm (1e-320 typed into a point table): the reciprocal of a
        // subnormal overflows, and GMP stopped the program with SIGFPE on floor(inf).
        QTest::newRow("subnormal") << 1e-320 << "";
        QTest::newRow("negative subnormal") << -4.9e-324 << "";
        QTest::newRow("infinity") << std::numeric_limits<double>::infinity() << "";
        QTest::newRow("nan") << std::numeric_limits<double>::quiet_NaN() << "";
    }
    void smallFractionsOfDoubles()
    {
        QFETCH(double, value);
        QFETCH(QString, fraction);
        const auto q = smallRational(value, 1000);
        QCOMPARE(q ? QString::fromStdString(toString(*q)) : QString(), fraction);
        QVERIFY(!q || q->get_d() == value);
    }
    void polynomialText()
    {
        const Polynomial<Rational> p{Rational(2), Rational(-6), Rational(-1)};
        QCOMPARE(QString::fromStdString(toText(p)), QString("2 - 6t - t^2"));
        const Polynomial<Rational> q{Rational(0), Rational(-1, 2), Rational(1), Rational(-1, 2)};
        QCOMPARE(QString::fromStdString(toText(q, "s")), QString("-1/2 s + s^2 - 1/2 s^3"));
        QCOMPARE(QString::fromStdString(toText(Polynomial<Rational>())), QString("0"));
    }
    void polynomialAlgebra()
    {
        using P = Polynomial<Rational>;
        const P t = P::identity();
        const P one(1);
        const P p = (one - t) * (one - t); // B_0^2
        QCOMPARE(p, (P{Rational(1), Rational(-2), Rational(1)}));
        QCOMPARE(p.derivative(), (P{Rational(-2), Rational(2)}));
        QCOMPARE(p(Rational(1, 4)), Rational(9, 16));
        // p(t + 1) = t^2
        QCOMPARE(p.shifted(Rational(1)), (P{Rational(0), Rational(0), Rational(1)}));
        QCOMPARE((p - p).degree(), -1);
    }
    // Round steps (round_step.h): 1, 2 or 5 × 10^k, exactly, on both sides of a power of ten.
    void roundSteps()
    {
        const auto text = [](RoundStep s) { return QString::fromStdString(toString(s.exact())); };
        QCOMPARE(text(roundStepAtMost(0.1)), QStringLiteral("1/10"));
        QCOMPARE(text(roundStepAtMost(0.09999)), QStringLiteral("1/20"));
        QCOMPARE(text(roundStepAtMost(0.3)), QStringLiteral("1/5"));
        QCOMPARE(text(roundStepAtMost(7)), QStringLiteral("5"));
        QCOMPARE(text(roundStepAtMost(1000)), QStringLiteral("1000"));
        QCOMPARE(text(roundStepAtLeast(0.1)), QStringLiteral("1/10"));
        QCOMPARE(text(roundStepAtLeast(0.10001)), QStringLiteral("1/5"));
        QCOMPARE(text(roundStepAtLeast(1.5)), QStringLiteral("2"));
        QCOMPARE(text(roundStepAtMost(4e-9)), QStringLiteral("1/500000000"));
        QCOMPARE(roundStepAtMost(0.1).timesTen().value(), 1.0);
        for (double bad : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()})
            QCOMPARE(text(roundStepAtMost(bad)), QStringLiteral("1"));
        // Next multiples, either way, exactly; a value on the grid moves one step.
        const Rational tenth = frac(1, 10);
        QCOMPARE(toString(nextMultiple(frac(-9, 5), tenth, 1)), std::string("-17/10"));
        QCOMPARE(toString(nextMultiple(frac(-9, 5), tenth, -1)), std::string("-19/10"));
        QCOMPARE(toString(nextMultiple(frac(1, 3), tenth, 1)), std::string("2/5"));
        QCOMPARE(toString(nextMultiple(frac(1, 3), tenth, -1)), std::string("3/10"));
        QCOMPARE(toString(nextMultiple(exactRational(-6.937088388214905), tenth, 1)), std::string("-69/10"));
        QCOMPARE(toString(nearestMultiple(frac(1, 3), frac(1, 2))), std::string("1/2"));
        QCOMPARE(toString(nearestMultiple(frac(-1, 4), frac(1, 2))), std::string("0"));
        QCOMPARE(toString(meantRational(0.1)), std::string("1/10"));
        QCOMPARE(meantRational(0.1 + 0.2) == exactRational(0.1 + 0.2), true);
    }

    // One notation per column (number_column.h).
    void columnNotations()
    {
        using V = std::vector<double>;
        QCOMPARE(columnNotation(V{0, 2.5, 0.05688}), ColumnNotation::Decimals);
        QCOMPARE(columnNotation(V{0, -1.8, 1.0 / 3}), ColumnNotation::Fractions);
        QCOMPARE(columnNotation(V{-1.8, 1.0 / 3, 1.0000000000000007}), ColumnNotation::Decimals);
        QCOMPARE(columnNotation(V{1.0 / 1024}), ColumnNotation::Decimals);
        QCOMPARE(columnNotation(V{}), ColumnNotation::Decimals);
        QCOMPARE(columnEntry(-1.8, ColumnNotation::Fractions), std::string("-9/5"));
        QCOMPARE(columnEntry(-1.8, ColumnNotation::Decimals), std::string("-1.8"));
        QCOMPARE(columnEntry(0.05688, ColumnNotation::Decimals), std::string("0.05688"));
        QCOMPARE(columnEntry(-0.0, ColumnNotation::Decimals), std::string("0"));
        QCOMPARE(columnEntry(1.0 / 3, ColumnNotation::Decimals), std::string("0.3333333333333333"));
    }

    // Exact values beside their doubles (exact_point.h): written from the rational, never from
    // the double's binary digits. Expected texts by long division by hand (and Python's decimal).
    void exactValuesAreWrittenExactly()
    {
        QCOMPARE(terminatingDecimal(frac(11, 100), 17), std::optional<std::string>("0.11"));
        QCOMPARE(terminatingDecimal(frac(-259, 125), 17), std::optional<std::string>("-2.072"));
        QCOMPARE(terminatingDecimal(frac(7, 1), 17), std::optional<std::string>("7"));
        QCOMPARE(terminatingDecimal(Rational(0), 17), std::optional<std::string>("0"));
        QCOMPARE(terminatingDecimal(frac(1, 1024), 17), std::optional<std::string>("0.0009765625"));
        QVERIFY(!terminatingDecimal(frac(1, 3), 17));
        QVERIFY(!terminatingDecimal(exactRational(0.1), 17)); // 55 significant digits
        QCOMPARE(roundedDecimal(frac(1, 3), 16), std::string("0.3333333333333333"));
        QCOMPARE(roundedDecimal(frac(-2, 3), 16), std::string("-0.6666666666666667"));
        QCOMPARE(roundedDecimal(frac(54, 6125), 16), std::string("0.008816326530612245")); // the double: …244
        QCOMPARE(roundedDecimal(frac(99999999, 10), 3), std::string("10000000"));          // rounds up a digit
        QCOMPARE(roundedDecimal(frac(125, 10), 16), std::string("12.5"));
        // 0.1 nudged five times by 0.01 in doubles is 0.15000000000000002; kept exact it is 3/20.
        const double sum = 0.1 + 0.01 + 0.01 + 0.01 + 0.01 + 0.01;
        QVERIFY(sum != 0.15);
        QCOMPARE(readableExact(frac(3, 20), 0.15), std::string("0.15"));
        QCOMPARE(readableExact(std::nullopt, 0.1 + 0.2), std::string("0.3"));
        QCOMPARE(readableExact(frac(1, 3), 1.0 / 3), std::string("0.333333333333333"));
        QCOMPARE(readableExact(std::nullopt, 0.1 + 0.2), std::string("0.3"));
        using C = std::vector<ExactCoordinate>;
        QCOMPARE(columnNotation(C{frac(1, 3), Rational(2)}), ColumnNotation::Fractions);
        QCOMPARE(columnNotation(C{frac(1, 3), std::nullopt}), ColumnNotation::Decimals);
        QCOMPARE(columnNotation(C{frac(1, 3), frac(1, 1225)}), ColumnNotation::Decimals);
        QCOMPARE(columnEntry(frac(6206, 6125), 6206.0 / 6125, ColumnNotation::Decimals), std::string("1.013224489795918"));
        QCOMPARE(columnEntry(std::nullopt, 1.0000000000000007, ColumnNotation::Decimals), std::string("1.0000000000000007"));
        QCOMPARE(columnEntry(frac(1, 3), 1.0 / 3, ColumnNotation::Fractions), std::string("1/3"));
        // A point given as doubles keeps the small fractions they were written as, else none.
        const ExactPoint written = writtenExact(Point(1.0 / 3, 2.7182818284590451));
        QCOMPARE(written.x, ExactCoordinate(frac(1, 3)));
        QVERIFY(!written.y);
        QVERIFY(!allExact({written}, 1));
        QVERIFY(allExact({ExactPoint{frac(1, 3), Rational(2)}}, 1));
        QVERIFY(!allExact({}, 1));
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestRational)
#include "test_rational.moc"
