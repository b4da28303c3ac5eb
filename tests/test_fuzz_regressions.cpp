// The fuzz targets of the core (tests/fuzz) in the ordinary suite: every committed seed
// and every input that once made a target fail (tests/fuzz/regressions/<target>/) goes
// through the same property check as the fuzzer (tests/fuzz/properties.h), which
// answers with what it found wrong; a bug that comes back fails here by name.
#include "tests/fuzz/properties.h"

#include <QDir>
#include <QFile>
#include <QtTest>

namespace {

const char* const kTargets[] = {"json", "point_list", "rational", "polynomial", "scene"};

/// The committed inputs of a target: its seed corpus and its regressions.
QStringList inputsOf(const QString& target)
{
    QStringList files;
    for (const char* kind : {"corpus", "regressions"}) {
        const QDir dir(QStringLiteral(GRANOTA_SOURCE_DIR "/tests/fuzz/%1/%2").arg(QLatin1String(kind), target));
        for (const QString& name : dir.entryList(QDir::Files, QDir::Name))
            files << dir.filePath(name);
    }
    return files;
}

} // namespace

class TestFuzzRegressions : public QObject {
    Q_OBJECT
private slots:
    void everyTargetHasSeeds()
    {
        for (const char* target : kTargets)
            QVERIFY2(inputsOf(QLatin1String(target)).size() >= 3, target);
    }

    void replay_data()
    {
        QTest::addColumn<QString>("target");
        QTest::addColumn<QString>("file");
        for (const char* target : kTargets)
            for (const QString& file : inputsOf(QLatin1String(target)))
                QTest::newRow(qPrintable(QDir(QStringLiteral(GRANOTA_SOURCE_DIR "/tests/fuzz")).relativeFilePath(file)))
                    << QString::fromLatin1(target) << file;
    }

    void replay()
    {
        QFETCH(QString, target);
        QFETCH(QString, file);
        QFile in(file);
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray bytes = in.readAll();
        const std::string finding = granota::fuzz::checkCore(target.toStdString(), std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
        QVERIFY2(finding.empty(), finding.c_str());
    }
};

QTEST_GUILESS_MAIN(TestFuzzRegressions)
#include "test_fuzz_regressions.moc"
