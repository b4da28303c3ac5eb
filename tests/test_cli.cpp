// granota-cli against the contract of docs/cli.md: JSON keys, exact output of the thesis's
// examples, and exit status 2 with "error:" on stderr for every kind of bad input.
#include "cli_runner.h"
#include "core/curves/fitting/least_squares_fit.h"

#include <QtTest>
#include "tests/test_main.h"

#include <cmath>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

namespace {

using Run = CliRun;
inline Run cli(const QStringList& args) { return runCli(args); }

/// Writes `bytes` to `name` in `dir` and returns its path (empty if it could not).
QString writeFile(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes)
{
    QFile file(dir.filePath(name));
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size())
        return QString();
    return file.fileName();
}

QStringList strings(const QJsonArray& a)
{
    QStringList l;
    for (const auto& v : a)
        l << v.toString();
    return l;
}

const char* const kEx22 = "2,3;-1,8;-5,-3;3,0;-7,-2";
const char* const kEx27 = "0,0;1,3;4,2;8,-2;1,5";
const char* const kEx213 = "3,5;2,2;6,0;8,3;7,5";

} // namespace

class TestCli : public QObject {
    Q_OBJECT
private slots:
    void bezierEx22Exact()
    {
        const Run r = cli({"bezier", "--points", kEx22, "--t", "1/2", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = r.json();
        // c(t) = (2 - 12t - 6t^2 + 52t^3 - 43t^4, 3 + 20t - 96t^2 + 120t^3 - 49t^4)
        const QJsonObject poly = o["poly"].toObject();
        QCOMPARE(strings(poly["x"].toArray()), QStringList({"2", "-12", "-6", "52", "-43"}));
        QCOMPARE(strings(poly["y"].toArray()), QStringList({"3", "20", "-96", "120", "-49"}));
        // c(1/2) from that polynomial: x = 2 - 6 - 3/2 + 13/2 - 43/16 = -27/16.
        QCOMPARE(strings(o["point"].toArray()), QStringList({"-27/16", "15/16"}));
        const QJsonArray levels = o["levels"].toArray();
        QCOMPARE(levels.size(), 5);
        for (int r = 0; r < 5; ++r)
            QCOMPARE(levels[r].toArray().size(), 5 - r);
        // P_0^1(1/2) = (2 - 3/2, 3 + 5/2) from Ex 2.2's table.
        QCOMPARE(strings(levels[1].toArray()[0].toArray()), QStringList({"1/2", "11/2"}));
        QCOMPARE(strings(levels[4].toArray()[0].toArray()), strings(o["point"].toArray()));
    }

    void bezierDoubleAgrees()
    {
        const Run r = cli({"bezier", "--points", kEx22, "--t", "0.5", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray p = r.json()["point"].toArray();
        QCOMPARE(p[0].toDouble(), -27.0 / 16);
        QCOMPARE(p[1].toDouble(), 15.0 / 16);
        QCOMPARE(r.json()["poly"].toObject()["x"].toArray()[4].toDouble(), -43.0);
    }

    // --reduce: the closest quadratic in L² to (0,0),(0,1),(1,1),(1,0) removes the cubic's
    // shifted-Legendre component: x = 3t² − 2t³ + (1/10)(20t³ − 30t² + 12t − 1) = −1/10 + 6t/5,
    // so the x's are −1/10, 1/2, 11/10; y = 3t − 3t² is already quadratic (0, 3/2, 0). The
    // error is |−2/20|·‖L̃_3‖ = (1/10)/√7 = √(1/700).
    void bezierReduce()
    {
        const Run r = cli({"bezier", "--points", "0,0;0,1;1,1;1,0", "--reduce", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray q = r.json()["reduced"].toArray();
        QCOMPARE(q.size(), 3);
        QCOMPARE(strings(q[0].toArray()), QStringList({"-1/10", "0"}));
        QCOMPARE(strings(q[1].toArray()), QStringList({"1/2", "3/2"}));
        QCOMPARE(strings(q[2].toArray()), QStringList({"11/10", "0"}));
        QVERIFY(std::abs(r.json()["reduction_error"].toDouble() - std::sqrt(1.0 / 700)) < 1e-15);
        QVERIFY(!r.json().contains("levels")); // no --t: only the reduction

        // Doubles, with --t: the construction and the reduction, correctly rounded.
        const Run d = cli({"bezier", "--points", "0,0;0,1;1,1;1,0", "--t", "0.5", "--reduce", "--json"});
        QCOMPARE(d.exitCode, 0);
        QVERIFY(d.json().contains("levels"));
        QCOMPARE(d.json()["reduced"].toArray()[2].toArray()[0].toDouble(), 1.1);
        QVERIFY(d.out.contains("\"reduction_error\":0.0377964473009227"));

        // Ex 2.2's quartic elevated to degree 5 (exactly, as fractions) comes back exactly.
        const Run e = cli({"bezier", "--points", "2,3;-2/5,7;-17/5,7/5;-9/5,-9/5;1,-2/5;-7,-2", "--reduce", "--exact", "--json"});
        QCOMPARE(e.exitCode, 0);
        const QJsonArray back = e.json()["reduced"].toArray();
        QCOMPARE(back.size(), 5);
        QCOMPARE(strings(back[1].toArray()), QStringList({"-1", "8"}));
        QCOMPARE(strings(back[2].toArray()), QStringList({"-5", "-3"}));
        QCOMPARE(strings(back[3].toArray()), QStringList({"3", "0"}));
        QCOMPARE(e.json()["reduction_error"].toDouble(), 0.0);
        const Run t = cli({"bezier", "--points", "0,0;0,1;1,1;1,0", "--reduce"});
        QVERIFY(t.out.contains("L2 distance: 0.03779644730092272"));
    }

    void bernsteinExact()
    {
        const Run r = cli({"bernstein", "--degree", "4", "--t", "1/3", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = r.json();
        // B_i^4(1/3) = C(4,i) 2^(4-i) / 81
        QCOMPARE(strings(o["values"].toArray()), QStringList({"16/81", "32/81", "8/27", "8/81", "1/81"}));
        // Ex 2.4: B_1^4 = 4t - 12t^2 + 12t^3 - 4t^4
        QCOMPARE(strings(o["poly"].toArray()[1].toArray()), QStringList({"0", "4", "-12", "12", "-4"}));
    }

    void fitEx27Exact()
    {
        const Run r = cli({"fit", "--points", kEx27, "--degree", "2", "--param", "uniform", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject o = r.json();
        const QJsonArray cp = o["control_points"].toArray();
        QCOMPARE(cp.size(), 3);
        QCOMPARE(strings(cp[0].toArray()), QStringList({"-8/7", "46/35"}));
        QCOMPARE(strings(cp[1].toArray()), QStringList({"323/35", "-19/35"}));
        QCOMPARE(strings(cp[2].toArray()), QStringList({"86/35", "116/35"}));
        QCOMPARE(strings(o["params"].toArray()), QStringList({"0", "1/4", "1/2", "3/4", "1"}));
        QCOMPARE(strings(o["MtM"].toArray()[0].toArray()), QStringList({"177/128", "23/64", "17/128"}));
        QCOMPARE(strings(o["M_pinv"].toArray()[1].toArray()), QStringList({"-23/35", "22/35", "37/35", "22/35", "-23/35"}));
        QVERIFY(o["cond"].toDouble() > 1);
        QVERIFY(o.contains("sse"));
    }

    void fitEx28Exact()
    {
        const Run r = cli({"fit", "--points", kEx27, "--degree", "3", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray cp = r.json()["control_points"].toArray();
        QCOMPARE(strings(cp[1].toArray()), QStringList({"-3371/630", "2711/210"}));
        QCOMPARE(strings(cp[2].toArray()), QStringList({"11399/630", "-2539/210"}));
    }

    void fitSolversAgree_data()
    {
        QTest::addColumn<QString>("solver");
        QTest::newRow("qr") << "qr";
        QTest::newRow("svd") << "svd";
        QTest::newRow("normal") << "normal";
    }
    void fitSolversAgree()
    {
        QFETCH(QString, solver);
        const Run r = cli({"fit", "--points", kEx27, "--degree", "2", "--param", "uniform", "--solver", solver, "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray p1 = r.json()["control_points"].toArray()[1].toArray();
        QVERIFY(std::abs(p1[0].toDouble() - 323.0 / 35) < 1e-12);
        QVERIFY(std::abs(p1[1].toDouble() + 19.0 / 35) < 1e-12);
    }

    void fitChordUsesConsecutiveDistances()
    {
        // Ex 2.9's data: d = √10, √10, 4√2, 7√2 (the thesis's (1-7) slip would give √85).
        const Run r = cli({"fit", "--points", kEx27, "--degree", "2", "--param", "chord", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray t = r.json()["params"].toArray();
        const double total = 2 * std::sqrt(10.0) + 11 * std::sqrt(2.0);
        QVERIFY(std::abs(t[1].toDouble() - std::sqrt(10.0) / total) < 1e-14);
        QVERIFY(std::abs(t[3].toDouble() - (2 * std::sqrt(10.0) + 4 * std::sqrt(2.0)) / total) < 1e-14);
        QCOMPARE(t[4].toDouble(), 1.0);
    }

    // Annex III's BezParamProp (issue 33, part 3): d_j = |Q_{j−1}|, from the origin; Ex 2.9's
    // points give |Q_0..Q_3| = 0, √10, √20, √68, so t = 0, 0, √10/Σ, (√10 + √20)/Σ, 1.
    void fitAnnexIIIUsesDistancesFromTheOrigin()
    {
        const Run r = cli({"fit", "--points", kEx27, "--degree", "3", "--param", "annex-iii", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray t = r.json()["params"].toArray();
        const double total = std::sqrt(10.0) + std::sqrt(20.0) + std::sqrt(68.0);
        QCOMPARE(t[1].toDouble(), 0.0);
        QVERIFY(std::abs(t[2].toDouble() - std::sqrt(10.0) / total) < 1e-14);
        QVERIFY(std::abs(t[3].toDouble() - (std::sqrt(10.0) + std::sqrt(20.0)) / total) < 1e-14);
        // Irrational |Q_1| = √10: no exact fit — it says which distance spoils it — but the t_i
        // in radicals: t_2 = √10/(√10 + 2√5 + 2√17) ≈ 0.199128 (the doubles above), which sympy
        // rationalises to (−145√2 − 195 + 20√85 + 19√170)/161.
        const Run exact = cli({"fit", "--points", kEx27, "--degree", "3", "--param", "annex-iii", "--exact"});
        QCOMPARE(exact.exitCode, 0);
        QVERIFY2(exact.out.contains("|Q_1| = √(10)"), exact.out.constData());
        QVERIFY2(exact.out.contains("t_2 = (−145√2 + 20√85 + 19√170 − 195)/161 ≈ 0.199128"), exact.out.constData());
    }

    // fit --exact --json gives §2.1.3's checks (issue 33, part 4): the four Penrose
    // conditions, and the Hessian 2MᵀM — Ex 2.7's MᵀM as printed, doubled — with positive
    // eigenvalues that sum to its trace, 2·(177 + 68 + 177)/128 = 211/32 (by hand).
    void fitExactChecksPenroseAndTheHessian()
    {
        const Run r = cli({"fit", "--points", kEx27, "--degree", "2", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject j = r.json();
        QCOMPARE(j["penrose"].toArray(), (QJsonArray{true, true, true, true}));
        QCOMPARE(strings(j["hessian"].toArray()[0].toArray()), (QStringList{"177/64", "23/32", "17/64"}));
        double sum = 0;
        for (const QJsonValue& v : j["hessian_eigenvalues"].toArray()) {
            QVERIFY(v.toDouble() > 0);
            sum += v.toDouble();
        }
        QVERIFY(std::abs(sum - 211.0 / 32) < 1e-13);
        const Run text = cli({"fit", "--points", kEx27, "--degree", "2", "--exact"});
        QVERIFY2(text.out.contains("(M⁺M)ᵀ = M⁺M ✓") && text.out.contains("all positive"), text.out.constData());
    }

    // fit --exact with chord lengths (issue 33, part 4): the t_i of Ex 2.9/2.10 are irrational,
    // so the fit is the floating-point one (exit 0, no matrices), with the t_i in radicals —
    // (11√5 − 10)/101 … by hand and by sympy (docs/thesis-errata-checks.py) — and, for the
    // thesis's data, the t_i it prints from d_4 = √85 and printed − right (sympy:
    // 0.004635073328, 0.009270146656, 0.017561617890).
    void fitExactChordGivesParametersInRadicals()
    {
        const Run r = cli({"fit", "--points", kEx27, "--degree", "3", "--param", "chord", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject j = r.json();
        QCOMPARE(strings(j["t_radicals"].toArray()),
                 (QStringList{"0", "(11√5 − 10)/101", "(22√5 − 20)/101", "(14√5 + 24)/101", "1"}));
        QCOMPARE(strings(j["t_printed"].toArray())[1], QStringLiteral("(744√5 − 65√34 − 160√170 + 1540)/4951"));
        const QJsonArray difference = j["t_printed_difference"].toArray();
        QCOMPARE(difference.size(), 5);
        const double expected[] = {0, 0.004635073328, 0.009270146656, 0.017561617890, 0};
        for (int i = 0; i < 5; ++i)
            QVERIFY2(std::abs(difference[i].toDouble() - expected[i]) < 1e-11, qPrintable(QString::number(i)));
        QVERIFY(!j.contains("M")); // nothing exact to show but the parameters
        QVERIFY(std::abs(j["params"].toArray()[1].toDouble() - 0.144522254975) < 1e-12);
        // Other data: the radicals, but nothing printed to compare with.
        const Run other = cli({"fit", "--points", "0,0;1,1;2,3", "--degree", "1", "--param", "chord", "--exact", "--json"});
        QCOMPARE(other.exitCode, 0);
        QCOMPARE(strings(other.json()["t_radicals"].toArray()), (QStringList{"0", "(√10 − 2)/3", "1"})); // √2(√5 − √2)/(5 − 2)
        QVERIFY(!other.json().contains("t_printed"));
        // Without --exact, no radicals.
        const Run plain = cli({"fit", "--points", kEx27, "--degree", "3", "--param", "chord", "--json"});
        QVERIFY(!plain.json().contains("t_radicals"));
    }

    void catmullRomEx213()
    {
        const Run r = cli(
            {"catmull-rom", "--points", kEx213, "--tau", "1/2", "--mode", "open", "--exact", "--json", "--samples", "3"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray segs = r.json()["segments"].toArray();
        QCOMPARE(segs.size(), 4);
        // p_1^n(s) = (3 - 1/2 s - 7/2 s^2 + 3 s^3, 5 - 3/2 s - 7/2 s^2 + 2 s^3)
        QCOMPARE(strings(segs[0].toObject()["x"].toArray()), QStringList({"3", "-1/2", "-7/2", "3"}));
        QCOMPARE(strings(segs[0].toObject()["y"].toArray()), QStringList({"5", "-3/2", "-7/2", "2"}));
        // p_2(s) = (2 + 3/2 s + 6 s^2 - 7/2 s^3, 2 - 5/2 s - 3/2 s^2 + 2 s^3)
        QCOMPARE(strings(segs[1].toObject()["x"].toArray()), QStringList({"2", "3/2", "6", "-7/2"}));
        // p_4^n(s) = (8 + 1/2 s - 7/2 s^2 + 2 s^3, 3 + 5/2 s - 1/2 s^3)
        QCOMPARE(strings(segs[3].toObject()["x"].toArray()), QStringList({"8", "1/2", "-7/2", "2"}));
        QCOMPARE(strings(segs[3].toObject()["y"].toArray()), QStringList({"3", "5/2", "0", "-1/2"}));
        const QJsonArray samples = r.json()["samples"].toArray();
        QCOMPARE(samples.size(), 4 * 3); // S per segment, ends included
        QCOMPARE(strings(samples[0].toArray()), QStringList({"3", "5"}));
        QCOMPARE(strings(samples[11].toArray()), QStringList({"7", "5"}));
    }

    // --exact names every knot's continuity (catmull_rom_analysis.h). The closed curve through
    // Ex 2.13's five points has five knots, q_1 … q_4 and the closing q_0. τ = 1/2: C¹ and G¹
    // at least (Prop 2.3). τ = 0: Def 2.8 gives p′(0) = p′(1) = 0, so the first derivatives agree
    // (C¹) but there is no tangent direction (G⁰ only); p″(1) = −6(p_2 − p_1) of one segment
    // against p″(0) = 6(p_2 − p_1) of the next differ unless the points repeat, so not C².
    void catmullRomKnots()
    {
        const Run half = cli({"catmull-rom", "--points", kEx213, "--tau", "1/2", "--mode", "closed", "--exact", "--json"});
        QCOMPARE(half.exitCode, 0);
        const QJsonArray knots = half.json()["knots"].toArray();
        QCOMPARE(knots.size(), 5);
        for (int i = 0; i < knots.size(); ++i) {
            const QJsonObject k = knots[i].toObject();
            QCOMPARE(k["knot"].toInt(), (i + 1) % 5);
            QVERIFY(k["C"].toInt() >= 1);
            QVERIFY(k["G"].toInt() >= 1);
        }
        const Run zero = cli({"catmull-rom", "--points", kEx213, "--tau", "0", "--exact"});
        QCOMPARE(zero.exitCode, 0);
        const QString text = QString::fromUtf8(zero.out);
        for (const char* knot : {"q_1", "q_2", "q_3"})
            QVERIFY2(text.contains(QStringLiteral("  %1: C^1, G^0\n").arg(QLatin1String(knot))), qPrintable(text));
        QVERIFY(!text.contains(QStringLiteral("q_4:"))); // open: the joins of four segments are q_1 … q_3
        // Without --exact there is no analysis to print.
        const Run doubles = cli({"catmull-rom", "--points", kEx213, "--tau", "0", "--json"});
        QVERIFY(!doubles.json().contains("knots"));
    }

    // "bezier": one entry per segment, b_0 and b_3 the segment's ends (q_i, q_{i+1}), and for
    // the uniform curve b_1 = p_1 + τ(p_2 − p_0)/3, b_2 = p_2 − τ(p_3 − p_1)/3. Ex 2.13, τ = 1/2:
    // p_2 from (q_0, q_1, q_2, q_3): b_1 = (2,2) + ((6,0) − (3,5))/6 = (5/2, 7/6),
    // b_2 = (6,0) − ((8,3) − (2,2))/6 = (5, −1/6); p_1^n from (q_0, q_0, q_1, q_2): b_1 = (3,5) + ((2,2) − (3,5))/6.
    void catmullRomBezier()
    {
        const Run r = cli({"catmull-rom", "--points", kEx213, "--tau", "1/2", "--mode", "closed", "--exact", "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray segs = r.json()["segments"].toArray();
        const QJsonArray bez = r.json()["bezier"].toArray();
        QCOMPARE(segs.size(), 5);
        QCOMPARE(bez.size(), segs.size());
        const QList<QStringList> q{{"3", "5"}, {"2", "2"}, {"6", "0"}, {"8", "3"}, {"7", "5"}};
        for (int i = 0; i < bez.size(); ++i) {
            const QJsonArray b = bez[i].toArray();
            QCOMPARE(b.size(), 4);
            QCOMPARE(strings(b[0].toArray()), q[i]);
            QCOMPARE(strings(b[3].toArray()), q[(i + 1) % 5]);
        }
        QCOMPARE(strings(bez[1].toArray()[1].toArray()), QStringList({"5/2", "7/6"}));
        QCOMPARE(strings(bez[1].toArray()[2].toArray()), QStringList({"5", "-1/6"}));

        const Run open = cli({"catmull-rom", "--points", kEx213, "--tau", "1/2", "--exact", "--json"});
        QCOMPARE(open.exitCode, 0);
        const QJsonArray first = open.json()["bezier"].toArray()[0].toArray();
        QCOMPARE(strings(first[1].toArray()), QStringList({"17/6", "9/2"}));

        // Doubles (centripetal here) give numbers, one entry per segment too.
        const Run c = cli({"catmull-rom", "--points", kEx213, "--alpha", "1/2", "--json"});
        QCOMPARE(c.exitCode, 0);
        const QJsonArray cb = c.json()["bezier"].toArray();
        QCOMPARE(cb.size(), 4);
        QVERIFY(std::abs(cb[3].toArray()[3].toArray()[0].toDouble() - 7.0) < 1e-12); // ends at q_4
        QVERIFY(std::abs(cb[3].toArray()[3].toArray()[1].toDouble() - 5.0) < 1e-12);
    }

    void catmullRomModes_data()
    {
        QTest::addColumn<QString>("mode");
        QTest::addColumn<int>("segments");
        QTest::newRow("open") << "open" << 4;
        QTest::newRow("cyclic") << "cyclic" << 4;
        QTest::newRow("closed") << "closed" << 5;
    }
    void catmullRomModes()
    {
        QFETCH(QString, mode);
        QFETCH(int, segments);
        const Run r = cli({"catmull-rom", "--points", kEx213, "--tau", "0.5", "--mode", mode, "--json"});
        QCOMPARE(r.exitCode, 0);
        const QJsonArray segs = r.json()["segments"].toArray();
        QCOMPARE(segs.size(), segments);
        if (mode == "closed") { // the segment q_4 -> q_0 comes last and ends at q_0
            const QJsonObject last = segs.last().toObject();
            double x = 0, y = 0;
            for (int k = 0; k < 4; ++k) {
                x += last["x"].toArray()[k].toDouble();
                y += last["y"].toArray()[k].toDouble();
            }
            QCOMPARE(x, 3.0);
            QCOMPARE(y, 5.0);
        }
    }

    void catmullRomCentripetal()
    {
        const Run r = cli({"catmull-rom", "--points", "0,0;1,0;1,0;5,3", "--alpha", "1/2", "--json", "--samples", "5"});
        QCOMPARE(r.exitCode, 0); // coincident points: finite output
        QVERIFY(!r.out.contains("null"));
        QVERIFY(!r.out.toLower().contains("nan"));
    }

    void pointsFiles()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QFile csv(dir.filePath("q.csv")), json(dir.filePath("q.json")), bad(dir.filePath("bad.csv"));
        QVERIFY(csv.open(QIODevice::WriteOnly) && json.open(QIODevice::WriteOnly) && bad.open(QIODevice::WriteOnly));
        csv.write("x,y\n0,0\n1,3\n4,2\n# comment\n8,-2\n1,5\n");
        json.write("[[0,0],[1,3],[\"4\",2],[8,-2.0],[1,5]]");
        bad.write("0,0\n1,3\n4,two\n");
        csv.close();
        json.close();
        bad.close();
        for (const QString& f : {csv.fileName(), json.fileName()}) {
            const Run r = cli({"fit", "--points-file", f, "--degree", "2", "--exact", "--json"});
            QCOMPARE(r.exitCode, 0);
            QCOMPARE(strings(r.json()["control_points"].toArray()[0].toArray()), QStringList({"-8/7", "46/35"}));
        }
        const Run r = cli({"fit", "--points-file", bad.fileName(), "--degree", "1"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.startsWith("error:"));
        QVERIFY(r.err.contains("line 3"));
    }

    void humanReadableByDefault()
    {
        const Run r = cli({"demo"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("(2 - 12t - 6t^2 + 52t^3 - 43t^4, 3 + 20t - 96t^2 + 120t^3 - 49t^4)"));
        QVERIFY(r.out.contains("P_1^3(t) = (-1 - 12t + 36t^2 - 30t^3, 8 - 33t + 42t^2 - 19t^3)"));
        const Run fit = cli({"fit", "--points", kEx27, "--degree", "2", "--exact"});
        QCOMPARE(fit.exitCode, 0);
        QVERIFY(fit.out.contains("P_1 = (323/35, -19/35)"));
    }

    // docs/extreme-cases.md, docs/cli.md: bad input is exit 2 with "error: …" on stderr, nothing on stdout.
    void badInput_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("no command") << QStringList{};
        QTest::newRow("unknown command") << QStringList{"frobnicate"};
        QTest::newRow("unknown option") << QStringList{"bezier", "--points", "0,0;1,1", "--t", "0", "--colour", "red"};
        QTest::newRow("missing t") << QStringList{"bezier", "--points", "0,0;1,1"};
        QTest::newRow("reduce one point") << QStringList{"bezier", "--points", "1,1", "--reduce"};
        QTest::newRow("reduce degree 41") << QStringList{"bezier", "--points", QString("0,0;").repeated(41) + "1,1", "--reduce"};
        QTest::newRow("reduce NaN") << QStringList{"bezier", "--points", "0,0;nan,1", "--reduce"};
        QTest::newRow("missing value") << QStringList{"bezier", "--points", "0,0;1,1", "--t"};
        QTest::newRow("NaN point") << QStringList{"bezier", "--points", "0,0;nan,1", "--t", "0.5"};
        QTest::newRow("inf point") << QStringList{"bezier", "--points", "0,0;1,inf", "--t", "0.5"};
        QTest::newRow("garbage point") << QStringList{"bezier", "--points", "0,0;1;2", "--t", "0.5"};
        QTest::newRow("garbage t") << QStringList{"bezier", "--points", "0,0;1,1", "--t", "half"};
        QTest::newRow("NaN t") << QStringList{"bezier", "--points", "0,0;1,1", "--t", "nan"};
        QTest::newRow("zero denominator") << QStringList{"bezier", "--points", "0,0;1/0,1", "--t", "0"};
        QTest::newRow("empty points") << QStringList{"bezier", "--points", "", "--t", "0"};
        QTest::newRow("both point sources") << QStringList{"bezier", "--points", "0,0", "--points-file", "x", "--t", "0"};
        QTest::newRow("missing file") << QStringList{"fit", "--points-file", "/nonexistent/q.csv", "--degree", "1"};
        QTest::newRow("negative degree") << QStringList{"bernstein", "--degree", "-1", "--t", "0"};
        QTest::newRow("fractional degree") << QStringList{"bernstein", "--degree", "3/2", "--t", "0"};
        QTest::newRow("huge degree") << QStringList{"bernstein", "--degree", "100000", "--t", "0"};
        QTest::newRow("degree >= points") << QStringList{"fit", "--points", kEx27, "--degree", "5"};
        QTest::newRow("too few points") << QStringList{"fit", "--points", "1,1", "--degree", "0"};
        QTest::newRow("bad param") << QStringList{"fit", "--points", kEx27, "--degree", "2", "--param", "arc"};
        QTest::newRow("bad solver") << QStringList{"fit", "--points", kEx27, "--degree", "2", "--solver", "lu"};
        QTest::newRow("exact centripetal, irrational")
            << QStringList{"fit", "--points", kEx27, "--degree", "2", "--param", "centripetal", "--exact"};
        QTest::newRow("normal eq. singular")
            << QStringList{"fit", "--points", "0,0;0,0;0,0;1,1", "--degree", "2", "--param", "chord", "--solver", "normal"};
        QTest::newRow("too few for cyclic") << QStringList{"catmull-rom", "--points", "0,0;1,1", "--mode", "cyclic"};
        QTest::newRow("one point") << QStringList{"catmull-rom", "--points", "0,0"};
        QTest::newRow("bad mode") << QStringList{"catmull-rom", "--points", kEx213, "--mode", "spiral"};
        QTest::newRow("alpha out of range") << QStringList{"catmull-rom", "--points", kEx213, "--alpha", "2"};
        QTest::newRow("exact centripetal") << QStringList{"catmull-rom", "--points", kEx213, "--alpha", "1/2", "--exact"};
        QTest::newRow("one sample") << QStringList{"catmull-rom", "--points", kEx213, "--samples", "1"};
        QTest::newRow("repeated option") << QStringList{"fit", "--points", kEx27, "--degree", "2", "--degree", "3"};
    }
    void badInput() { verifyRowIsRefused(OutputOnRefusal::Empty); }

    // docs/extreme-cases.md: extreme but valid input gives a finite answer (exit 0, no NaN/null).
    void extremeButValid_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("huge coordinates") << QStringList{"fit",      "--points", "1e9,1e9;2e9,-1e9;3e9,1e9;4e9,0",
                                                         "--degree", "2",        "--param",
                                                         "chord",    "--json"};
        QTest::newRow("tiny coordinates") << QStringList{"fit",         "--points", "1e-9,1e-9;2e-9,-1e-9;3e-9,1e-9;4e-9,0",
                                                         "--degree",    "2",        "--param",
                                                         "centripetal", "--json"};
        QTest::newRow("coincident, chord, qr")
            << QStringList{"fit", "--points", "0,0;0,0;1,1;1,1;2,0", "--degree", "2", "--param", "chord", "--json"};
        QTest::newRow("all coincident") << QStringList{"fit", "--points", "3,3;3,3;3,3", "--degree",
                                                       "1",   "--param",  "chord",       "--json"};
        QTest::newRow("collinear") << QStringList{"fit", "--points", "0,0;1,1;2,2;3,3;4,4", "--degree", "3", "--json"};
        QTest::newRow("degree 60") << QStringList{"bernstein", "--degree", "60", "--t", "0.3", "--json"};
        QTest::newRow("tau -10") << QStringList{"catmull-rom", "--points", kEx213, "--tau", "-10", "--json"};
        QTest::newRow("tau 10") << QStringList{"catmull-rom", "--points", kEx213, "--tau", "10", "--mode", "closed", "--json"};
        QTest::newRow("iterate") << QStringList{"fit",     "--points", kEx27,       "--degree", "3",
                                                "--param", "chord",    "--iterate", "--json"};
        QTest::newRow("t outside [0,1]") << QStringList{"bezier", "--points", kEx22, "--t", "3", "--json"};
    }
    void extremeButValid()
    {
        QFETCH(QStringList, args);
        const Run r = cli(args);
        QCOMPARE(r.exitCode, 0);
        QVERIFY(!r.json().isEmpty());
        QVERIFY2(!r.out.contains("null") && !r.out.toLower().contains("nan") && !r.out.contains("inf"), r.out.constData());
    }

    // --points-file is read with a bound (core/base/input_limits.h): a device that never ends
    // is refused at 64 MB, a folder is named as one, not as a file without points.
    void pointsFileBounded()
    {
        const Run zero = cli({"bezier", "--points-file", "/dev/zero", "--t", "0"});
        QCOMPARE(zero.exitCode, 2);
        QVERIFY2(zero.err.startsWith("error: ") && zero.err.contains("larger than 64 MB"), zero.err.constData());
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const Run folder = cli({"fit", "--points-file", dir.path(), "--degree", "1"});
        QCOMPARE(folder.exitCode, 2);
        QVERIFY2(folder.err.startsWith("error: ") && folder.err.contains("is a folder"), folder.err.constData());
        QVERIFY(!folder.err.contains("no points"));
    }

    // A CSV saved with a UTF-8 byte-order mark reads as the same points.
    void pointsFileWithByteOrderMark()
    {
        QTemporaryDir dir;
        const QString csv = writeFile(dir, "bom.csv", "\xEF\xBB\xBFx,y\n0,0\n1,3\n4,2\n8,-2\n1,5\n");
        QVERIFY(!csv.isEmpty());
        const Run r = cli({"fit", "--points-file", csv, "--degree", "2", "--exact", "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(strings(r.json()["control_points"].toArray()[0].toArray()), QStringList({"-8/7", "46/35"}));
    }

    // The argument check of fit --degree states the fit's real maximum, and the usage agrees.
    void fitDegreeStatesTheRealMaximum()
    {
        QString pts;
        for (int i = 0; i <= 160; ++i)
            pts += QString("%1,%2;").arg(i).arg(i % 7);
        const Run r = cli({"fit", "--points", pts, "--degree", "150"});
        QCOMPARE(r.exitCode, 2);
        const QRegularExpression range(QStringLiteral("\\(0 to (\\d+)\\)"));
        const auto m = range.match(QString::fromUtf8(r.err));
        QVERIFY2(m.hasMatch(), r.err.constData());
        const int maximum = m.captured(1).toInt();
        QVERIFY2(maximum < 150, r.err.constData());
        // That maximum is accepted (given enough points), one more is not.
        const Run most = cli({"fit", "--points", pts, "--degree", QString::number(maximum), "--json"});
        QVERIFY2(!most.err.contains("out of range") && !most.err.contains("maximum"), most.err.constData());
        const Run help = cli({"fit", "--help"});
        QCOMPARE(help.exitCode, 0);
        QVERIFY2(help.out.contains(m.captured(0).toUtf8()), help.out.constData());
    }

    // fit --iterate is bounded (kMaxCliFitWork, least_squares_fit.h): 4 000 points at degree
    // 100 with its 50 corrections are (1 + 50) · 4000 · 101² ≈ 2.1e9 units, refused at once
    // with exit 2 and what to lower; before, it ran for minutes. Without --iterate, and at a
    // lower degree, the same points are fitted.
    void fitIterateIsBounded()
    {
        QTemporaryDir dir;
        QString csv;
        for (int i = 0; i < 4000; ++i) {
            const double s = i / 3999.0;
            csv += QString("%1,%2\n").arg(std::cos(5 * s) + s, 0, 'g', 17).arg(std::sin(4 * s) - s * s, 0, 'g', 17);
        }
        const QString file = writeFile(dir, "many.csv", csv.toUtf8());
        QVERIFY(!file.isEmpty());
        const double work = 51.0 * 4000 * 101 * 101;
        QVERIFY(work > granota::kMaxCliFitWork);
        const Run refused = cli({"fit", "--points-file", file, "--degree", "100", "--iterate"});
        QCOMPARE(refused.exitCode, 2);
        QVERIFY2(refused.err.startsWith("error: --iterate on 4000 points at degree 100 is too much work"),
                 refused.err.constData());
        QVERIFY2(refused.err.contains("lower the degree"), refused.err.constData());
        QCOMPARE(refused.err.count('\n'), 1);
        QVERIFY(refused.out.isEmpty());
        const Run plain = cli({"fit", "--points-file", file, "--degree", "100", "--json"});
        QVERIFY2(plain.exitCode == 0, plain.err.constData());
        const Run lower = cli({"fit", "--points-file", file, "--degree", "5", "--iterate", "--json"});
        QVERIFY2(lower.exitCode == 0, lower.err.constData());
    }

    // Text from the user inside a message has its control characters escaped: an ESC in a
    // CSV cell or an argument cannot clear the terminal through stderr.
    void messagesEscapeControlCharacters_data()
    {
        QTest::addColumn<QStringList>("args");
        const QString evil = QStringLiteral("\033[2J\033]0;pwned\007x");
        QTest::newRow("CSV cell") << QStringList{"fit", "--points-file", "CSV", "--degree", "1"};
        QTest::newRow("command") << QStringList{evil};
        QTest::newRow("argument") << QStringList{"bezier", evil};
        QTest::newRow("option") << QStringList{"bezier", "--" + evil};
        QTest::newRow("points") << QStringList{"bezier", "--points", evil + ",1", "--t", "0"};
        QTest::newRow("t") << QStringList{"bezier", "--points", "0,0;1,1", "--t", evil};
        QTest::newRow("degree") << QStringList{"bernstein", "--degree", evil, "--t", "0"};
        QTest::newRow("choice") << QStringList{"fit", "--points", kEx27, "--degree", "2", "--param", evil};
        QTest::newRow("file name") << QStringList{"fit", "--points-file", "/nonexistent/" + evil, "--degree", "1"};
        QTest::newRow("scene") << QStringList{"simulate", "--scene", evil};
        QTest::newRow("solver") << QStringList{"simulate", "--scene", "frog", "--solver", evil};
        QTest::newRow("set key") << QStringList{"simulate", "--scene", "frog", "--set", evil + "=1"};
        QTest::newRow("set value") << QStringList{"simulate", "--scene", "frog", "--set", "gravity=" + evil};
        QTest::newRow("set form") << QStringList{"simulate", "--scene", "frog", "--set", evil};
        QTest::newRow("trace") << QStringList{"simulate", "--scene", "frog", "--steps", "1", "--trace", "/nonexistent/" + evil};
    }
    void messagesEscapeControlCharacters()
    {
        QFETCH(QStringList, args);
        QTemporaryDir dir;
        const QString csv = writeFile(dir, "evil.csv", "\033[2J\033]0;pwned\007x,1\n2,3\n");
        QVERIFY(!csv.isEmpty());
        args.replaceInStrings(QRegularExpression("^CSV$"), csv);
        const Run r = cli(args);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("error: ") && r.err.endsWith("\n"), r.err.constData());
        const QByteArray line = r.err.chopped(1);
        for (char c : line)
            QVERIFY2(static_cast<unsigned char>(c) >= 0x20, r.err.toPercentEncoding(" :'/()=,").constData());
        QVERIFY2(line.contains("\\x1b"), line.constData());
    }

    // Every command's answer, written to a full disk: the failed write is said on stderr,
    // with the reason, and the status is 2 like every other error (docs/cli.md, --help).
    void failedWriteSaysSo_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("demo") << QStringList{"demo"};
        QTest::newRow("demo json") << QStringList{"demo", "--json"};
        QTest::newRow("help") << QStringList{"--help"};
        QTest::newRow("command help") << QStringList{"fit", "--help"};
        QTest::newRow("bezier") << QStringList{"bezier", "--points", kEx22, "--t", "1/2", "--exact"};
        QTest::newRow("bernstein json") << QStringList{"bernstein", "--degree", "4", "--t", "1/3", "--json"};
        QTest::newRow("fit") << QStringList{"fit", "--points", kEx27, "--degree", "2"};
        QTest::newRow("catmull-rom") << QStringList{"catmull-rom", "--points", kEx213};
        QTest::newRow("simulate") << QStringList{"simulate", "--scene", "frog", "--steps", "1"};
        QTest::newRow("bench") << QStringList{"bench", "--scene", "frog", "--steps", "1"};
    }
    void failedWriteSaysSo()
    {
        QFETCH(QStringList, args);
        const Run r = runCliToFile(QStringLiteral("/dev/full"), args);
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(r.err, QByteArray("error: cannot write the output: No space left on device\n"));
    }

    // A file the command writes itself: the trace, on a full disk.
    void failedTraceWriteSaysSo()
    {
        const Run r = cli({"simulate", "--scene", "frog", "--steps", "10", "--trace", "/dev/full"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("error: cannot write the trace to '/dev/full': No space left on device"), r.err.constData());
        QVERIFY(r.out.isEmpty());
    }

    // Input whose doubles overflow: every number printed is finite. Without --exact the
    // answer is exit 2 naming the value too large for a double (and suggesting --exact);
    // with --exact the exact answer, exit 0, with no nan/inf/null anywhere.
    void hostileDoubles_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<bool>("exactWorks"); // fit needs cond₂(M) in double even with --exact
        const QString digits10000 = QString(10000, QLatin1Char('9'));
        QTest::newRow("t 1e200") << QStringList{"bezier", "--points", "0,0;1,3;4,5", "--t", "1e200"} << true;
        QTest::newRow("point 1e400") << QStringList{"bezier", "--points", "0,0;1e400,3", "--t", "0.5"} << true;
        QTest::newRow("t 1e400") << QStringList{"bezier", "--points", "0,0;1,3", "--t", "1e400"} << true;
        QTest::newRow("point 1e309") << QStringList{"bezier", "--points", "0,0;1e309,1;2,2", "--t", "1/2"} << true;
        QTest::newRow("10000 digits") << QStringList{"bezier", "--points", "0,0;" + digits10000 + ",1", "--t", "1/2"} << true;
        QTest::newRow("tangent overflows") << QStringList{"bezier", "--points", "-1e308,0;1e308,0", "--t", "1/2"} << true;
        QTest::newRow("tangent at 0") << QStringList{"bezier", "--points", "0,0;1e308,1e308;-1e308,1e308", "--t", "0"} << true;
        QTest::newRow("bernstein 200 at 1e10") << QStringList{"bernstein", "--degree", "200", "--t", "1e10"} << true;
        QTest::newRow("bernstein t 1e400") << QStringList{"bernstein", "--degree", "3", "--t", "1e400"} << true;
        QTest::newRow("catmull-rom 1e309") << QStringList{"catmull-rom", "--points", "0,0;1e309,1;2,2"} << true;
        QTest::newRow("catmull-rom overflows") << QStringList{"catmull-rom", "--points", "-1e308,0;1e308,0;-1e308,0"} << true;
        QTest::newRow("fit 1e309") << QStringList{"fit", "--points", "0,0;1e309,1;2,2", "--degree", "1"} << false;
    }
    void hostileDoubles()
    {
        QFETCH(QStringList, args);
        QFETCH(bool, exactWorks);
        for (const QStringList& extra : {QStringList{}, QStringList{"--json"}}) {
            const Run r = cli(args + extra);
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.startsWith("error: ") && r.err.count('\n') == 1, r.err.constData());
            QVERIFY2(r.err.contains("too large for a double"), r.err.constData());
            if (exactWorks)
                QVERIFY2(r.err.contains("--exact"), r.err.constData());
            QVERIFY(r.out.isEmpty());
            if (!exactWorks)
                continue;
            const Run e = cli(args + extra + QStringList{"--exact"});
            QVERIFY2(e.exitCode == 0, e.err.constData());
            const QByteArray out = e.out.toLower();
            QVERIFY2(!out.contains("nan") && !out.contains("inf") && !out.contains("null"), e.out.left(2000).constData());
            if (!extra.isEmpty())
                QVERIFY(!e.json().isEmpty());
        }
    }

    void highDegreeFitWarns()
    {
        QString pts;
        for (int i = 0; i <= 80; ++i)
            pts += QString("%1,%2;").arg(i).arg(std::sin(i * 0.2), 0, 'g', 17);
        const Run r = cli({"fit", "--points", pts, "--degree", "60", "--json"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.json()["cond"].toDouble() > 1e10);
        QVERIFY(!r.json()["warnings"].toArray().isEmpty());
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
