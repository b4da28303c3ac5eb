// granota-cli's differential geometry of a Bézier curve (docs/cli.md): `project` (the
// closest point) and `analyze` (hodograph, length, extrema, box, inflections, cusps, the
// curvature at t), against values known in closed form; bad input is exit 2 with "error:".
#include "cli_runner.h"

#include <QtTest>
#include "tests/test_main.h"

#include <QJsonArray>
#include <QJsonObject>

#include <cmath>

namespace {

double num(const QJsonValue& v) { return v.toDouble(std::nan("")); }

} // namespace

class TestCliCurves : public QObject {
    Q_OBJECT
private slots:
    void projectKnownValues()
    {
        // The arch (0,0),(0,1),(1,1),(1,0): from (1/2, 5) the top c(1/2) = (1/2, 3/4), 4.25 away.
        const CliRun top = runCli({"project", "--points", "0,0;0,1;1,1;1,0", "--at", "1/2,5", "--json"});
        QCOMPARE(top.exitCode, 0);
        const QJsonObject j = top.json();
        QCOMPARE(j.keys(), (QStringList{"distance", "point", "t"}));
        QVERIFY(std::fabs(num(j["t"]) - 0.5) < 1e-15);
        QVERIFY(std::fabs(num(j["distance"]) - 4.25) < 1e-14);
        QVERIFY(std::fabs(num(j["point"].toArray()[1]) - 0.75) < 1e-15);
        // From (1/2, −1) both ends are √1.25 away: the smallest t, 0, is the answer.
        const QJsonObject tie = runCli({"project", "--points", "0,0;0,1;1,1;1,0", "--at", "0.5,-1", "--json"}).json();
        QCOMPARE(num(tie["t"]), 0.0);
        QVERIFY(std::fabs(num(tie["distance"]) - std::sqrt(1.25)) < 1e-15);
        // A segment: the foot of the perpendicular, exactly.
        const QJsonObject foot = runCli({"project", "--points", "0,0;4,0", "--at", "1,3", "--json"}).json();
        QCOMPARE(num(foot["t"]), 0.25);
        QCOMPARE(num(foot["distance"]), 3.0);
        // One control point is a curve too (the point itself, t = 0).
        const QJsonObject single = runCli({"project", "--points", "2,2", "--at", "5,6", "--json"}).json();
        QCOMPARE(num(single["t"]), 0.0);
        QCOMPARE(num(single["distance"]), 5.0);
        // Text output names t and the distance.
        const CliRun text = runCli({"project", "--points", "0,0;4,0", "--at", "1,3"});
        QCOMPARE(text.exitCode, 0);
        QVERIFY(text.out.contains("t = 0.25"));
        QVERIFY(text.out.contains("distance = 3"));
    }

