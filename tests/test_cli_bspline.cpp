// granota-cli bspline (issue 36): knot insertion and removal where NURBS-Python goes wrong
// (geomdl #135, #158), a knot the curve needs kept, the uniform cubic's start, the clamped
// B-spline with no interior knot equal to `bezier`, the rational circle, the Bézier pieces,
// and exit 2 with one "error:" line for every kind of bad input of the issue. Expected values
// by hand in the comments (Boehm's α_i = (ū − u_i)/(u_{i+p} − u_i) written out).
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

/// A list of points as "x,y" strings: [["0","0"],["1","1"]] → {"0,0", "1,1"}.
QStringList pointStrings(const QJsonValue& v)
{
    QStringList out;
    for (const QJsonValue& p : v.toArray())
        out << strings(p).join(',');
    return out;
}

/// `count` points (i, i mod 7) in a CSV file that lives as long as the test.
QString manyPoints(int count)
{
    static QTemporaryDir dir;
    const QString path = dir.filePath(QString("points%1.csv").arg(count));
    QFile f(path);
    if (!f.exists() && f.open(QIODevice::WriteOnly))
        for (int i = 0; i < count; ++i)
            f.write(QByteArray::number(i) + ',' + QByteArray::number(i % 7) + '\n');
    return path;
}

} // namespace

