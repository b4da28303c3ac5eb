// granota-cli kochanek-bartels (issue 37): the keys of catmull-rom plus "tangents". Expected
// values: the closed (0,0),(1,1),(2,0) curve with C = 1/2 worked by hand (Δ₋ = (1,1),
// Δ₊ = (1,−1) at (1,1): in = (1,−1/2), out = (1,1/2); the knot there C⁰ and not G¹); T alone
// against the catmull-rom command's own output with τ = (1 − T)/2 (Lemma 2.3's matrix, a
// separate computation); bad input exits 2 with one "error: …" line.
#include "cli_runner.h"

#include <QtTest>
#include "tests/test_main.h"

#include <QJsonArray>
#include <QJsonObject>

namespace {

QStringList strings(const QJsonValue& v)
{
    QStringList out;
    for (const QJsonValue& x : v.toArray())
        out << x.toString();
    return out;
}

} // namespace

class TestCliKochanekBartels : public QObject {
    Q_OBJECT
private slots:
    void closedTriangleByHand()
    {
        const CliRun r = runCli({"kochanek-bartels", "--points", "0,0;1,1;2,0", "--tcb", "0,1/2,0", "--mode", "closed", "--exact",
                                 "--json", "--samples", "3"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject j = r.json();
        const QJsonArray tangents = j["tangents"].toArray();
        QCOMPARE(tangents.size(), 3);
        QCOMPARE(strings(tangents[1].toObject()["in"]), (QStringList{"1", "-1/2"}));
        QCOMPARE(strings(tangents[1].toObject()["out"]), (QStringList{"1", "1/2"}));
        // Segment 2 (q_1 → q_2) starts with out_1: c_1 = (1, 1/2), c_0 = (1, 1).
        const QJsonObject seg = j["segments"].toArray()[1].toObject();
        QCOMPARE(strings(seg["x"]).mid(0, 2), (QStringList{"1", "1"}));
        QCOMPARE(strings(seg["y"]).mid(0, 2), (QStringList{"1", "1/2"}));
        // Its Bézier points: b_1 = q_1 + out_1/3 = (4/3, 7/6).
        QCOMPARE(strings(j["bezier"].toArray()[1].toArray()[1]), (QStringList{"4/3", "7/6"}));
        QCOMPARE(j["samples"].toArray().size(), 9);
        const QJsonArray knots = j["knots"].toArray();
        QCOMPARE(knots.size(), 3);
        QCOMPARE(knots[0].toObject()["knot"].toInt(), 1);
        QCOMPARE(knots[0].toObject()["C"].toInt(), 0);
        QCOMPARE(knots[0].toObject()["G"].toInt(), 0);
        const CliRun text = runCli(
            {"kochanek-bartels", "--points", "0,0;1,1;2,0", "--tcb", "0,1/2,0", "--mode", "closed", "--exact"});
        QCOMPARE(text.exitCode, 0);
        QVERIFY2(text.out.contains("q_1: in (1, -1/2), out (1, 1/2)"), text.out.constData());
    }

    // T alone: the same segments and Bézier points as catmull-rom --tau (1 − T)/2, in every mode.
    void tensionIsCatmullRomTau_data()
    {
        QTest::addColumn<QString>("mode");
        QTest::addColumn<QString>("tension");
        QTest::addColumn<QString>("tau");
        for (const char* mode : {"open", "cyclic", "closed"}) {
            QTest::addRow("%s T=0", mode) << mode << "0"
                                          << "1/2";
            QTest::addRow("%s T=1/3", mode) << mode << "1/3"
                                            << "1/3";
            QTest::addRow("%s T=-2", mode) << mode << "-2"
                                           << "3/2";
        }
    }
    void tensionIsCatmullRomTau()
    {
        QFETCH(QString, mode);
        QFETCH(QString, tension);
        QFETCH(QString, tau);
        const QString points = "3,5;2,2;6,0;8,3;7,5";
        const CliRun kb = runCli(
            {"kochanek-bartels", "--points", points, "--tcb", tension + ",0,0", "--mode", mode, "--exact", "--json"});
        const CliRun cr = runCli({"catmull-rom", "--points", points, "--tau", tau, "--mode", mode, "--exact", "--json"});
        QCOMPARE(kb.exitCode, 0);
        QCOMPARE(cr.exitCode, 0);
        for (const char* key : {"segments", "samples", "bezier", "knots"})
            QCOMPARE(kb.json()[key], cr.json()[key]);
        // In doubles too (the same numbers to rounding: compare the first segment's coefficients).
        const CliRun kbd = runCli({"kochanek-bartels", "--points", points, "--tcb", tension + ",0,0", "--mode", mode, "--json"});
        const CliRun crd = runCli({"catmull-rom", "--points", points, "--tau", tau, "--mode", mode, "--json"});
        QCOMPARE(kbd.exitCode, 0);
        const QJsonArray a = kbd.json()["segments"].toArray()[0].toObject()["y"].toArray();
        const QJsonArray b = crd.json()["segments"].toArray()[0].toObject()["y"].toArray();
        for (int k = 0; k < 4; ++k)
            QVERIFY(std::abs(a[k].toDouble() - b[k].toDouble()) < 1e-12);
    }

    // One triple per point; the centripetal curve runs in doubles.
    void perPointAndAlpha()
    {
        const CliRun r = runCli(
            {"kochanek-bartels", "--points", "0,0;1,1;2,0;4,1", "--tcb", "0,0,0; 1,0,0; 0,-1,0; 0,0,1;", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        // T = 1 at q_1: both tangents zero.
        QCOMPARE(strings(r.json()["tangents"].toArray()[1].toObject()["in"]), (QStringList{"0", "0"}));
        const CliRun alpha = runCli({"kochanek-bartels", "--points", "0,0;3,4;3,5", "--tcb", "0,0,0", "--alpha", "1", "--json"});
        QCOMPARE(alpha.exitCode, 0);
        // α = 1: h_0 = 5, h_1 = 1; in_1 = (3/2, 5/2)·10/6, out_1 = (3/2, 5/2)·2/6 (kochanek_bartels.h).
        const QJsonObject t = alpha.json()["tangents"].toArray()[1].toObject();
        QVERIFY(std::abs(t["in"].toArray()[0].toDouble() - 2.5) < 1e-12);
        QVERIFY(std::abs(t["out"].toArray()[1].toDouble() - 5.0 / 6) < 1e-12);
    }

    void badInput_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("says");
        const QStringList tri{"kochanek-bartels", "--points", "0,0;1,1;2,0"};
        QTest::addRow("no tcb") << tri << "--tcb T,C,B is required";
        QTest::addRow("continuity 2") << (tri + QStringList{"--tcb", "0,2,0"}) << "continuity C 2 must lie between -1 and 1";
        QTest::addRow("bias -3/2") << (tri + QStringList{"--tcb", "0,0,-3/2"}) << "bias B -3/2 must lie between -1 and 1";
        QTest::addRow("two fields") << (tri + QStringList{"--tcb", "0,0"}) << "write tension, continuity and bias";
        QTest::addRow("not a number") << (tri + QStringList{"--tcb", "0,x,0"}) << "is not a number";
        QTest::addRow("wrong count") << (tri + QStringList{"--tcb", "0,0,0;0,0,0"}) << "2 triples for 3 points";
        QTest::addRow("too few closed") << QStringList{"kochanek-bartels", "--points", "0,0;1,1", "--tcb", "0,0,0",
                                                       "--mode",           "closed"}
                                        << "needs at least 3 points";
        QTest::addRow("alpha 2") << (tri + QStringList{"--tcb", "0,0,0", "--alpha", "2"}) << "--alpha must be between 0 and 1";
        QTest::addRow("exact alpha") << (tri + QStringList{"--tcb", "0,0,0", "--alpha", "1/2", "--exact"})
                                     << "--exact needs --alpha 0";
        QTest::addRow("huge tension") << (tri + QStringList{"--tcb", "1e400,0,0"}) << "too large";
        QTest::addRow("overflow") << QStringList{"kochanek-bartels", "--points", "0,0;1e308,0;-1e308,0", "--tcb", "-3,0,0"}
                                  << "too large";
    }
    void badInput()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, says);
        const CliRun r = runCli(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("error: ") && r.err.contains(says.toUtf8()), r.err.constData());
        QCOMPARE(r.err.count('\n'), 1);
        QVERIFY(r.out.isEmpty());
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestCliKochanekBartels)
#include "test_cli_kochanek_bartels.moc"
