// Square roots in simplest radical form: the chord lengths of Ex 2.9 and Ex 2.10.
#include "core/exact/rational.h"
#include "core/exact/square_root.h"

#include <QtTest>
#include "tests/test_main.h"

using namespace granota;

class TestSquareRoot : public QObject {
    Q_OBJECT
private slots:
    void simplifies_data()
    {
        QTest::addColumn<QString>("square");
        QTest::addColumn<QString>("root");
        // Ex 2.9: d_1² = 1 + 9, d_2² = 9 + 1, d_3² = 16 + 16, d_4² = 49 + 49 (not 36 + 49).
        QTest::newRow("d1 = √10") << "10"
                                  << "√10";
        QTest::newRow("d3 = 4√2") << "32"
                                  << "4√2";
        QTest::newRow("d4 = 7√2") << "98"
                                  << "7√2";
        QTest::newRow("the thesis's √85 stays") << "85"
                                                << "√85";
        QTest::newRow("perfect square") << "49"
                                        << "7";
        QTest::newRow("rational square") << "9/4"
                                         << "3/2";
        QTest::newRow("fraction") << "3/2"
                                  << "√6/2";
        QTest::newRow("fraction with coefficient") << "50/9"
                                                   << "5√2/3";
        QTest::newRow("zero") << "0"
                              << "0";
        QTest::newRow("one") << "1"
                             << "1";
        QTest::newRow("large prime square") << "1000006000009"
                                            << "1000003"; // 1000003²
        QTest::newRow("large square-free") << "999999999989"
                                           << "√999999999989";
    }
    void simplifies()
    {
        QFETCH(QString, square);
        QFETCH(QString, root);
        const auto q = parseRational(square.toStdString());
        QVERIFY(q);
        const auto r = simplifySquareRoot(*q);
        QVERIFY(r);
        QCOMPARE(QString::fromStdString(toString(*r)), root);
        // a²·b gives back q exactly.
        QCOMPARE(Rational(r->coefficient * r->coefficient * Rational(r->radicand)), *q);
    }
    void radicandIsSquareFree()
    {
        for (long n = 1; n <= 2000; ++n) {
            const auto r = simplifySquareRoot(Rational(n));
            QVERIFY(r);
            for (long p = 2; p * p <= n; ++p)
                QVERIFY2(r->radicand % (p * p) != 0, qPrintable(QString::number(n)));
            QCOMPARE(Rational(r->coefficient * r->coefficient * Rational(r->radicand)), Rational(n));
        }
    }
    void chordLengthsOfEx29()
    {
        // Q_3 = (8, −2), Q_4 = (1, 5): d_4 = √(49 + 49) = 7√2 (the thesis's (1 − 7) gives √85).
        const std::vector<RPoint> q = {RPoint(0, 0), RPoint(1, 3), RPoint(4, 2), RPoint(8, -2), RPoint(1, 5)};
        const auto d = exactChordLengths(q);
        QCOMPARE(d.size(), std::size_t(4));
        QStringList texts;
        for (const auto& di : d) {
            QVERIFY(di);
            texts << QString::fromStdString(toString(*di));
        }
        QCOMPARE(texts, (QStringList{"√10", "√10", "4√2", "7√2"}));
        QVERIFY(exactChordLengths({RPoint(1, 1)}).empty());
        const auto zero = exactChordLengths({RPoint(1, 1), RPoint(1, 1)});
        QCOMPARE(QString::fromStdString(toString(*zero.at(0))), QStringLiteral("0"));
    }
    void refuses()
    {
        QVERIFY(!simplifySquareRoot(Rational(-2)));
        QVERIFY(!simplifySquareRoot(*parseRational("1e30"))); // too large to factor quickly
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestSquareRoot)
#include "test_square_root.moc"
