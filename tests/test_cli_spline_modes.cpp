// granota-cli spline --parametric and --monotone (issue 37). Expected values: the diamond's
// periodic spline solved by hand (tests/test_parametric_spline.cpp explains it), the clamped
// tangent times the 3-4-5 step (chord parameters: p′(s) = h·p′(u) with h = 5), and Steffen's
// slopes on the d3-shape #38 data (exact fractions by hand, test_monotone_spline.cpp).
#include "cli_runner.h"

#include <QtTest>
#include "tests/test_main.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>

#include <cmath>

namespace {

QStringList strings(const QJsonValue& v)
{
    QStringList out;
    for (const QJsonValue& x : v.toArray())
        out << x.toString();
    return out;
}

const char* kD3Issue38 = "0,224;100,200;107,180;502,300;580,120;607,148;900,400";

/// 3000 small integer points (i mod 13, i² mod 7): the closed exact spline's estimate is
/// about 1.4·10⁹ bit operations (docs/exact-cost.md: 2700 such points are already refused).
QString manyPoints()
{
    static QTemporaryDir dir;
    const QString path = dir.filePath("many.csv");
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        for (int i = 0; i < 3000; ++i)
            f.write(QByteArray::number(i % 13) + ',' + QByteArray::number((i * i) % 7) + '\n');
    return path;
}

} // namespace

