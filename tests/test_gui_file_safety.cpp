// Nothing lost, second round (issue 32, items 1 to 4 and 9), in the window: a save, an
// autosave, every export and a screenshot onto a full disk keep the old file byte for byte
// and say why; Save As with a name typed without “.granota” asks before replacing
// “name.granota”; Save asks before replacing a file changed on disk since it was read;
// pipes are refused; an orphan autosave is offered by one window at a time and never named
// as kept when it is gone. The expected bytes are those the test wrote before the failure.
#include "full_disk.h"
#include "ui/fit/fit_tab.h"
#include "ui/shell/autosave.h"
#include "ui/shell/document.h"
#include "ui/shell/document_controller.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QLineEdit>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include "tests/gui_timeouts.h"
#include "tests/test_main.h"

#include <functional>
#include <sys/stat.h>
#include <utime.h>

using granota::ui::Autosave;
using granota::ui::MainWindow;

namespace {

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<missing>");
}

bool writeAll(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

/// Answers the modal windows that come up while `action` runs: `answer` is called with the
/// active modal window at every turn of the event loop the dialog runs (every 10 ms) until
/// it returns false (done); it keeps its own state to act once on each.
void answerModals(const std::function<bool(QWidget*)>& answer, const std::function<void()>& action)
{
    bool done = false;
    QTimer poll;
    poll.setInterval(10);
    QObject::connect(&poll, &QTimer::timeout, [&] {
        QWidget* modal = QApplication::activeModalWidget();
        if (!done && modal && modal->isVisible())
            done = !answer(modal);
    });
    poll.start();
    action();
    poll.stop();
}

QPushButton* buttonWithText(QMessageBox* box, const QString& text)
{
    for (QAbstractButton* b : box->buttons())
        if (b->text().remove(QLatin1Char('&')) == text)
            return qobject_cast<QPushButton*>(b);
    return nullptr;
}

void clearAutosaves() { QDir(Autosave::defaultFolder()).removeRecursively(); }

} // namespace

