// Nothing the user made is lost (issue 12, items 1 to 6, 8 and 15): whatever Granota saves
// it opens, a refused document changes neither the tabs nor their undo history, malformed
// documents are refused with a message, an autosave that was not recovered is never
// deleted or overwritten, recovery goes back into the document the autosave belongs to,
// a failing autosave says so, and devices are read with a bound.
#include "core/base/input_limits.h"
#include "ui/shell/autosave.h"
#include "ui/shell/document.h"
#include "ui/fit/fit_tab.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "ui/common/point_editor.h"
#include "ui/common/tab_page.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QRegularExpression>
#include <QMessageBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include "tests/test_main.h"
#include <QUndoStack>

#include <cmath>

using granota::ui::Autosave;
using granota::ui::MainWindow;
using granota::ui::TabPage;

namespace {

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void writeAll(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    QCOMPARE(f.write(bytes), bytes.size());
}

QByteArray state(const MainWindow& w) { return granota::ui::serializeDocument(w.tabs(), QString()); }

/// A document (or autosave) whose De Casteljau and fitting parts are valid and whose frog
/// part names a scene that does not exist.
QByteArray halfValidDocument(const QString& autosaveOf = QString(), bool withAutosave = false)
{
    QJsonObject tabs;
    tabs.insert("decasteljau", QJsonObject{{"points", QJsonArray{QJsonArray{0, 0}, QJsonArray{7, 7}, QJsonArray{9, 1}}}});
    tabs.insert("fit", QJsonObject{{"points", QJsonArray{QJsonArray{0, 0}, QJsonArray{1, 3}, QJsonArray{4, 4}, QJsonArray{6, 1}}},
                                   {"degree", 2}});
    tabs.insert("frog", QJsonObject{{"scene", "no-such-scene"}});
    QJsonObject root{{"format", "granota"}, {"version", 1}, {"current", "fit"}, {"tabs", tabs}};
    if (withAutosave)
        root.insert("autosave", QJsonObject{{"file", autosaveOf}});
    return QJsonDocument(root).toJson();
}

/// An autosave another session left: written under the folder with no live lock.
QString leaveOrphan(const QByteArray& bytes, const QString& name)
{
    const QString path = QDir(Autosave::defaultFolder()).filePath(name + ".granota");
    QDir().mkpath(Autosave::defaultFolder());
    writeAll(path, bytes);
    return path;
}

void clearAutosaves() { QDir(Autosave::defaultFolder()).removeRecursively(); }

} // namespace

