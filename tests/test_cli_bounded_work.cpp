// Issue 32, item 6: work that was not bounded. Each request below is a few words or a small
// file, and each once ran for minutes or hours, or took gigabytes; each is now refused before
// any of the work, with exit status 2 and a message naming what to lower — or, for those
// that can legitimately finish, finishes. Every run is the real granota-cli under a 4 GB
// address-space limit (docs/extreme-cases.md, "Work").
#include "cli_runner.h"

#include <QtTest>
#include "tests/test_main.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>

#include "tests/asan.h"

namespace {

/// The address space granota-cli gets, in KiB (`ulimit -v`): 4 GB.
[[maybe_unused]] constexpr const char* kAddressSpaceKiB = "4000000";
/// A hang guard only (never a measure of speed): a run refused or accepted here takes
/// seconds; before the fixes some took hours.
constexpr int kHangGuardMs = 300000;

/// granota-cli under `ulimit -v` 4 GB. Under AddressSanitizer (the sanitize preset) the
/// limit is left out, as ASan's shadow memory reserves terabytes of address space; the
/// assertions stay.
CliRun runBounded(const QStringList& args)
{
#ifdef GRANOTA_TEST_ASAN
    return runCli(args, kHangGuardMs);
#else
    return runCliInAddressSpace(QString::fromLatin1(kAddressSpaceKiB), args, kHangGuardMs);
#endif
}

/// Writes `text` to `path`.
bool writeFile(const QString& path, const QByteArray& text)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(text) == text.size();
}

} // namespace

