// granota-cli spline (issue 33, part 2): the cubic spline of Def 2.3 with its end
// conditions, each piece in powers of x. Expected values: Ex 2.1's printed pieces with the
// +1/53 its s₂ lacks (the thesis), a cubic reproduced by clamped and not-a-knot ends (a
// cubic is its own spline under both), and the smoothstep of two points with flat ends.
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

/// 10 001 points (i, i mod 7): an exact spline of minutes (docs/exact-cost.md), refused.
QString manyPoints()
{
    static QTemporaryDir dir;
    const QString path = dir.filePath("many.csv");
    QFile f(path);
    if (f.open(QIODevice::WriteOnly))
        for (int i = 0; i <= 10000; ++i)
            f.write(QByteArray::number(i) + ',' + QByteArray::number(i % 7) + '\n');
    return path;
}

} // namespace

class TestCliSpline : public QObject {
    Q_OBJECT
private slots:
    void ex21ExactlyAsPrintedButForTheSlip()
    {
        const CliRun r = runCli({"spline", "--points", "0,1;1,3;2,1;3,-1", "--ends", "ex-2.1", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject j = r.json();
        QCOMPARE(j["ends"].toString(), QString("ex-2.1"));
        const QJsonArray pieces = j["pieces"].toArray();
        QCOMPARE(pieces.size(), 3);
        QCOMPARE(strings(pieces[0].toObject()["poly"]), (QStringList{"1", "238/53", "-132/53", "0"}));
        QCOMPARE(strings(pieces[1].toObject()["poly"]), (QStringList{"1/53", "394/53", "-288/53", "52/53"}));
        QCOMPARE(strings(pieces[2].toObject()["poly"]), (QStringList{"385/53", "-182/53", "0", "4/53"}));
        QCOMPARE(pieces[1].toObject()["from"].toString(), QString("1"));
        QCOMPARE(pieces[1].toObject()["to"].toString(), QString("2"));
        // The text prints the pieces in powers of x, with their intervals.
        const CliRun text = runCli({"spline", "--points", "0,1;1,3;2,1;3,-1", "--ends", "ex-2.1", "--exact"});
        QCOMPARE(text.exitCode, 0);
        QVERIFY2(text.out.contains("s_3(x) = ") && text.out.contains("x ∈ [2, 3]"), text.out.constData());
    }
    void aCubicIsReproduced()
    {
        // f(x) = 2x³ − 3x² + x/2 − 1 at 0, 1/3, 1, 5/2, 4; f′(0) = 1/2, f′(4) = 145/2.
        const QString points = "0,-1;1/3,-59/54;1,-3/2;5/2,51/4;4,81";
        for (const QStringList& ends : {QStringList{"--ends", "clamped", "--start-slope", "1/2", "--end-slope", "145/2"},
                                        QStringList{"--ends", "not-a-knot"}}) {
            const CliRun r = runCli(QStringList{"spline", "--points", points, "--exact", "--json"} + ends);
            QCOMPARE(r.exitCode, 0);
            for (const QJsonValue& piece : r.json()["pieces"].toArray())
                QCOMPARE(strings(piece.toObject()["poly"]), (QStringList{"-1", "1/2", "-3", "2"}));
            // In doubles, the same to rounding.
            const CliRun d = runCli(QStringList{"spline", "--points", points, "--json"} + ends);
            QCOMPARE(d.exitCode, 0);
            const QJsonArray poly = d.json()["pieces"].toArray()[2].toObject()["poly"].toArray();
            const double expected[] = {-1, 0.5, -3, 2};
            for (int i = 0; i < 4; ++i)
                QVERIFY2(std::abs(poly[i].toDouble() - expected[i]) < 1e-12, qPrintable(QString::number(poly[i].toDouble())));
        }
    }
    void twoFlatEndsGiveTheSmoothstep()
    {
        const CliRun r = runCli({"spline", "--points", "0,0;1,1", "--ends", "clamped", "--start-slope", "0", "--end-slope", "0",
                                 "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(strings(r.json()["pieces"].toArray()[0].toObject()["poly"]), (QStringList{"0", "0", "3", "-2"}));
    }
    void badInput_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("says");
        QTest::newRow("unknown ends") << QStringList{"spline", "--points", "0,0;1,1;2,0", "--ends", "periodic"} << "--ends";
        QTest::newRow("clamped without slopes")
            << QStringList{"spline", "--points", "0,0;1,1", "--ends", "clamped"} << "needs both end slopes";
        QTest::newRow("slopes without clamped")
            << QStringList{"spline", "--points", "0,0;1,1", "--start-slope", "1", "--end-slope", "1"} << "--ends clamped";
        QTest::newRow("x not increasing") << QStringList{"spline", "--points", "0,0;2,1;1,0"} << "increase strictly";
        QTest::newRow("one point") << QStringList{"spline", "--points", "0,0"} << "at least 2 points";
        QTest::newRow("ex-2.1 with x_{k-1} = 0")
            << QStringList{"spline", "--points", "-2,0;-1,1;0,0;1,2", "--ends", "ex-2.1", "--exact"} << "x_{k-1}";
        QTest::newRow("exact too costly") << QStringList{"spline", "--points-file", manyPoints(), "--exact"}
                                          << "leave out --exact";
    }
    void badInput()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, says);
        const CliRun r = runCli(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.out.isEmpty());
        QVERIFY2(r.err.startsWith("error: ") && r.err.contains(says.toUtf8()), r.err.constData());
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestCliSpline)
#include "test_cli_spline.moc"