class TestGuiDocumentSafety : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("GranotaTest"));
        QCoreApplication::setApplicationName(QStringLiteral("GranotaDocumentSafety"));
        granota::ui::setLanguage(QStringLiteral("en"), false);
    }
    void init() { clearAutosaves(); }

    // 1. Whatever Granota saves, it opens: the largest import, saved and autosaved.
    void theLargestDocumentRoundTrips()
    {
        QTemporaryDir dir;
        const QString csv = dir.filePath("big.csv");
        {
            QFile f(csv);
            QVERIFY(f.open(QIODevice::WriteOnly));
            QByteArray text;
            text.reserve(int(granota::kMaxDataPoints) * 40);
            for (std::size_t i = 0; i < granota::kMaxDataPoints; ++i)
                text += QByteArray::number(double(i) / 1000.0 + 0.123456789, 'g', 12) + ',' +
                        QByteArray::number(std::sin(double(i) * 1e-3) * 123.456789, 'g', 12) + '\n';
            f.write(text);
        }
        MainWindow window;
        auto* fit = qobject_cast<granota::ui::FitTab*>(window.tab("fit"));
        QVERIFY(fit);
        QString error;
        QVERIFY2(fit->importFile(csv, &error), qPrintable(error));
        // At the limit the editor adds no point: no Save can write what Open refuses.
        fit->pointEditor()->insertPoint(0, granota::Point(-1, -1));
        QCOMPARE(fit->pointEditor()->points().size(), granota::kMaxDataPoints);
        const QString file = dir.filePath("big.granota");
        QVERIFY2(window.saveFile(file, &error), qPrintable(error));
        QVERIFY(QFileInfo(file).size() < qint64(granota::kMaxFileBytes));
        QVERIFY(window.autosave());
        QVERIFY(QFileInfo(window.autosaveFile()).size() < qint64(granota::kMaxFileBytes));

        MainWindow reopened;
        QVERIFY2(reopened.openFile(file, &error), qPrintable(error));
        QCOMPARE(state(reopened), state(window));
        MainWindow fromAutosave;
        QVERIFY2(fromAutosave.openFile(window.autosaveFile(), &error), qPrintable(error));
        QCOMPARE(state(fromAutosave), state(window));
    }
    void moreDataPointsThanTheLimitAreRefused()
    {
        QJsonArray points;
        for (std::size_t i = 0; i <= granota::kMaxDataPoints; ++i)
            points.append(QJsonArray{double(i), 1.0});
        const QByteArray doc = QJsonDocument(QJsonObject{{"format", "granota"},
                                                         {"version", 1},
                                                         {"tabs", QJsonObject{{"fit", QJsonObject{{"points", points}}}}}})
                                   .toJson(QJsonDocument::Compact);
        QTemporaryDir dir;
        writeAll(dir.filePath("over.granota"), doc);
        MainWindow window;
        const QByteArray before = state(window);
        QString error;
        QVERIFY(!window.openFile(dir.filePath("over.granota"), &error));
        QVERIFY2(error.contains(QString::number(granota::kMaxDataPoints)), qPrintable(error));
        QCOMPARE(state(window), before);
    }

    // 4. A refused document leaves undo untouched.
    void aRefusedDocumentLeavesUndoAlone()
    {
        MainWindow window;
        QVERIFY(window.loadExample("2.8"));
        QVERIFY(window.loadExample("2.2"));
        QVector<int> counts;
        for (TabPage* page : window.tabs())
            counts << page->undoStack()->count();
        const QByteArray before = state(window);
        QTemporaryDir dir;
        writeAll(dir.filePath("half.granota"), halfValidDocument());
        QString error;
        QVERIFY(!window.openFile(dir.filePath("half.granota"), &error));
        QVERIFY2(error.contains("no-such-scene"), qPrintable(error));
        QCOMPARE(state(window), before);
        for (int i = 0; i < window.tabs().size(); ++i)
            QCOMPARE(window.tabs()[i]->undoStack()->count(), counts[i]);
        // Undo takes back the user's own last step (Ex 2.8), not the refused file's points.
        window.tab("fit")->undoStack()->undo();
        MainWindow fresh;
        QCOMPARE(window.tab("fit")->saveState(), fresh.tab("fit")->saveState());
    }

    // 5 and 15. Malformed documents are refused with a message that says what is wrong.
    void malformedDocumentsAreRefused_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::addColumn<QString>("message");
        const QByteArray head = R"({"format": "granota", "version": 1, )";
        QTest::newRow("tabs a number") << head + R"("tabs": 5})"
                                       << "\"tabs\"";
        QTest::newRow("tabs a list") << head + R"("tabs": [1, 2]})"
                                     << "\"tabs\"";
        QTest::newRow("no tabs") << QByteArray(R"({"format": "granota", "version": 1})") << "\"tabs\"";
        QTest::newRow("frog a number") << head + R"("tabs": {"frog": 5}})"
                                       << "not an object";
        QTest::newRow("fit a string") << head + R"("tabs": {"fit": "x"}})"
                                      << "not an object";
        QTest::newRow("a JSON list") << QByteArray("[1, 2, 3]") << "JSON list";
        QTest::newRow("version a string") << QByteArray(R"({"format": "granota", "version": "1", "tabs": {}})")
                                          << "not a whole number";
        QTest::newRow("version 1.5") << QByteArray(R"({"format": "granota", "version": 1.5, "tabs": {}})")
                                     << "not a whole number";
        // Issue 32, item 9: a file cut short is named so, at the byte it stops, in place of
        // the parser's jargon ("invalid termination by number (at byte 73)").
        const QByteArray whole = head + R"("tabs": {"fit": {"points": [[0, 0], [1, 3], [2, 1.25]], "degree": 1}}})";
        for (const int cut : {10, 30, 61, 73, static_cast<int>(whole.size()) - 1})
            QTest::newRow(qPrintable(QStringLiteral("cut at %1").arg(cut)))
                << whole.left(cut) << QStringLiteral("cut off at byte %1.").arg(cut);
        QTest::newRow("empty") << QByteArray("  \n") << "the file is empty";
        QTest::newRow("a wrong byte") << QByteArray("{\"format\": granota}") << "not JSON at byte 11 (line 1)";
    }
    void malformedDocumentsAreRefused()
    {
        QFETCH(QByteArray, bytes);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString file = dir.filePath("bad.granota");
        writeAll(file, bytes);
        MainWindow window;
        QVERIFY(window.loadExample("2.3"));
        const QByteArray before = state(window);
        QString error;
        QVERIFY(!window.openFile(file, &error));
        QVERIFY2(error.contains(message), qPrintable(error));
        QVERIFY2(!error.contains("no error occurred") && !error.contains("-1"), qPrintable(error));
        QCOMPARE(state(window), before);
        QVERIFY(window.currentFile() != file);
    }

    // 8. Devices and folders are refused, quickly and with a message.
    void devicesAndFoldersAreRefused_data()
    {
        QTest::addColumn<QString>("path");
        QTest::addColumn<QString>("message");
        QTest::newRow("/dev/zero") << "/dev/zero"
                                   << "larger than 64 MB";
        QTest::newRow("/dev/urandom") << "/dev/urandom"
                                      << "larger than 64 MB";
        QTest::newRow("a folder") << QDir::tempPath() << "is a folder";
    }
    void devicesAndFoldersAreRefused()
    {
        QFETCH(QString, path);
        QFETCH(QString, message);
        MainWindow window;
        const QByteArray before = state(window);
        QString error;
        QVERIFY(!window.openFile(path, &error));
        QVERIFY2(error.contains(message), qPrintable(error));
        auto* fit = qobject_cast<granota::ui::FitTab*>(window.tab("fit"));
        error.clear();
        QVERIFY(!fit->importFile(path, &error));
        QVERIFY2(error.contains(message), qPrintable(error));
        QCOMPARE(state(window), before);
    }

    // 2. A recovery that cannot take everything keeps the autosave and takes the valid tabs.
    void aPartlyRefusedAutosaveRecoversTheValidTabsAndIsKept()
    {
        const QByteArray bytes = halfValidDocument(QString(), true);
        const QString orphan = leaveOrphan(bytes, "crashed");
        QString kept;
        {
            MainWindow window;
            const auto candidates = window.recoverableAutosaves();
            QCOMPARE(candidates.size(), 1);
            QCOMPARE(candidates.front().path, QFileInfo(orphan).absoluteFilePath());
            const MainWindow::RecoveryOutcome outcome = window.recoverAutosave(orphan);
            QVERIFY(outcome.recovered);
            QVERIFY(!outcome.complete);
            QVERIFY2(outcome.message.contains("Frog") && outcome.message.contains("no-such-scene"), qPrintable(outcome.message));
            QVERIFY(window.isModified());
            const QJsonArray points = window.tab("decasteljau")->saveState().value("points").toArray();
            QCOMPARE(points.size(), 3);
            QCOMPARE(points[1].toArray()[0].toDouble(), 7.0);
            // The whole autosave is kept, byte for byte, where no autosave writes.
            QVERIFY(!QFile::exists(orphan));
            const QRegularExpressionMatch m = QRegularExpression("“([^”]+)”\\.$").match(outcome.message);
            QVERIFY2(m.hasMatch(), qPrintable(outcome.message));
            kept = m.captured(1);
            QCOMPARE(readAll(kept), bytes);
            // The autosave timer and a clean close leave it alone.
            QVERIFY(window.autosave());
            QVERIFY(window.autosaveFile() != kept);
            QCOMPARE(readAll(kept), bytes);
        }
        QCOMPARE(readAll(kept), bytes);
        MainWindow next; // a kept file is not offered again at every start
        QVERIFY(next.recoverableAutosaves().isEmpty() || next.recoverableAutosaves().front().path != kept);
    }
    void anUnreadableAutosaveIsKeptAndChangesNothing_data()
    {
        QTest::addColumn<QByteArray>("bytes");
        QTest::newRow("garbage") << QByteArray("\x01\x02\x03 not a document");
        QTest::newRow("truncated") << halfValidDocument(QString(), true).left(120);
        QTest::newRow("every tab refused") << QByteArray(
            R"({"format": "granota", "version": 1, "tabs": {"frog": {"scene": "nope"}}})");
    }
    void anUnreadableAutosaveIsKeptAndChangesNothing()
    {
        QFETCH(QByteArray, bytes);
        const QString orphan = leaveOrphan(bytes, "broken");
        MainWindow window;
        const QByteArray before = state(window);
        const MainWindow::RecoveryOutcome outcome = window.recoverAutosave(orphan);
        QVERIFY(!outcome.recovered);
        QVERIFY(!window.isModified());
        QCOMPARE(state(window), before);
        const QRegularExpressionMatch m = QRegularExpression("“([^”]+)”\\.$").match(outcome.message);
        QVERIFY2(m.hasMatch(), qPrintable(outcome.message));
        QCOMPARE(readAll(m.captured(1)), bytes);
        window.close(); // unmodified: closes without asking
        QCOMPARE(readAll(m.captured(1)), bytes);
    }
    void aRunningSessionsAutosaveIsNotAnOrphan()
    {
        MainWindow other;
        QVERIFY(other.loadExample("2.2"));
        QVERIFY(other.autosave());
        MainWindow window;
        for (const granota::ui::Orphan& o : window.recoverableAutosaves())
            QVERIFY(o.path != other.autosaveFile());
        // A clean close of one window removes its own autosave only.
        const QString orphan = leaveOrphan(halfValidDocument(QString(), true), "crashed");
        window.close();
        QVERIFY(QFile::exists(orphan));
        QVERIFY(QFile::exists(other.autosaveFile()));
    }

    // 3. Recovery restores into the document the autosave belongs to, never into another.
    void recoveryGoesBackToItsOwnDocument()
    {
        QTemporaryDir dir;
        const QString a = dir.filePath("A.granota"), b = dir.filePath("B.granota");
        QByteArray bBytes;
        {
            MainWindow maker;
            QString error;
            QVERIFY(maker.loadExample("2.2"));
            QVERIFY(maker.saveFile(a, &error));
            QVERIFY(maker.loadExample("2.3"));
            QVERIFY(maker.saveFile(b, &error));
            QVERIFY(maker.loadExample("2.13")); // unsaved work on B
            QVERIFY(maker.autosave());
            bBytes = state(maker);
        } // crash: B's autosave stays
        const QByteArray aBytes = readAll(a);
        {
            MainWindow onA; // `granota A.granota`
            QString error;
            QVERIFY(onA.openFile(a, &error));
            QVERIFY2(onA.recoverableAutosaves().isEmpty(), "B's autosave offered to a window on A");
            onA.close();
        }
        QCOMPARE(readAll(a), aBytes);
        MainWindow untitled;
        const auto candidates = untitled.recoverableAutosaves();
        QCOMPARE(candidates.size(), 1);
        QCOMPARE(candidates.front().documentFile, QFileInfo(b).absoluteFilePath());
        QVERIFY(untitled.recoverAutosave(candidates.front().path).complete);
        QCOMPARE(untitled.currentFile(), QFileInfo(b).absoluteFilePath());
        QVERIFY(untitled.isModified());
        QCOMPARE(state(untitled), bBytes);
        QString error;
        QVERIFY(untitled.saveFile(untitled.currentFile(), &error)); // Ctrl+S
        QCOMPARE(readAll(a), aBytes);
        MainWindow check;
        QVERIFY(check.openFile(b, &error));
        QCOMPARE(state(check), bBytes);
        QVERIFY(!QFile::exists(candidates.front().path)); // recovered whole and saved: done
    }

    // 6. An autosave that cannot be written says so, once, and keeps saying it in the status bar.
    void aFailingAutosaveSaysSoOnce()
    {
        MainWindow window;
        window.show();
        QVERIFY(window.loadExample("2.2"));
        QVERIFY(QDir().mkpath(window.autosaveFile())); // its path is a directory now
        QVERIFY(!window.autosave());
        QVERIFY(!window.autosaveError().isEmpty());
        QVERIFY(!window.autosave());
        QVERIFY(!window.autosave());
        const auto boxes = window.findChildren<QMessageBox*>("autosaveFailed");
        QCOMPARE(boxes.size(), 1);
        QVERIFY(boxes.front()->isVisible());
        QLabel* warning = nullptr;
        for (QLabel* l : window.statusBar()->findChildren<QLabel*>())
            if (l->text().contains("Not autosaved"))
                warning = l;
        QVERIFY(warning && warning->isVisible());
        QVERIFY(QDir(window.autosaveFile()).removeRecursively());
        QVERIFY(window.autosave());
        QVERIFY(window.autosaveError().isEmpty());
        QVERIFY(!warning->isVisible());
    }
};

GRANOTA_TEST_MAIN(TestGuiDocumentSafety)
#include "test_gui_document_safety.moc"