class TestCliBoundedWork : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_thousand, m_millionDigits, m_sixtyMillionDigits;

    /// The files' paths put in for their names in `args`.
    QStringList withFiles(QStringList args) const
    {
        args.replaceInStrings("THOUSAND", m_thousand);
        args.replaceInStrings("SIXTY_MILLION_DIGITS", m_sixtyMillionDigits); // before its tail
        args.replaceInStrings("MILLION_DIGITS", m_millionDigits);
        return args;
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // 1000 points: an open Catmull-Rom curve of 999 segments (Def 2.10).
        QByteArray thousand;
        for (int i = 0; i < 1000; ++i)
            thousand += QByteArray::number(i) + "," + QByteArray::number(i % 7) + "\n";
        m_thousand = m_dir.filePath("thousand.csv");
        QVERIFY(writeFile(m_thousand, thousand));
        // Two points, one coordinate of 10⁶ digits (the most a coordinate may have) or of
        // 6·10⁷ (the issue's: 254 s and 3.3 GB with --exact).
        m_millionDigits = m_dir.filePath("million.csv");
        QVERIFY(writeFile(m_millionDigits, "1" + QByteArray(999999, '3') + ",0\n0,1\n"));
        m_sixtyMillionDigits = m_dir.filePath("sixty-million.csv");
        QVERIFY(writeFile(m_sixtyMillionDigits, "1" + QByteArray(59999999, '3') + ",0\n0,1\n"));
    }

    void refused_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("says");  // what the message states
        QTest::addColumn<QString>("lower"); // what it asks to lower
        // 999 segments × 100 000 samples: 17 GB before, now beyond kMaxCurveSamples (10⁶).
        QTest::newRow("catmull-rom samples")
            << QStringList{"catmull-rom", "--points-file", "THOUSAND", "--samples", "100000", "--json"}
            << "100000 samples on each of 999 segments are 99900000, more than 1000000 in all"
            << "lower --samples";
        // One sample more per segment than fits: 999 × 1002 = 1 000 998 (1001 is accepted below).
        QTest::newRow("catmull-rom samples, just beyond")
            << QStringList{"catmull-rom", "--points-file", "THOUSAND", "--samples", "1002"} << "are 1000998, more than"
            << "lower --samples";
        // The 60-million-digit coordinate: refused as it is read.
        QTest::newRow("catmull-rom 60 million digits")
            << QStringList{"catmull-rom", "--points-file", "SIXTY_MILLION_DIGITS", "--exact"}
            << "x is 60000000 characters long, more than 1000000"
            << "write fewer digits";
        // A million digits (b_P ≈ 3.3·10⁶ bits), one segment, 100 samples written: about
        // 2 · (64 + 600) · 3.3·10⁶ ≈ 4.4·10⁹ bit operations (exact_cost.h), beyond 10⁹.
        QTest::newRow("catmull-rom exact budget")
            << QStringList{"catmull-rom", "--points-file", "MILLION_DIGITS", "--exact", "--samples", "100", "--json"}
            << "the exact Catmull-Rom curve would take about 4.4e9 bit operations, more than 1e9"
            << "lower --samples, the number of points or the digits";
        // About 3 hours: 10⁵ steps of a body whose 5·10⁷ pairs of edges are checked each step.
        QTest::newRow("simulate stable big body")
            << QStringList{"simulate", "--scene", "bounce", "--solver", "stable", "--set", "sides=10000", "--steps", "100000"}
            << "100000 steps of 10000 vertices on the stable solver"
            << "lower --steps";
        // 5000 copies of a 10 000-sided frog: 5·10⁷ vertices, 4.5 GB before the first step.
        QTest::newRow("bench copies") << QStringList{"bench", "--scene", "frog", "--bodies", "5000", "--set", "sides=10000"}
                                      << "5000 copies of 10000 vertices are 50000000, more than 100000 vertices in all"
                                      << "lower --bodies";
        // 10⁸ steps of the stable frog, about 20 µs each: half an hour.
        QTest::newRow("bench steps") << QStringList{"bench", "--scene", "frog", "--solver", "stable", "--steps", "100000000"}
                                     << "100000000 steps of 22 vertices on the stable solver"
                                     << "lower --steps";
        // §4.9's Bézier curve of degree 10 000 sampled at 2000 points: 10⁴·(10⁴ + 1)/2 · 2000
        // ≈ 10¹¹ interpolations, 47 s for --steps 0 before.
        QTest::newRow("bezier outline") << QStringList{"simulate", "--scene",     "bezier",  "--set", "bezier_samples=2000",
                                                       "--set",    "sides=10000", "--steps", "0"}
                                        << "a Bézier curve of degree 10000 sampled at 2000 points"
                                        << "lower sides or bezier_samples";
        // At 20 points the budget (5·10⁸) allows 7070 sides: 7071·7072/2·20 = 500 061 120.
        QTest::newRow("bezier outline, just beyond")
            << QStringList{"simulate", "--scene", "bezier", "--set", "sides=7071", "--steps", "0"}
            << "a Bézier curve of degree 7071 sampled at 20 points"
            << "lower sides or bezier_samples";
    }
    void refused()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, says);
        QFETCH(QString, lower);
        const CliRun r = runBounded(withFiles(args));
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.startsWith("error: "), r.err.constData());
        QVERIFY2(r.err.contains(says.toUtf8()), r.err.constData());
        QVERIFY2(r.err.contains(lower.toUtf8()), r.err.constData());
        QCOMPARE(r.err.count('\n'), 1); // one line
        QVERIFY(r.out.isEmpty());
    }

    void accepted_data()
    {
        QTest::addColumn<QStringList>("args");
        // 999 × 1001 = 999 999 samples: inside (the text form computes none of them).
        QTest::newRow("catmull-rom samples, just inside")
            << QStringList{"catmull-rom", "--points-file", "THOUSAND", "--samples", "1001"};
        // The million digits without samples: 2 · 64 · 3.3·10⁶ ≈ 4.3·10⁸ bit operations.
        QTest::newRow("catmull-rom exact, a million digits")
            << QStringList{"catmull-rom", "--points-file", "MILLION_DIGITS", "--exact"};
        QTest::newRow("simulate stable big body, a few steps")
            << QStringList{"simulate", "--scene", "bounce", "--solver", "stable", "--set", "sides=10000", "--steps", "2"};
        // 5000 frogs of 10 sides: 50 000 vertices, as the seed's `java SeedFrog STEPS 5000`.
        QTest::newRow("bench 5000 frogs") << QStringList{"bench", "--scene", "frog", "--bodies", "5000", "--steps", "10"};
        QTest::newRow("bezier outline, 2000 points")
            << QStringList{"simulate", "--scene", "bezier", "--set", "bezier_samples=2000", "--steps", "0"};
        QTest::newRow("bezier outline, just inside")
            << QStringList{"simulate", "--scene", "bezier", "--set", "sides=7070", "--steps", "0"};
    }
    void accepted()
    {
        QFETCH(QStringList, args);
        const CliRun r = runBounded(withFiles(args));
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(!r.out.isEmpty());
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestCliBoundedWork)
#include "test_cli_bounded_work.moc"
