#pragma once
// The committed inputs of the fuzz targets, for the ordinary suite's replays
// (test_fuzz_regressions for the core, test_gui_fuzz_regressions for the widgets): each
// target's seed corpus (tests/fuzz/corpus/<target>/) and every input that once made it
// fail (tests/fuzz/regressions/<target>/), one data row each, named by its path, and the
// two checks both replays make of them.
#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QStringList>
#include <QTest>

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace granota::fuzz {

/// The seed corpus and the regressions of `target`.
inline QStringList inputsOf(const QString& target)
{
    QStringList files;
    for (const char* kind : {"corpus", "regressions"}) {
        const QDir dir(QStringLiteral(GRANOTA_SOURCE_DIR "/tests/fuzz/%1/%2").arg(QLatin1String(kind), target));
        for (const QString& name : dir.entryList(QDir::Files, QDir::Name))
            files << dir.filePath(name);
    }
    return files;
}

/// The columns "target" and "file", a row per committed input of each target.
inline void addInputRows(std::initializer_list<const char*> targets)
{
    QTest::addColumn<QString>("target");
    QTest::addColumn<QString>("file");
    for (const char* target : targets)
        for (const QString& file : inputsOf(QLatin1String(target)))
            QTest::newRow(qPrintable(QDir(QStringLiteral(GRANOTA_SOURCE_DIR "/tests/fuzz")).relativeFilePath(file)))
                << QString::fromLatin1(target) << file;
}

/// The bytes of a committed input; nullopt when it cannot be read.
inline std::optional<QByteArray> readInput(const QString& file)
{
    QFile in(file);
    if (!in.open(QIODevice::ReadOnly))
        return std::nullopt;
    return in.readAll();
}

inline std::string_view view(const QByteArray& bytes)
{
    return std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size()));
}

/// Every one of `targets` has at least three committed inputs (a target without seeds is
/// not tested by its replay).
inline void verifyEveryTargetHasSeeds(std::initializer_list<const char*> targets)
{
    for (const char* target : targets)
        QVERIFY2(inputsOf(QLatin1String(target)).size() >= 3, target);
}

/// Replays the current row of addInputRows() through `check` (checkCore or checkUi): the
/// input is read, and the property check finds nothing wrong with it.
inline void replayInputRow(std::string (*check)(std::string_view target, std::string_view input))
{
    QFETCH(QString, target);
    QFETCH(QString, file);
    const auto bytes = readInput(file);
    QVERIFY2(bytes, qPrintable(file));
    const std::string finding = check(target.toStdString(), view(*bytes));
    QVERIFY2(finding.empty(), finding.c_str());
}

} // namespace granota::fuzz