    void analyzeKnownValues()
    {
        // (0,0),(0,1),(1,1),(1,0): c′ = 3[(0,1),(1,0),(0,−1)], |c′| = 3(1 − 2t + 2t²)… its
        // length is exactly 2; κ(0) = (x′y″ − y′x″)/|c′|³ = (0·(−6) − 3·6)/27 = −2/3.
        const CliRun r = runCli({"analyze", "--points", "0,0;0,1;1,1;1,0", "--t", "0", "--length-at", "1", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject j = r.json();
        for (const char* key : {"degree", "hodograph", "length", "extrema", "bbox", "inflections", "cusps", "at", "t_at_length"})
            QVERIFY2(j.contains(key), key);
        QCOMPARE(j["degree"].toInt(), 3);
        QVERIFY(std::fabs(num(j["length"]) - 2.0) < 1e-13);
        const QJsonArray h = j["hodograph"].toArray();
        QCOMPARE(h.size(), 3);
        QCOMPARE(num(h[0].toArray()[1]), 3.0);
        QCOMPARE(num(h[1].toArray()[0]), 3.0);
        QCOMPARE(num(h[2].toArray()[1]), -3.0);
        QVERIFY(j["extrema"].toObject()["x"].toArray().isEmpty());
        QCOMPARE(j["extrema"].toObject()["y"].toArray(), QJsonArray{0.5});
        QCOMPARE(num(j["bbox"].toArray()[1].toArray()[1]), 0.75);
        const QJsonObject at = j["at"].toObject();
        QVERIFY(std::fabs(num(at["curvature"]) + 2.0 / 3.0) < 1e-15);
        QVERIFY(std::fabs(num(at["radius"]) - 1.5) < 1e-15);
        QCOMPARE(num(at["normal"].toArray()[0]), -1.0); // left of the tangent (0, 3)
        QCOMPARE(num(at["arc_length"]), 0.0);
        // By symmetry half the length is reached at t = 1/2.
        QVERIFY(std::fabs(num(j["t_at_length"]) - 0.5) < 1e-12);

        // (0,0),(0.5,1),(1,0): L = (2√5 + asinh 2)/4.
        const QJsonObject q = runCli({"analyze", "--points", "0,0;0.5,1;1,0", "--json"}).json();
        QVERIFY(std::fabs(num(q["length"]) - (2 * std::sqrt(5.0) + std::asinh(2.0)) / 4) < 1e-13);
        QVERIFY(!q.contains("at"));

        // Inflections of (0,0),(1,0.25),(0,1),(1,0) at 1/2 and 4/5.
        const QJsonArray infl = runCli({"analyze", "--points", "0,0;1,0.25;0,1;1,0", "--json"}).json()["inflections"].toArray();
        QCOMPARE(infl.size(), 2);
        QCOMPARE(num(infl[0]), 0.5);
        QVERIFY(std::fabs(num(infl[1]) - 0.8) < 1e-15);
    }

    void analyzeAtACusp()
    {
        // (0,0),(1,1),(0,1),(1,0): c′(1/2) = 0. The normal, κ, radius and centre are null.
        const QJsonObject j = runCli({"analyze", "--points", "0,0;1,1;0,1;1,0", "--t", "1/2", "--json"}).json();
        QCOMPARE(j["cusps"].toArray(), QJsonArray{0.5});
        const QJsonObject at = j["at"].toObject();
        QVERIFY(at["normal"].isNull());
        QVERIFY(at["curvature"].isNull());
        QVERIFY(at["radius"].isNull());
        QVERIFY(at["center"].isNull());
        QCOMPARE(num(at["tangent"].toArray()[0]), 0.0);
    }

    void projectInCatalanLocale()
    {
        const CliRun r = runCliWith({"LANG=ca_ES.UTF-8", "LC_ALL=ca_ES.UTF-8"},
                                    {"project", "--points", "0,0;4,0", "--at", "1.5,3"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("t = 0.375"), r.out.constData()); // a point, never a comma
    }

    void badInput_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("project: no --at") << QStringList{"project", "--points", "0,0;1,1"};
        QTest::newRow("project: NaN --at") << QStringList{"project", "--points", "0,0;1,1", "--at", "nan,0"};
        QTest::newRow("project: inf --at") << QStringList{"project", "--points", "0,0;1,1", "--at", "0,inf"};
        QTest::newRow("project: huge --at") << QStringList{"project", "--points", "0,0;1,1", "--at", "1e400,0"};
        QTest::newRow("project: two points --at") << QStringList{"project", "--points", "0,0;1,1", "--at", "1,1;2,2"};
        QTest::newRow("project: garbage --at") << QStringList{"project", "--points", "0,0;1,1", "--at", "here"};
        QTest::newRow("project: NaN point") << QStringList{"project", "--points", "0,0;nan,1", "--at", "0,0"};
        QTest::newRow("project: no points") << QStringList{"project", "--at", "0,0"};
        QTest::newRow("project: --t") << QStringList{"project", "--points", "0,0;1,1", "--at", "0,0", "--t", "1"};
        QTest::newRow("analyze: one point") << QStringList{"analyze", "--points", "1,1"};
        QTest::newRow("analyze: NaN point") << QStringList{"analyze", "--points", "0,0;nan,1"};
        QTest::newRow("analyze: huge point") << QStringList{"analyze", "--points", "0,0;1e400,1"};
        QTest::newRow("analyze: length-at > L") << QStringList{"analyze", "--points", "0,0;1,0", "--length-at", "1.5"};
        QTest::newRow("analyze: length-at < 0") << QStringList{"analyze", "--points", "0,0;1,0", "--length-at", "-1/10"};
        QTest::newRow("analyze: t > 1") << QStringList{"analyze", "--points", "0,0;1,0", "--t", "2"};
        QTest::newRow("analyze: garbage t") << QStringList{"analyze", "--points", "0,0;1,0", "--t", "x"};
    }
    void badInput()
    {
        QFETCH(QStringList, args);
        const CliRun r = runCli(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.out.isEmpty());
        QVERIFY2(r.err.startsWith("error: "), r.err.constData());
        QCOMPARE(r.err.count('\n'), 1);
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestCliCurves)
#include "test_cli_curves.moc"
