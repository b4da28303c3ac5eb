// The cost of exact work is estimated before it is done (core/exact/exact_cost.h): the CLI's
// --exact refuses what would run for minutes, at once, and still answers exactly just
// inside; the estimate grows as the algorithms do.
#include "cli_runner.h"

#include "core/exact/exact_cost.h"
#include "core/curves/fitting/least_squares_fit.h"

#include <QtTest>
#include "tests/test_main.h"

#include <QJsonArray>
#include <QJsonObject>

using namespace granota;

namespace {

/// A process that does not finish within this is a failure (the refused cases used to run
/// for minutes). Not a timing assertion: a hung test would otherwise only time out.
constexpr int kRefusalTimeoutMs = 30000;

/// m small integer points (i, 7i mod 13).
QString smallPoints(int m)
{
    QStringList p;
    for (int i = 0; i < m; ++i)
        p << QStringLiteral("%1,%2").arg(i).arg((i * 7) % 13);
    return p.join(';');
}

std::vector<RPoint> smallRPoints(int m)
{
    std::vector<RPoint> q;
    for (int i = 0; i < m; ++i)
        q.emplace_back(Rational(i), Rational((i * 7) % 13));
    return q;
}

} // namespace

class TestExactCost : public QObject {
    Q_OBJECT
private slots:
    void bitLengths()
    {
        QCOMPARE(bitLength(Rational(1, 2)), 3L); // 1 and 10
        QCOMPARE(bitLength(Rational(-255)), 9L); // 11111111 over 1
        QCOMPARE(bitLength(*parseRational("1e1000")), 3322L + 1);
        QCOMPARE(maxBitLength({RPoint(Rational(3), Rational(1, 1024))}), 12L);
    }

    void workGrowsAsTheAlgorithms()
    {
        // Def 2.4: n² b_P + n³ b_t / 3 — doubling the bits of t doubles the t part.
        const double small = deCasteljauExactWork(200, 0, 1000), twice = deCasteljauExactWork(200, 0, 2000);
        QVERIFY(std::abs(twice / small - 2) < 1e-9);
        QVERIFY(deCasteljauExactWork(100, 0, 1000) < small / 7); // ≈ 1/8 at half the degree
        QVERIFY(bernsteinExactWork(200, 3) < deCasteljauExactWork(200, 3, 3));
        // With weights: the same triangle on three homogeneous coordinates whose bits are the
        // points' plus the weights', each level divided by its weights (exact_cost.h): 3 times.
        QCOMPARE(rationalDeCasteljauExactWork(50, 10, 6, 20), 3 * deCasteljauExactWork(50, 16, 20));
        // The fit grows faster than the cube of the degree.
        std::vector<Rational> t;
        for (int i = 0; i <= 200; ++i)
            t.push_back(Rational(i, 200));
        const double d20 = fitExactWork(20, t, 4), d40 = fitExactWork(40, t, 4);
        QVERIFY(d40 > 8 * d20);
    }

    void refusedAtOnce_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("what");
        QTest::newRow("bernstein 200 at 1e10000")
            << QStringList{"bernstein", "--degree", "200", "--t", "1e10000", "--exact"} << "Bernstein values";
        QTest::newRow("bezier 201 points at 1e1000")
            << QStringList{"bezier", "--points", smallPoints(201), "--t", "1e1000", "--exact"} << "De Casteljau triangle";
        QTest::newRow("bezier --weights 201 points at 1e-1000")
            << QStringList{"bezier", "--points", smallPoints(201), "--weights", QString("1,").repeated(200) + "2",
                           "--t",    "1e-1000",  "--exact"}
            << "De Casteljau triangle with weights";
        // The Bézier extraction is one pass (about 0.3 s at 1500 such points): 10 000 are refused.
        QTest::newRow("bspline 10000 points of degree 10 to Bezier")
            << QStringList{"bspline", "--points", smallPoints(10000), "--degree", "10", "--to-bezier", "--exact"}
            << "B-spline computation";
        QTest::newRow("fit degree 100 on 201 points")
            << QStringList{"fit", "--points", smallPoints(201), "--degree", "100", "--exact"} << "fit";
    }
    void refusedAtOnce()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, what);
        const CliRun r = runCli(args, kRefusalTimeoutMs);
        QVERIFY2(r.exitCode != -1, "did not finish: the exact work was done instead of refused");
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("error: the exact " + what.toUtf8() + " would take about "), r.err.constData());
        QVERIFY(r.err.contains("lower "));
        QCOMPARE(r.err.count('\n'), 1);
        QVERIFY(r.out.isEmpty());
        if (what == "fit") { // without --exact the same fit is answered in decimals
            args.removeAll("--exact");
            QCOMPARE(runCli(args, kRefusalTimeoutMs).exitCode, 0);
        }
    }

    void justInsideIsExact()
    {
        // Degree 200 at t = 1/2: B_i^200(1/2) = C(200, i) / 2^200 (Def 2.5), checked against
        // the recursion of Lemma 2.1 that the CLI uses.
        const CliRun r = runCli({"bernstein", "--degree", "200", "--t", "1/2", "--exact", "--json"}, kRefusalTimeoutMs);
        QCOMPARE(r.exitCode, 0);
        const QJsonArray values = r.json()["values"].toArray();
        QCOMPARE(values.size(), 201);
        mpz_class two200;
        mpz_ui_pow_ui(two200.get_mpz_t(), 2, 200);
        for (int i = 0; i <= 200; ++i) {
            Rational expected(binomial(200, i) / Rational(two200));
            expected.canonicalize();
            QCOMPARE(values[i].toString().toStdString(), toString(expected));
        }
        // 201 control points at t = 1/2: the whole triangle, exactly; c(1/2) is the
        // Bernstein sum of the points with those weights.
        const CliRun b = runCli({"bezier", "--points", smallPoints(201), "--t", "1/2", "--exact", "--json"}, kRefusalTimeoutMs);
        QCOMPARE(b.exitCode, 0);
        Rational x = 0, y = 0;
        const std::vector<RPoint> q = smallRPoints(201);
        for (int i = 0; i <= 200; ++i) {
            const Rational w = binomial(200, i) / Rational(two200);
            x += w * q[std::size_t(i)].x;
            y += w * q[std::size_t(i)].y;
        }
        const QJsonArray point = b.json()["point"].toArray();
        QCOMPARE(point[0].toString().toStdString(), toString(x));
        QCOMPARE(point[1].toString().toStdString(), toString(y));
        // The thesis's worked examples are far inside.
        QCOMPARE(runCli({"bezier", "--points", "2,3;-1,8;-5,-3;3,0;-7,-2", "--t", "1/2", "--exact"}).exitCode, 0);
        QCOMPARE(runCli({"fit", "--points", "0,0;1,3;4,2;8,-2;1,5", "--degree", "2", "--exact"}).exitCode, 0);
    }

    void fitRefusesBeforeBuildingAMatrix()
    {
        const std::vector<RPoint> q = smallRPoints(201);
        auto refused = fitBezierExact(q, 100, Parametrization::Uniform);
        QVERIFY(!refused.ok());
        QCOMPARE(refused.error().code, ErrorCode::OutOfRange);
        QVERIFY(refused.error().message.find("would take about") != std::string::npos);
        // A budget is a parameter: the same fit at degree 3 is inside the default and
        // outside a tiny one.
        QVERIFY(fitBezierExact(q, 3, Parametrization::Uniform).ok());
        QVERIFY(!fitBezierExact(q, 3, Parametrization::Uniform, 1000).ok());
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestExactCost)
#include "test_exact_cost.moc"
