// granota-cli bezier --weights (issue 36): the rational Bézier curve with the keys of
// `bezier`, exact under --exact, and exit 2 with one "error:" line for weights that are not
// positive, the wrong number of them, and t outside [0, 1].
#include "cli_runner.h"

#include <QtTest>
#include "tests/test_main.h"

#include <QJsonArray>
#include <QJsonObject>

#include <cmath>

namespace {

QStringList strings(const QJsonValue& v)
{
    QStringList out;
    for (const QJsonValue& x : v.toArray())
        out << x.toString();
    return out;
}

const char* const kQuarter = "1,0;1,1;0,1";

} // namespace

class TestCliBezierWeights : public QObject {
    Q_OBJECT
private slots:
    // Weights (1, 1, 2) on (1,0), (1,1), (0,1): c(t) = (1 − t², 2t)/(1 + t²) (the numerators
    // and denominator of the Bernstein sums, expanded by hand: (1−t)² + 2t(1−t) = 1 − t²,
    // 2t(1−t) + 2t² = 2t, (1−t)² + 2t(1−t) + 2t² = 1 + t²). At t = 1/2: (3/5, 4/5); level 1 by
    // hand: w_0^1 = 1, P_0^1 = (1, 1/2); w_1^1 = 3/2, P_1^1 = ((1·1 + 2·0)/3, (1 + 2)/3) = (1/3, 1);
    // c′ = (−4t, 2(1 − t²))/(1 + t²)² = (−32/25, 24/25).
    void quarterCircleExact()
    {
        const CliRun r = runCli({"bezier", "--points", kQuarter, "--weights", "1,1,2", "--t", "1/2", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = r.json();
        QCOMPARE(o["degree"].toInt(), 2);
        QCOMPARE(strings(o["point"]), QStringList({"3/5", "4/5"}));
        QCOMPARE(strings(o["tangent"]), QStringList({"-32/25", "24/25"}));
        const QJsonArray levels = o["levels"].toArray();
        QCOMPARE(levels.size(), 3);
        QCOMPARE(strings(levels[1].toArray()[0]), QStringList({"1", "1/2"}));
        QCOMPARE(strings(levels[1].toArray()[1]), QStringList({"1/3", "1"}));
        QCOMPARE(strings(levels[2].toArray()[0]), QStringList({"3/5", "4/5"}));
        const QJsonArray weightLevels = o["weight_levels"].toArray();
        QCOMPARE(strings(weightLevels[1]), QStringList({"1", "3/2"}));
        QCOMPARE(strings(weightLevels[2]), QStringList({"5/4"}));
        QCOMPARE(strings(o["weights"]), QStringList({"1", "1", "2"}));
        const QJsonObject poly = o["poly"].toObject();
        QCOMPARE(strings(poly["x"]), QStringList({"1", "0", "-1"}));
        QCOMPARE(strings(poly["y"]), QStringList({"0", "2", "0"}));
        QCOMPARE(strings(poly["w"]), QStringList({"1", "0", "1"}));
    }

    // Without --exact the same numbers as doubles; weights all 1 give `bezier`'s own point.
    void doublesAgree()
    {
        const CliRun r = runCli({"bezier", "--points", kQuarter, "--weights", "1,1,2", "--t", "0.5", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray p = r.json()["point"].toArray();
        QVERIFY(std::abs(p[0].toDouble() - 0.6) <= 1e-15 && std::abs(p[1].toDouble() - 0.8) <= 1e-15);
        const char* const ex22 = "2,3;-1,8;-5,-3;3,0;-7,-2";
        const CliRun ones = runCli({"bezier", "--points", ex22, "--weights", "1,1,1,1,1", "--t", "1/2", "--exact", "--json"});
        const CliRun plain = runCli({"bezier", "--points", ex22, "--t", "1/2", "--exact", "--json"});
        QCOMPARE(ones.exitCode, 0);
        // Ex 2.2 at 1/2: (−27/16, 15/16) (test_cli's bezierEx22Exact derives it).
        QCOMPARE(strings(ones.json()["point"]), QStringList({"-27/16", "15/16"}));
        QCOMPARE(ones.json()["levels"], plain.json()["levels"]);
        QCOMPARE(ones.json()["tangent"], plain.json()["tangent"]);
        // The standard-form quarter circle with w = √2/2 (decimals): |c(t)| = 1 to rounding.
        const CliRun q = runCli({"bezier", "--points", kQuarter, "--weights", "1,0.7071067811865476,1", "--t", "0.3", "--json"});
        QCOMPARE(q.exitCode, 0);
        const QJsonArray c = q.json()["point"].toArray();
        QVERIFY(std::abs(std::hypot(c[0].toDouble(), c[1].toDouble()) - 1) <= 1e-15);
    }

    void badInput_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("zero weight") << QStringList{"bezier", "--points", kQuarter, "--weights", "1,0,1", "--t", "0.5"};
        QTest::newRow("negative weight") << QStringList{"bezier", "--points", kQuarter, "--weights", "1,-1/2,1", "--t", "0.5"};
        QTest::newRow("too few weights") << QStringList{"bezier", "--points", kQuarter, "--weights", "1,1", "--t", "0.5"};
        QTest::newRow("too many weights") << QStringList{"bezier", "--points", kQuarter, "--weights", "1,1,1,1", "--t", "0.5"};
        QTest::newRow("not a number") << QStringList{"bezier", "--points", kQuarter, "--weights", "1,w,1", "--t", "0.5"};
        QTest::newRow("empty entry") << QStringList{"bezier", "--points", kQuarter, "--weights", "1,,1", "--t", "0.5"};
        QTest::newRow("NaN weight") << QStringList{"bezier", "--points", kQuarter, "--weights", "1,nan,1", "--t", "0.5"};
        QTest::newRow("t above 1") << QStringList{"bezier", "--points", kQuarter, "--weights", "1,1,2", "--t", "3/2"};
        QTest::newRow("t below 0") << QStringList{"bezier", "--points", kQuarter, "--weights", "1,1,2", "--t", "-1"};
        QTest::newRow("with reduce") << QStringList{"bezier", "--points", kQuarter, "--weights", "1,1,2", "--reduce"};
        QTest::newRow("weight beyond doubles")
            << QStringList{"bezier", "--points", kQuarter, "--weights", "1,1e400,1", "--t", "0.5"};
    }
    void badInput()
    {
        QFETCH(QStringList, args);
        const CliRun r = runCli(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.out.isEmpty());
        QVERIFY2(r.err.startsWith("error: ") && r.err.count('\n') == 1, r.err.constData());
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestCliBezierWeights)
#include "test_cli_bezier_weights.moc"
