// granota-cli report NAME|all --out DIR (docs/work-precision.md): one CSV with the machine and the build in
// its header, and an SVG and a PNG plot per report, from the real binary.
#include "cli_runner.h"
#include "energy_drift_closed_forms.h"
#include "full_disk.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QSet>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QTest>
#include "tests/test_main.h"

#include <cmath>

class TestCliReport : public QObject {
    Q_OBJECT

private slots:
    void allReportsWriteCsvSvgAndPng()
    {
        QTemporaryDir dir;
        const CliRun run = runCli({"report", "all", "--quick", "--out", dir.path()});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.err.isEmpty(), run.err.constData());
        for (const char* name :
             {"curve-sampling", "catmull-rom-sampling", "bezier-evaluation", "least-squares", "integrators", "soft-body"}) {
            const QString base = QDir(dir.path()).filePath(QString::fromLatin1(name));
            QFile csv(base + QStringLiteral(".csv"));
            QVERIFY2(csv.open(QIODevice::ReadOnly | QIODevice::Text), name);
            const QStringList lines = QString::fromUtf8(csv.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
            QVERIFY(lines.first().startsWith(QStringLiteral("# report: %1").arg(QString::fromLatin1(name))));
            // The sampling reports are plotted against their points, the others against run time.
            const bool sampling = QByteArray(name).endsWith("sampling");
            QVERIFY2(lines.contains(sampling ? QStringLiteral("# x axis: knob") : QStringLiteral("# x axis: seconds")), name);
            bool machine = false, build = false;
            int rows = 0;
            for (const QString& line : lines) {
                machine |= line.startsWith(QStringLiteral("# machine: "));
                build |= line.startsWith(QStringLiteral("# build: "));
                if (!line.startsWith(QLatin1Char('#')) && !line.startsWith(QStringLiteral("method,"))) {
                    const QStringList f = line.split(QLatin1Char(','));
                    QCOMPARE(f.size(), 4);
                    bool ok1 = false, ok2 = false, ok3 = false;
                    QVERIFY(f[1].toDouble(&ok1) > 0 && f[2].toDouble(&ok2) > 0 && f[3].toDouble(&ok3) > 0);
                    QVERIFY(ok1 && ok2 && ok3);
                    ++rows;
                }
            }
            QVERIFY(machine && build);
            QVERIFY(rows >= 5);
            QVERIFY(QSvgRenderer(base + QStringLiteral(".svg")).isValid());
            const QImage png(base + QStringLiteral(".png"));
            QCOMPARE(png.size(), QSize(900, 600));
        }
    }

