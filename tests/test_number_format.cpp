// The numbers Granota writes (core/base/number_format.h): formatDouble is the shortest text
// that reads back as the same double, checked against the plain search it replaced (every
// precision from 1 up, the first that reads back); formatReadable, for the window's CSV
// files, drops a computed value's binary noise and keeps a typed value as typed (issue 34,
// item 8).
#include "core/base/number_format.h"

#include <QTest>
#include "tests/test_main.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>

using namespace granota;

namespace {

/// The reference: printf's "%.*g" at each precision from 1 up, the first that reads back.
std::string searchedShortest(double v)
{
    if (v == 0)
        return "0";
    if (std::fabs(v) < 1e16 && v == std::trunc(v))
        return formatFixed(v, 0);
    char buf[64];
    for (int p = 1; p <= 17; ++p) {
        std::snprintf(buf, sizeof buf, "%.*g", p, v);
        if (std::strtod(buf, nullptr) == v)
            break;
    }
    return buf;
}

} // namespace

class TestNumberFormat : public QObject {
    Q_OBJECT
private slots:
    void shortestIsTheSearchedShortest()
    {
        std::mt19937_64 rng(34);
        std::uniform_real_distribution<double> mantissa(-10, 10);
        std::uniform_int_distribution<int> exponent(-30, 30);
        for (int i = 0; i < 20000; ++i) {
            const double v = std::ldexp(mantissa(rng), exponent(rng));
            QCOMPARE(formatDouble(v), searchedShortest(v));
        }
        for (double v : {0.1, 1.0 / 3, 1e-9, 123456.789, 5e-324, std::numeric_limits<double>::max(), -2.5})
            QCOMPARE(formatDouble(v), searchedShortest(v));
    }

    void readableDropsBinaryNoise_data()
    {
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("text");
        // Each value is a computation whose exact answer has few digits; the double carries an
        // error in the 16th or 17th digit that formatDouble shows.
        QTest::newRow("0.1 + 0.2") << 0.1 + 0.2 << QStringLiteral("0.3");
        QTest::newRow("2.072") << 2.0719999999999996 << QStringLiteral("2.072");
        QTest::newRow("0.648") << 0.6480000000000005 << QStringLiteral("0.648");
        QTest::newRow("11/70 from the fit") << 0.15714285714285747 << QStringLiteral("0.157142857142857");
        QTest::newRow("-0") << -0.0 << QStringLiteral("0");
        QTest::newRow("whole") << 640.0 << QStringLiteral("640");
        QTest::newRow("small") << 1e-9 << QStringLiteral("1e-09");
    }
    void readableDropsBinaryNoise()
    {
        QFETCH(double, value);
        QFETCH(QString, text);
        QCOMPARE(QString::fromStdString(formatReadable(value)), text);
    }

    // A value typed with up to 15 significant digits comes back as typed.
    void readableKeepsTypedValues()
    {
        std::mt19937_64 rng(8);
        std::uniform_int_distribution<long long> digits(1, 999999999999999LL);
        std::uniform_int_distribution<int> exponent(-20, 5);
        for (int i = 0; i < 20000; ++i) {
            char typed[64];
            std::snprintf(typed, sizeof typed, "%llde%d", digits(rng), exponent(rng));
            const double v = std::strtod(typed, nullptr);
            QCOMPARE(std::strtod(formatReadable(v).c_str(), nullptr), v);
            QCOMPARE(formatReadable(v), formatDouble(v));
        }
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestNumberFormat)
#include "test_number_format.moc"
