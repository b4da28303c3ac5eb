// On a Catalan desktop (LC_NUMERIC=ca_ES.UTF-8, decimal comma) every number read from or
// written to a file, a stream or the command line means what it means in the C locale:
// the core's formatters and parsers, the scenes, the point lists, JSON, and the real
// granota-cli's text, JSON, traces and report CSVs.
#include "catalan_locale.h"
#include "cli_runner.h"

#include "core/io/json.h"
#include "core/io/point_list.h"
#include "core/reports/work_precision.h"
#include "core/exact/polynomial_text.h"
#include "core/exact/rational.h"
#include "core/softbody/scenes/scene.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include "tests/test_main.h"

#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace granota;

namespace {

/// Every field of a CSV line read as a C-locale number (from_chars never sees the locale);
/// false when a field is not a number.
bool numbers(const QByteArray& line, QList<double>* out)
{
    for (const QByteArray& field : line.split(',')) {
        const QByteArray f = field.trimmed();
        double v = 0;
        const auto r = std::from_chars(f.constData(), f.constData() + f.size(), v);
        if (r.ec != std::errc() || r.ptr != f.constData() + f.size())
            return false;
        out->append(v);
    }
    return true;
}

} // namespace

class TestCatalanLocale : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY2(enterCatalanLocale(), kMissingCatalan);
        // The fault this file guards against, shown to be live in this process.
        char buf[32];
        std::snprintf(buf, sizeof buf, "%g", 0.5);
        QCOMPARE(QByteArray(buf), QByteArray("0,5"));
    }
    void cleanupTestCase() { std::setlocale(LC_ALL, "C"); }

    void formattersWriteAPoint()
    {
        QCOMPARE(formatDouble(0.5), std::string("0.5"));
        QCOMPARE(formatDouble(-1e-9), std::string("-1e-09"));
        QCOMPARE(formatDouble(0.1 + 0.2), std::string("0.30000000000000004"));
        QCOMPARE(formatDouble(100), std::string("100"));
        QCOMPARE(formatSignificant(8.59183387e-3, 9), std::string("0.00859183387"));
        QCOMPARE(formatSignificant(3.66950989e-08, 2), std::string("3.7e-08"));
        QCOMPARE(formatFixed(2.25, 1), std::string("2.2")); // round half to even, as printf
        QCOMPARE(formatFixed(-0.005, 3), std::string("-0.005"));
    }

    void parsersReadAPoint()
    {
        QCOMPARE(*parseRational("0.25"), frac(1, 4));
        // The nearest double, as from_chars reads the decimal (GMP's get_d() truncates).
        for (const char* text : {"0.1", "0.05688", "2.675", "1e-300", "123456.789"}) {
            double expected = 0;
            std::from_chars(text, text + std::strlen(text), expected);
            QCOMPARE(toDouble(*parseRational(text)), expected);
        }
        QCOMPARE(toDouble(frac(1, 3)), 1.0 / 3.0);
        QCOMPARE(toDouble(frac(-2, 3)), -2.0 / 3.0);
        QVERIFY(!parseRational("0,25"));
        const auto json = Json::parse("[0.5, -1.25e2, 3]");
        QVERIFY(json);
        QCOMPARE(*json->asArray()->at(0).asNumber(), 0.5);
        QCOMPARE(*json->asArray()->at(1).asNumber(), -125.0);
        QCOMPARE(json->dump(), std::string("[0.5,-125,3]"));
        const auto points = parsePointList("0.5,1.5;2,0.1");
        QVERIFY(points);
        QCOMPARE(points->at(0).x, frac(1, 2));
        QCOMPARE(points->at(1).y, frac(1, 10));
        const auto poly = parsePolynomial("0.5 - 1.5t^2");
        QVERIFY(poly);
        QCOMPARE(poly->coefficient(2), frac(-3, 2));
    }

    void everySceneLoadsWithItsDecimals()
    {
        for (const std::string& name : sceneNames()) {
            const auto scene = loadScene(name);
            QVERIFY2(scene, (name + ": " + (scene ? std::string() : scene.error().message)).c_str());
            // Written back and read again: the same scene, decimals included.
            const std::string text = sceneToJson(*scene).dump();
            QVERIFY2(text.find("0,") == std::string::npos || text.find("\"") != std::string::npos, text.c_str());
            const auto again = Json::parse(text);
            QVERIFY(again);
            const auto reread = parseScene(*again);
            QVERIFY2(reread, name.c_str());
            QCOMPARE(sceneToJson(*reread).dump(), text);
        }
        const auto frog = loadScene("frog");
        QVERIFY(frog);
        auto scene = *frog;
        QVERIFY(applySetting(scene, "area_factor=0.025"));
        QVERIFY(sceneToJson(scene).dump().find("\"area_factor\":0.025") != std::string::npos);
    }

    void cliTextAndJsonWriteAPoint()
    {
        const CliRun run = runCliWith(catalanEnvironment(), {"bezier", "--points", "0,0;1,2;3,2;4,0", "--t", "0.3", "--json"});
        QCOMPARE(run.exitCode, 0);
        const QJsonObject o = run.json();
        QVERIFY2(!o.isEmpty(), run.out.constData());
        const QJsonArray point = o.value("point").toArray();
        QCOMPARE(point.size(), 2);
        QVERIFY(std::fabs(point.at(0).toDouble() - 1.116) < 1e-12);
        const CliRun text = runCliWith(catalanEnvironment(), {"fit", "--points", "0,0;1,2.5;2,3;3,1;4,0", "--degree", "2"});
        QCOMPARE(text.exitCode, 0);
        QVERIFY2(text.out.contains("cond₂(M) = "), text.out.constData());
        QVERIFY2(!QString::fromUtf8(text.out).contains(QRegularExpression("\\d,\\d{3}")), text.out.constData());
    }

    void traceIsTheReferenceByteForByte()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("trace.csv");
        const CliRun run = runCliWith(catalanEnvironment(),
                                      {"simulate", "--scene", "frog", "--solver", "seed", "--steps", "600", "--trace", path});
        QCOMPARE(run.exitCode, 0);
        QFile mine(path), reference(QStringLiteral(GRANOTA_SOURCE_DIR "/tests/data/seed_frog_trace.csv"));
        QVERIFY(mine.open(QIODevice::ReadOnly) && reference.open(QIODevice::ReadOnly));
        QVERIFY(mine.readAll() == reference.readAll());
    }

    void reportCsvsParseWithACLocaleReader()
    {
        QTemporaryDir dir;
        const CliRun run = runCliWith(catalanEnvironment(), {"report", "all", "--quick", "--out", dir.path()});
        QCOMPARE(run.exitCode, 0);
        const QStringList csvs = QDir(dir.path()).entryList({"*.csv"});
        QCOMPARE(csvs.size(), static_cast<int>(workPrecisionReportNames().size()));
        for (const QString& name : csvs) {
            QFile f(dir.filePath(name));
            QVERIFY(f.open(QIODevice::ReadOnly));
            int header = -1, rows = 0;
            for (const QByteArray& raw : f.readAll().split('\n')) {
                const QByteArray line = raw.trimmed();
                if (line.isEmpty() || line.startsWith('#'))
                    continue;
                const int fields = static_cast<int>(line.count(',')) + 1;
                if (header < 0) {
                    header = fields;
                    continue;
                }
                QVERIFY2(fields == header, qPrintable(name + ": " + line));
                // The method's name comes first; every field after it is a number.
                QList<double> values;
                QVERIFY2(numbers(line.mid(line.indexOf(',') + 1), &values), qPrintable(name + ": " + line));
                for (double v : values)
                    QVERIFY2(std::isfinite(v), qPrintable(name + ": " + line));
                ++rows;
            }
            QVERIFY2(rows > 0, qPrintable(name));
        }
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestCatalanLocale)
#include "test_catalan_locale.moc"