class TestCliBspline : public QObject {
    Q_OBJECT
private slots:
    // geomdl #158: (0,0), (1,1), (2,1), (3,0) of degree 2 on 0, 1, …, 6 (domain [2, 4]); ū = 4
    // is the domain's end. The last knot ≤ 4 is u_4, so Q_i = α_i P_i + (1 − α_i) P_{i−1} for
    // i = 3, 4 − … : α_3 = (4 − 3)/(5 − 3) = 1/2 → Q_3 = (5/2, 1/2); the rest are kept:
    // (0,0), (1,1), (2,1), (5/2,1/2), (3,0), knots 0,1,2,3,4,4,5,6 (the values).
    void insertionAtTheEndOfAFloatingDomain()
    {
        const CliRun r = runCli({"bspline", "--points", "0,0;1,1;2,1;3,0", "--degree", "2", "--knots", "0,1,2,3,4,5,6",
                                 "--insert", "4", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(pointStrings(r.json()["control_points"]), QStringList({"0,0", "1,1", "2,1", "5/2,1/2", "3,0"}));
        QCOMPARE(strings(r.json()["knots"]), QStringList({"0", "1", "2", "3", "4", "4", "5", "6"}));
        QCOMPARE(r.json()["degree"].toInt(), 2);
        QVERIFY(!r.json().contains("weights"));
    }

    // geomdl #135: the quadratic (0,0), (1,1), (2,0) on 0,0,0,1,1,1 with 1/2 inserted:
    // α_1 = (1/2 − 0)/(1 − 0) = 1/2, α_2 = 1/2, so Q = (0,0), (1/2,1/2), (3/2,1/2), (2,0);
    // removing 1/2 again gives the quadratic back, exactly, in fractions and in doubles.
    void insertionThenRemovalIsTheIdentity()
    {
        const CliRun in = runCli({"bspline", "--points", "0,0;1,1;2,0", "--degree", "2", "--insert", "1/2", "--exact", "--json"});
        QCOMPARE(in.exitCode, 0);
        QCOMPARE(pointStrings(in.json()["control_points"]), QStringList({"0,0", "1/2,1/2", "3/2,1/2", "2,0"}));
        QCOMPARE(strings(in.json()["knots"]), QStringList({"0", "0", "0", "1/2", "1", "1", "1"}));
        for (const char* u : {"1/2", "0.5"}) {
            const bool exact = QByteArray(u) == "1/2";
            QStringList args{"bspline",  "--points", "0,0;1/2,1/2;3/2,1/2;2,0", "--degree",
                             "2",        "--knots",  "0,0,0,1/2,1,1,1",         "--remove",
                             QString(u), "--json"};
            if (exact)
                args << "--exact";
            const CliRun out = runCli(args);
            QCOMPARE(out.exitCode, 0);
            QCOMPARE(out.json()["removed"].toInt(), 1);
            const QJsonArray p = out.json()["control_points"].toArray();
            QCOMPARE(p.size(), 3);
            if (exact)
                QCOMPARE(pointStrings(p), QStringList({"0,0", "1,1", "2,0"}));
            else
                QCOMPARE(p[1].toArray()[0].toDouble(), 1.0);
        }
    }

    // (0,0), (1,1), (2,0), (3,1) of degree 2 on 0,0,0,1/2,1,1,1: the pieces' second differences
    // differ ((0,0) − 2(1,1) + (3/2,1/2) = (−1/2,−3/2) on the left, (3/2,1/2) − 2(2,0) + (3,1) =
    // (1/2,3/2) on the right), so no single quadratic is the curve: 1/2 stays, removed = 0.
    // With --tolerance the doubles remove it and say by how much the curve moved.
    void aKnotTheCurveNeedsStays()
    {
        const CliRun r = runCli(
            {"bspline", "--points", "0,0;1,1;2,0;3,1", "--degree", "2", "--remove", "1/2", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.json()["removed"].toInt(), 0);
        QCOMPARE(pointStrings(r.json()["control_points"]), QStringList({"0,0", "1,1", "2,0", "3,1"}));
        const CliRun loose = runCli(
            {"bspline", "--points", "0,0;1,1;2,0;3,1", "--degree", "2", "--remove", "0.5", "--tolerance", "10", "--json"});
        QCOMPARE(loose.exitCode, 0);
        QCOMPARE(loose.json()["removed"].toInt(), 1);
        QVERIFY(loose.json()["removal_error"].toDouble() > 0);
    }

    // The uniform cubic on 0, 1, …, 7 starts (u = u_3 = 3) at (P_0 + 4P_1 + P_2)/6: with
    // (0,0), (1,1), (2,0), (3,1) that is ((0 + 4 + 2)/6, (0 + 4 + 0)/6) = (1, 2/3). Level 1 by
    // hand: α = (3 − u_j)/(u_{j+3} − u_j) for j = 1, 2, 3 is 2/3, 1/3, 0.
    void uniformCubicStart()
    {
        const CliRun r = runCli(
            {"bspline", "--points", "0,0;1,1;2,0;3,1", "--degree", "3", "--knots", "uniform", "--u", "3", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(strings(r.json()["point"]), QStringList({"1", "2/3"}));
        QCOMPARE(r.json()["span"].toInt(), 3);
        const QJsonArray levels = r.json()["levels"].toArray();
        QCOMPARE(levels.size(), 4);
        QCOMPARE(pointStrings(levels[1]), QStringList({"2/3,2/3", "4/3,2/3", "2,0"}));
        QCOMPARE(strings(r.json()["knots"]), QStringList({"0", "1", "2", "3", "4", "5", "6", "7"}));
    }

    // Clamped with no interior knot is the Bézier curve: Ex 2.2's quartic at u = 1/2 gives
    // bezier's levels, entry for entry.
    void clampedWithoutInteriorKnotIsBezier()
    {
        const char* const ex22 = "2,3;-1,8;-5,-3;3,0;-7,-2";
        const CliRun b = runCli({"bspline", "--points", ex22, "--degree", "4", "--u", "1/2", "--exact", "--json"});
        const CliRun z = runCli({"bezier", "--points", ex22, "--t", "1/2", "--exact", "--json"});
        QCOMPARE(b.exitCode, 0);
        QCOMPARE(b.json()["levels"], z.json()["levels"]);
        QCOMPARE(strings(b.json()["point"]), QStringList({"-27/16", "15/16"}));
    }

    // Weights (1, 1, 2) on (1,0), (1,1), (0,1): the rational circle point (3/5, 4/5) at u = 1/2
    // (x = (1 − u²)/(1 + u²), y = 2u/(1 + u²)), the weights of the levels 1, 3/2 and 5/4 as in
    // bezier --weights, and a single Bézier segment that is the curve itself.
    void rationalCircle()
    {
        const CliRun r = runCli({"bspline", "--points", "1,0;1,1;0,1", "--degree", "2", "--weights", "1,1,2", "--u", "1/2",
                                 "--to-bezier", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(strings(r.json()["point"]), QStringList({"3/5", "4/5"}));
        QCOMPARE(strings(r.json()["weights"]), QStringList({"1", "1", "2"}));
        QCOMPARE(strings(r.json()["weight_levels"].toArray()[1]), QStringList({"1", "3/2"}));
        const QJsonArray segments = r.json()["segments"].toArray();
        QCOMPARE(segments.size(), 1);
        QCOMPARE(pointStrings(segments[0]), QStringList({"1,0", "1,1", "0,1"}));
        QCOMPARE(strings(r.json()["segment_weights"].toArray()[0]), QStringList({"1", "1", "2"}));
    }

    // The Bézier extraction is one pass (bezier_extraction.h, O(n p²)): 20 000 cubic points in
    // doubles, once refused as n²p² work, give their 19 997 pieces — one per interior span of the
    // clamped vector (n − p + 1 = 19 999 − 3 + 1), from P₀ = (0, 0) to P_n = (19 999, 19 999 mod 7 = 0).
    void bezierPiecesOfManyPoints()
    {
        const CliRun r = runCli({"bspline", "--points-file", manyPoints(20000), "--degree", "3", "--to-bezier", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray s = r.json()["segments"].toArray();
        QCOMPARE(s.size(), 19997);
        const QJsonArray first = s.first().toArray()[0].toArray(), last = s.last().toArray()[3].toArray();
        QCOMPARE(first[0].toDouble(), 0.0);
        QCOMPARE(first[1].toDouble(), 0.0);
        QCOMPARE(last[0].toDouble(), 19999.0);
        QCOMPARE(last[1].toDouble(), 0.0);
    }

    // (1,0), (1,1), (0,1), (−1,1) of degree 2 on 0,0,0,1/2,1,1,1: two pieces meeting at the
    // midpoint of P_1 P_2, (1/2, 1). At u = 0.3 (t = 0.6 on the first piece):
    // x = 0.16·1 + 0.48·1 + 0.36·(1/2) = 0.82, y = 0.48 + 0.36 = 0.84.
    void bezierPiecesAndDoubles()
    {
        const CliRun r = runCli({"bspline", "--points", "1,0;1,1;0,1;-1,1", "--degree", "2", "--to-bezier", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray s = r.json()["segments"].toArray();
        QCOMPARE(s.size(), 2);
        QCOMPARE(pointStrings(s[0]), QStringList({"1,0", "1,1", "1/2,1"}));
        QCOMPARE(pointStrings(s[1]), QStringList({"1/2,1", "0,1", "-1,1"}));
        QCOMPARE(strings(r.json()["segment_intervals"].toArray()[1]), QStringList({"1/2", "1"}));
        const CliRun d = runCli({"bspline", "--points", "1,0;1,1;0,1;-1,1", "--degree", "2", "--u", "0.3", "--json"});
        QCOMPARE(d.exitCode, 0);
        const QJsonArray p = d.json()["point"].toArray();
        QVERIFY(std::abs(p[0].toDouble() - 0.82) <= 1e-15 && std::abs(p[1].toDouble() - 0.84) <= 1e-15);
        const CliRun text = runCli({"bspline", "--points", "1,0;1,1;0,1;-1,1", "--degree", "2", "--u", "1/4", "--exact"});
        QCOMPARE(text.exitCode, 0);
        QVERIFY(text.out.contains("c(u) = "));
        QVERIFY(text.out.contains("span k = 2"));
    }

    void badInput_data()
    {
        QTest::addColumn<QStringList>("args");
        const QStringList base{"bspline", "--points", "0,0;1,1;2,1;3,0"};
        QTest::newRow("no degree") << base;
        QTest::newRow("degree 0") << base + QStringList{"--degree", "0"};
        QTest::newRow("degree 11") << base + QStringList{"--degree", "11"};
        QTest::newRow("too few points") << base + QStringList{"--degree", "4"};
        QTest::newRow("decreasing knots") << base + QStringList{"--degree", "2", "--knots", "0,0,0,1,1/2,1,1"};
        QTest::newRow("too few knots") << base + QStringList{"--degree", "2", "--knots", "0,0,0,1,1,1"};
        QTest::newRow("too many knots") << base + QStringList{"--degree", "2", "--knots", "0,0,0,0,1,1,1,1"};
        QTest::newRow("multiplicity p + 2 at an end") << base + QStringList{"--degree", "2", "--knots", "0,0,0,0,1,1,1"};
        QTest::newRow("multiplicity p + 1 inside")
            << QStringList{"bspline", "--points", "0,0;1,1;2,1;3,0;4,4", "--degree", "2", "--knots", "0,0,0,1/2,1/2,1/2,1,1"};
        QTest::newRow("bad knot") << base + QStringList{"--degree", "2", "--knots", "0,0,0,x,1,1,1"};
        QTest::newRow("zero weight") << base + QStringList{"--degree", "2", "--weights", "1,0,1,1"};
        QTest::newRow("negative weight") << base + QStringList{"--degree", "2", "--weights", "1,-1,1,1"};
        QTest::newRow("too few weights") << base + QStringList{"--degree", "2", "--weights", "1,1,1"};
        QTest::newRow("u above the domain") << base + QStringList{"--degree", "2", "--u", "2"};
        QTest::newRow("u below the domain") << base + QStringList{"--degree", "2", "--knots", "0,1,2,3,4,5,6", "--u", "1"};
        QTest::newRow("insert outside") << base + QStringList{"--degree", "2", "--insert", "3/2"};
        QTest::newRow("insert above p") << base + QStringList{"--degree", "2", "--insert", "1/2", "--times", "2"};
        QTest::newRow("remove no knot") << base + QStringList{"--degree", "2", "--remove", "1/3"};
        QTest::newRow("remove an end") << base + QStringList{"--degree", "2", "--remove", "0"};
        QTest::newRow("times alone") << base + QStringList{"--degree", "2", "--times", "2"};
        QTest::newRow("negative tolerance") << base + QStringList{"--degree", "2", "--remove", "1/2", "--tolerance", "-1"};
        QTest::newRow("exact tolerance") << base + QStringList{"--degree", "2", "--remove", "1/2", "--tolerance", "1", "--exact"};
        // Three knots 1, 1 + 10⁻²⁰, 1 + 2·10⁻²⁰: distinct exactly, one knot of multiplicity 3 > p
        // once rounded to doubles (and accepted by --exact).
        QTest::newRow("knots merged by rounding") << QStringList{"bspline",
                                                                 "--points",
                                                                 "0,0;1,1;2,1;3,0;4,4",
                                                                 "--degree",
                                                                 "2",
                                                                 "--knots",
                                                                 "0,0,0,1,1.00000000000000000001,1.00000000000000000002,2,2"};
        // Work refused before it is done (exact-cost.md): the exact Bézier extraction of 20 000
        // points of degree 10 (an estimate of 1.2·10¹⁰).
        QTest::newRow("exact to-bezier too large")
            << QStringList{"bspline", "--points-file", manyPoints(20000), "--degree", "10", "--to-bezier", "--exact"};
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

GRANOTA_TEST_APPLESS_MAIN(TestCliBspline)
#include "test_cli_bspline.moc"