    // energy-drift (issue 33, part 5): `method,step,energy_error`, the five methods, and values
    // against the closed forms of tests/energy_drift_closed_forms.h (9 significant digits; 10⁵
    // steps move the phase by about 1e-11).
    void energyDriftWritesItsSeries()
    {
        QTemporaryDir dir;
        const CliRun run = runCli({"report", "energy-drift", "--out", dir.path()});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.err.isEmpty(), run.err.constData());
        QVERIFY2(run.out.contains("energy-drift: ") && run.out.contains("symplectic"), run.out.constData());
        const QString base = QDir(dir.path()).filePath(QStringLiteral("energy-drift"));
        QFile csv(base + QStringLiteral(".csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly | QIODevice::Text));
        const QStringList lines = QString::fromUtf8(csv.readAll()).split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QVERIFY(lines.contains(QStringLiteral("# x axis: step")));
        const auto header = lines.indexOf(QStringLiteral("method,step,energy_error"));
        QVERIFY(header > 0);
        QSet<QString> methods;
        int checked = 0;
        for (const QString& line : lines.mid(header + 1)) {
            const QStringList f = line.split(QLatin1Char(','));
            QCOMPARE(f.size(), 3);
            methods.insert(f[0]);
            bool ok1 = false, ok2 = false;
            const double step = f[1].toDouble(&ok1), value = f[2].toDouble(&ok2);
            QVERIFY(ok1 && ok2 && std::isfinite(value));
            if (step == 1 || step == 10 || step == 1000 || step == 100000) {
                const double expected = energy_drift::closedForm(f[0].toStdString(), step);
                QVERIFY2(std::fabs(value - expected) <= 1e-10 + 1e-8 * std::fabs(expected),
                         qPrintable(line + QStringLiteral(": closed form %1").arg(expected, 0, 'g', 12)));
                ++checked;
            }
        }
        QCOMPARE(methods, QSet<QString>({"explicit Euler", "semi-implicit Euler", "Verlet", "Verlet (Annex II start)", "RK4"}));
        QCOMPARE(checked, 5 * 4 - 1); // explicit Euler's series ends before step 10⁵ (its energy overflows)
        QVERIFY(lines.contains(QStringLiteral("RK4,100000,-0.00138619114"))); // g^(10⁵) − 1, the issue's −1.39e-3
        QVERIFY(QSvgRenderer(base + QStringLiteral(".svg")).isValid());
        QCOMPARE(QImage(base + QStringLiteral(".png")).size(), QSize(900, 600));
    }

    // A report file that cannot be written (each of the three, on a full disk: a link to
    // /dev/full) is an error naming the file and the reason, not a silent success.
    void failedFileWriteSaysSo_data()
    {
        QTest::addColumn<QString>("extension");
        QTest::newRow("csv") << QStringLiteral(".csv");
        QTest::newRow("svg") << QStringLiteral(".svg");
        QTest::newRow("png") << QStringLiteral(".png");
    }
    void failedFileWriteSaysSo()
    {
        QFETCH(QString, extension);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString file = dir.filePath(QStringLiteral("integrators") + extension);
        QVERIFY(QFile::link(QStringLiteral("/dev/full"), file));
        const CliRun run = runCli({"report", "integrators", "--quick", "--out", dir.path()});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.startsWith("error: cannot write ") && run.err.contains(("integrators" + extension).toUtf8()) &&
                     run.err.contains("No space left on device"),
                 run.err.constData());
        QVERIFY(run.out.isEmpty());
    }

    // On a real full disk (a tmpfs filled to the byte) an old report file is kept byte for
    // byte, and no hidden file is left beside it.
    void aFullDiskKeepsTheOldFile()
    {
        FullDisk disk;
        if (!disk.mounted())
            QSKIP(FullDisk::whyNot());
        const QByteArray old = "the old report, which must survive\n";
        QVERIFY(disk.put(QStringLiteral("integrators.csv"), old));
        QVERIFY(disk.fill());
        const CliRun run = runCli({"report", "integrators", "--quick", "--out", disk.filePath(QString())});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.startsWith("error: cannot write ") && run.err.endsWith(": No space left on device\n"),
                 run.err.constData());
        QCOMPARE(disk.read(QStringLiteral("integrators.csv")), old);
        QCOMPARE(QDir(disk.filePath(QString())).entryList(QDir::Files | QDir::Hidden, QDir::Name),
                 QStringList({QStringLiteral("filler"), QStringLiteral("integrators.csv")}));
    }

    // A report name with terminal escapes is echoed escaped, not as raw bytes.
    void unknownNameIsEscaped()
    {
        const CliRun run = runCli({"report", QStringLiteral("\033[2Jdragons"), "--out", "/tmp/x"});
        QCOMPARE(run.exitCode, 2);
        QVERIFY2(run.err.startsWith("error: ") && run.err.contains("'\\x1b[2Jdragons'"), run.err.constData());
        QVERIFY(!run.err.contains('\033'));
    }

    void badInput_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("no name") << QStringList{"report", "--out", "/tmp/x"};
        QTest::newRow("unknown name") << QStringList{"report", "dragons", "--out", "/tmp/x"};
        QTest::newRow("no out") << QStringList{"report", "integrators"};
        QTest::newRow("two names") << QStringList{"report", "integrators", "soft-body", "--out", "/tmp/x"};
        QTest::newRow("unwritable") << QStringList{"report", "integrators", "--quick", "--out", "/proc/granota"};
    }
    void badInput() { verifyRowIsRefused(); }
};

GRANOTA_TEST_MAIN(TestCliReport)
#include "test_cli_report.moc"