class TestCliSplineModes : public QObject {
    Q_OBJECT
private slots:
    void periodicDiamondExactly()
    {
        const CliRun r = runCli(
            {"spline", "--points", "0,0;1,1;2,0;1,-1", "--parametric", "--ends", "periodic", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject j = r.json();
        QCOMPARE(j["ends"].toString(), QString("periodic"));
        QCOMPARE(j["param"].toString(), QString("uniform"));
        QCOMPARE(strings(j["knots"]), (QStringList{"0", "1", "2", "3", "4"}));
        const QJsonArray segments = j["segments"].toArray();
        QCOMPARE(segments.size(), 4); // closed: the fourth goes back to (0, 0)
        QCOMPARE(strings(segments[0].toObject()["x"]), (QStringList{"0", "0", "3/2", "-1/2"}));
        QCOMPARE(strings(segments[0].toObject()["y"]), (QStringList{"0", "3/2", "0", "-1/2"}));
        const CliRun text = runCli({"spline", "--points", "0,0;1,1;2,0;1,-1", "--parametric", "--ends", "periodic", "--exact"});
        QCOMPARE(text.exitCode, 0);
        QVERIFY2(text.out.contains("p_4(s) = ") && text.out.contains("u ∈ [3, 4]"), text.out.constData());
    }

    void clampedChordTangents()
    {
        const CliRun r = runCli({"spline", "--points", "0,0;3,4;6,0", "--parametric", "--ends", "clamped", "--start-tangent",
                                 "1,0", "--end-tangent", "0,1", "--param", "chord", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject j = r.json();
        const QJsonArray knots = j["knots"].toArray();
        QCOMPARE(knots.size(), 3);
        QCOMPARE(knots[1].toDouble(), 5.0);
        QCOMPARE(knots[2].toDouble(), 10.0);
        // p′(s) at s = 0 is h_0 · p′(u) = 5 · (1, 0).
        const QJsonObject first = j["segments"].toArray()[0].toObject();
        QCOMPARE(first["x"].toArray()[1].toDouble(), 5.0);
        QVERIFY(std::abs(first["y"].toArray()[1].toDouble()) < 1e-12);
        // At the end: c1 + 2c2 + 3c3 = 5 · (0, 1).
        const QJsonObject last = j["segments"].toArray()[1].toObject();
        const auto endSlope = [&](const char* key) {
            const QJsonArray c = last[key].toArray();
            return c[1].toDouble() + 2 * c[2].toDouble() + 3 * c[3].toDouble();
        };
        QVERIFY(std::abs(endSlope("x")) < 1e-12);
        QVERIFY(std::abs(endSlope("y") - 5.0) < 1e-12);
    }

    void monotoneSteffen()
    {
        const CliRun r = runCli({"spline", "--points", kD3Issue38, "--monotone", "steffen", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject j = r.json();
        QCOMPARE(j["monotone"].toString(), QString("steffen"));
        const QJsonArray pieces = j["pieces"].toArray();
        QCOMPARE(pieces.size(), 6);
        // Piece 1 on [0, 100]: y(0) = 224, slopes 0 and −12/25 with Δ = −6/25: 224 − 0.0024 x².
        const QJsonArray p0 = pieces[0].toObject()["poly"].toArray();
        QCOMPARE(pieces[0].toObject()["from"].toDouble(), 0.0);
        QCOMPARE(pieces[0].toObject()["to"].toDouble(), 100.0);
        QVERIFY(std::abs(p0[0].toDouble() - 224) < 1e-12 && std::abs(p0[1].toDouble()) < 1e-12);
        QVERIFY(std::abs(p0[2].toDouble() + 0.0024) < 1e-15 && std::abs(p0[3].toDouble()) < 1e-15);
        QCOMPARE(strings(j["monotonicity"]),
                 (QStringList{"decreasing", "decreasing", "increasing", "decreasing", "increasing", "increasing"}));
        const CliRun fc = runCli({"spline", "--points", kD3Issue38, "--monotone", "fritsch-carlson"});
        QCOMPARE(fc.exitCode, 0);
        QVERIFY2(fc.out.contains("proven from its Bernstein coefficients") && !fc.out.contains("not monotone"),
                 fc.out.constData());
    }

    void badInput_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("says");
        const QStringList p{"spline", "--points", "0,0;1,1;2,0"};
        QTest::newRow("periodic, 2 points") << QStringList{"spline", "--points", "0,0;1,1", "--parametric", "--ends", "periodic"}
                                            << "at least 3 points";
        QTest::newRow("repeated point, chord")
            << QStringList{"spline", "--points", "0,0;1,1;1,1", "--parametric", "--param", "chord"} << "coincide";
        QTest::newRow("closing point repeated, centripetal")
            << QStringList{"spline", "--points", "0,0;1,1;2,0;0,0", "--parametric",
                           "--ends", "periodic", "--param",         "centripetal"}
            << "coincide";
        QTest::newRow("irrational chord, exact")
            << p + QStringList{"--parametric", "--param", "chord", "--exact"} << "not a rational number";
        QTest::newRow("clamped without tangents") << p + QStringList{"--parametric", "--ends", "clamped"} << "both end tangents";
        QTest::newRow("tangent with natural ends")
            << p + QStringList{"--parametric", "--start-tangent", "1,0", "--end-tangent", "1,0"} << "--ends clamped";
        QTest::newRow("bad tangent") << p + QStringList{"--parametric",  "--ends", "clamped", "--start-tangent", "1",
                                                        "--end-tangent", "1,0"}
                                     << "one vector";
        QTest::newRow("slopes with parametric")
            << p + QStringList{"--parametric", "--start-slope", "1", "--end-slope", "1"} << "end tangents";
        QTest::newRow("ex-2.1 ends with parametric") << p + QStringList{"--parametric", "--ends", "ex-2.1"} << "--ends";
        QTest::newRow("unknown parameters") << p + QStringList{"--parametric", "--param", "arc"} << "--param";
        QTest::newRow("param without parametric") << p + QStringList{"--param", "chord"} << "--parametric";
        QTest::newRow("both modes") << p + QStringList{"--parametric", "--monotone", "steffen"} << "not both";
        QTest::newRow("unknown monotone") << p + QStringList{"--monotone", "pchip"} << "--monotone";
        QTest::newRow("monotone, x not increasing")
            << QStringList{"spline", "--points", "0,0;2,1;1,0", "--monotone", "steffen"} << "increase strictly";
        QTest::newRow("monotone, one point")
            << QStringList{"spline", "--points", "0,0", "--monotone", "fritsch-carlson"} << "at least 2 points";
        QTest::newRow("monotone with ends") << p + QStringList{"--monotone", "steffen", "--ends", "natural"} << "--ends";
        QTest::newRow("exact too costly") << QStringList{"spline", "--points-file", manyPoints(), "--parametric",
                                                         "--ends", "periodic",      "--exact"}
                                          << "leave out --exact";
        QTest::newRow("monotone exact") << p + QStringList{"--monotone", "steffen", "--exact"} << "--exact";
    }
    void badInput()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, says);
        const CliRun r = runCli(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.out.isEmpty());
        QVERIFY2(r.err.startsWith("error: ") && r.err.contains(says.toUtf8()) && r.err.count('\n') == 1, r.err.constData());
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestCliSplineModes)
#include "test_cli_spline_modes.moc"