class TestGuiFileSafety : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("GranotaTest"));
        QCoreApplication::setApplicationName(QStringLiteral("GranotaFileSafety"));
        granota::ui::setLanguage(QStringLiteral("en"), false);
    }
    void init() { clearAutosaves(); }

    // 1. Ctrl+S onto a full disk: Qt 6.4's QSaveFile emptied a small document and said it
    // had saved it. Now the file stays, the window keeps its “*” and the reason is given.
    void aSaveOntoAFullDiskKeepsTheFileAndTheChanges()
    {
        FullDisk disk;
        if (!disk.mounted())
            QSKIP(FullDisk::whyNot());
        MainWindow window;
        const QString path = disk.filePath("lesson.granota");
        QString error;
        QVERIFY2(window.saveFile(path, &error), qPrintable(error));
        const QByteArray saved = readAll(path);
        QVERIFY(saved.size() < 16 * 1024); // the size at which QSaveFile's buffer hid the failure
        QVERIFY(window.loadExample(QStringLiteral("2.2")));
        QVERIFY(window.isModified());
        QVERIFY(disk.fill());
        QVERIFY(!window.saveFile(path, &error));
        QVERIFY2(error.contains("there is no space left on the disk") && error.contains("unchanged"), qPrintable(error));
        QCOMPARE(readAll(path), saved);
        QVERIFY(window.isModified());
        QVERIFY(window.windowTitle().contains(QLatin1Char('*')));
    }
    void anAutosaveOntoAFullDiskKeepsTheLastOne()
    {
        FullDisk disk;
        if (!disk.mounted())
            QSKIP(FullDisk::whyNot());
        Autosave autosave(disk.filePath("autosave"));
        QString error;
        QVERIFY2(autosave.write("{\"the\": \"last good autosave\"}", &error), qPrintable(error));
        const QByteArray good = readAll(autosave.path());
        QVERIFY(disk.fill());
        QVERIFY(!autosave.write(QByteArray(300, 'x'), &error));
        QVERIFY2(error.contains("there is no space left on the disk"), qPrintable(error));
        QCOMPARE(readAll(autosave.path()), good);
    }
    void everyExportOntoAFullDiskKeepsTheOldFile_data()
    {
        QTest::addColumn<QString>("format");
        for (const char* f : {"png", "svg", "pdf", "csv", "tikz"})
            QTest::newRow(f) << QString::fromLatin1(f);
    }
    void everyExportOntoAFullDiskKeepsTheOldFile()
    {
        QFETCH(QString, format);
        FullDisk disk;
        if (!disk.mounted())
            QSKIP(FullDisk::whyNot());
        MainWindow window;
        window.resize(800, 600);
        QVERIFY(window.loadExample(QStringLiteral("2.2")));
        const QString path = disk.filePath("figure." + format);
        const QByteArray old = "the figure of last year's slides";
        QVERIFY(disk.put("figure." + format, old));
        QVERIFY(disk.fill());
        const QString error = window.exportCurrent(format, path);
        QVERIFY2(error.contains("there is no space left on the disk"), qPrintable(error));
        QCOMPARE(readAll(path), old);
    }
    void aScreenshotOntoAFullDiskKeepsTheOldFile()
    {
        FullDisk disk;
        if (!disk.mounted())
            QSKIP(FullDisk::whyNot());
        const QByteArray old = "last week's screenshot";
        QVERIFY(disk.put("shot.png", old));
        QVERIFY(disk.fill());
        QProcess granota;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("QT_QPA_PLATFORM", "offscreen");
        granota.setProcessEnvironment(env);
        granota.start(GRANOTA_GUI_PATH, {"--lang", "en", "--size", "400x300", "--screenshot", disk.filePath("shot.png")});
        QVERIFY(granota.waitForFinished(kEventWaitMs * 4));
        QCOMPARE(granota.exitCode(), 2);
        QVERIFY2(granota.readAllStandardError().contains("there is no space left on the disk"), "no reason given");
        QCOMPARE(disk.read("shot.png"), old); // it was a broken 4096-byte PNG
    }

    // 2. “lesson” typed in Save As is “lesson.granota”: the dialog asks before replacing it.
    void saveAsWithoutTheSuffixAsksBeforeReplacing()
    {
        QTemporaryDir dir;
        const QString lesson = dir.filePath("lesson.granota");
        MainWindow window;
        QString error;
        QVERIFY(window.saveFile(lesson, &error));
        const QByteArray before = readAll(lesson);
        QVERIFY(window.loadExample(QStringLiteral("2.3")));
        QString question;
        int step = 0; // 0: type the name; 1: the question; 2: back in the dialog
        answerModals(
            [&](QWidget* modal) {
                if (auto* dialog = qobject_cast<QFileDialog*>(modal)) {
                    if (step == 0) {
                        dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))->setText(QStringLiteral("lesson"));
                        QMetaObject::invokeMethod(dialog, "accept", Qt::QueuedConnection);
                        step = 1;
                    } else if (step == 2) {
                        dialog->reject(); // not replaced: give up
                        return false;
                    }
                } else if (auto* box = qobject_cast<QMessageBox*>(modal); box && step == 1) {
                    question = box->text();
                    box->button(QMessageBox::No)->click();
                    step = 2;
                }
                return true;
            },
            [&] { QVERIFY(!window.document()->saveDialog(true)); });
        QVERIFY2(question.contains("lesson.granota"), qPrintable("asked: " + question));
        QCOMPARE(readAll(lesson), before);
        QVERIFY(window.isModified());
        // A new name gets the suffix and is saved.
        answerModals(
            [&](QWidget* modal) {
                auto* dialog = qobject_cast<QFileDialog*>(modal);
                if (!dialog)
                    return true;
                dialog->findChild<QLineEdit*>(QStringLiteral("fileNameEdit"))->setText(QStringLiteral("second"));
                QMetaObject::invokeMethod(dialog, "accept", Qt::QueuedConnection);
                return false;
            },
            [&] { QVERIFY(window.document()->saveDialog(true)); });
        QCOMPARE(window.currentFile(), QFileInfo(dir.filePath("second.granota")).absoluteFilePath());
        QCOMPARE(readAll(dir.filePath("second.granota")),
                 granota::ui::serializeDocument(window.tabs(), QStringLiteral("decasteljau")));
    }

    // 3. Another window (or a script) saved the same file: Save asks before replacing it.
    void saveAsksWhenTheFileChangedOnDisk()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("shared.granota");
        MainWindow mine, other;
        QString error;
        QVERIFY(mine.saveFile(path, &error));
        QVERIFY(other.openFile(path, &error));
        QVERIFY(other.loadExample(QStringLiteral("2.8")));
        QVERIFY(other.saveFile(path, &error));
        const QByteArray theirs = readAll(path);
        QVERIFY(mine.document()->changedOnDisk());
        QVERIFY(mine.loadExample(QStringLiteral("2.2")));
        QString asked;
        const auto answerWith = [&](const QString& button) {
            return [&asked, button](QWidget* modal) {
                auto* box = qobject_cast<QMessageBox*>(modal);
                if (!box || box->objectName() != QLatin1String("changedOnDisk"))
                    return true;
                asked = box->text();
                if (button.isEmpty())
                    box->button(QMessageBox::Cancel)->click();
                else
                    buttonWithText(box, button)->click();
                return false;
            };
        };
        answerModals(answerWith(QString()), [&] { QVERIFY(!mine.document()->saveDialog(false)); });
        QVERIFY2(asked.contains("shared.granota") && asked.contains("changed on disk"), qPrintable(asked));
        QCOMPARE(readAll(path), theirs); // cancelled: their save is kept
        QVERIFY(mine.isModified());
        asked.clear();
        answerModals(answerWith(QStringLiteral("Replace it")), [&] { QVERIFY(mine.document()->saveDialog(false)); });
        QVERIFY(!asked.isEmpty());
        QCOMPARE(readAll(path), granota::ui::serializeDocument(mine.tabs(), QStringLiteral("decasteljau")));
        QVERIFY(!mine.document()->changedOnDisk());
    }
    // A new time stamp with the same bytes (touch, a backup restored) is not a change.
    void aNewTimeStampAloneIsNotAChange()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("touched.granota");
        MainWindow window;
        QString error;
        QVERIFY(window.saveFile(path, &error));
        struct utimbuf later {
            0, 1000000000
        };
        QVERIFY(::utime(QFile::encodeName(path).constData(), &later) == 0);
        QVERIFY(!window.document()->changedOnDisk());
        QVERIFY(writeAll(path, readAll(path) + " ")); // one more byte: a change
        QVERIFY(window.document()->changedOnDisk());
    }

    // 4. A named pipe with no writer blocked File ▸ Open, `granota FIFO` and the import forever.
    void pipesAreRefused()
    {
        QTemporaryDir dir;
        const QString fifo = dir.filePath("lesson.granota");
        QVERIFY(::mkfifo(QFile::encodeName(fifo).constData(), 0600) == 0);
        MainWindow window;
        const QByteArray before = granota::ui::serializeDocument(window.tabs(), QString());
        QString error;
        QVERIFY(!window.openFile(fifo, &error));
        QVERIFY2(error.contains("is a pipe or a device, not a file"), qPrintable(error));
        auto* fit = qobject_cast<granota::ui::FitTab*>(window.tab("fit"));
        error.clear();
        QVERIFY(!fit->importFile(fifo, &error));
        QVERIFY2(error.contains("not a file"), qPrintable(error));
        QCOMPARE(granota::ui::serializeDocument(window.tabs(), QString()), before);
    }

    // 9. A bad document given at start (a double-click) opens the window with the reason.
    void aBadDocumentAtStartIsSaidInTheWindow()
    {
        QTemporaryDir dir;
        const QString bad = dir.filePath("cut.granota");
        QVERIFY(writeAll(bad, "{\"format\": \"granota\", \"vers"));
        MainWindow window;
        window.show();
        QString error;
        QVERIFY(!window.openFile(bad, &error));
        window.showOpenError(error);
        const auto boxes = window.findChildren<QMessageBox*>(QStringLiteral("openFailed"));
        QCOMPARE(boxes.size(), 1);
        QVERIFY(boxes.front()->isVisible());
        QCOMPARE(boxes.front()->text(), error);
        QVERIFY(window.isVisible());
    }
    // 9. While one window offers an orphan, a second one does not offer it too.
    void anOrphanIsOfferedByOneWindowAtATime()
    {
        MainWindow source;
        QVERIFY(source.loadExample(QStringLiteral("2.2")));
        const QByteArray bytes = granota::ui::serializeAutosave(source.tabs(), QStringLiteral("decasteljau"), QString());
        QDir().mkpath(Autosave::defaultFolder());
        const QString orphan = QDir(Autosave::defaultFolder()).filePath("left-by-a-crash.granota");
        QVERIFY(writeAll(orphan, bytes));
        MainWindow first, second;
        QCOMPARE(first.recoverableAutosaves().size(), 1);
        int offeredToSecondMeanwhile = -1;
        answerModals(
            [&](QWidget* modal) {
                auto* box = qobject_cast<QMessageBox*>(modal);
                if (!box)
                    return true;
                offeredToSecondMeanwhile = second.recoverableAutosaves().size();
                buttonWithText(box, QStringLiteral("Keep for later"))->click();
                return false;
            },
            [&] { first.offerRecovery(); });
        QCOMPARE(offeredToSecondMeanwhile, 0);
        QCOMPARE(second.recoverableAutosaves().size(), 1); // kept for later: offered again
        QCOMPARE(readAll(orphan), bytes);
    }
    // 9. An autosave that is gone is never named as “kept”.
    void aVanishedAutosaveIsNotNamedAsKept()
    {
        MainWindow window;
        const QString gone = QDir(Autosave::defaultFolder()).filePath("gone.granota");
        const auto outcome = window.recoverAutosave(gone);
        QVERIFY(!outcome.recovered);
        QVERIFY2(!outcome.message.contains("kept as"), qPrintable(outcome.message));
        QVERIFY2(outcome.message.contains("no longer on disk"), qPrintable(outcome.message));
    }
};

GRANOTA_TEST_MAIN(TestGuiFileSafety)
#include "test_gui_file_safety.moc"
