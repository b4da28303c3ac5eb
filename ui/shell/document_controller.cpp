#include "ui/shell/document_controller.h"

#include "ui/shell/document.h"
#include "ui/files/file_dialogs.h"
#include "ui/shell/main_window.h"
#include "ui/common/tab_page.h"
#include "ui/files/user_file.h"

#include <QApplication>
#include <QCryptographicHash>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>

namespace granota::ui {

// The texts are MainWindow::tr(): they keep the translation context of the main window, where
// they were written first and where translations/granota_*.ts hold them.

namespace {
constexpr int kMaxRecent = 8;
constexpr int kAutosaveMs = 20000;
} // namespace

DocumentController::DocumentController(MainWindow* window, QMenu* recentMenu)
    : QObject(window), m_window(window), m_recentMenu(recentMenu)
{
    for (TabPage* page : m_window->tabs())
        connect(page, &TabPage::documentChanged, this, [this] { setModified(true); });
    rebuildRecentMenu();

    m_autosaveWarning = new QLabel(m_window);
    m_autosaveWarning->setStyleSheet(QStringLiteral("QLabel { color: #b00020; font-weight: bold; }"));
    m_autosaveWarning->hide();
    m_window->statusBar()->addPermanentWidget(m_autosaveWarning);
    m_autosave = std::make_unique<Autosave>();
    m_autosaveTimer = new QTimer(this);
    m_autosaveTimer->setInterval(kAutosaveMs);
    connect(m_autosaveTimer, &QTimer::timeout, this, [this] {
        if (m_autosaveDirty)
            autosave();
    });
    m_autosaveTimer->start();
}

DocumentController::~DocumentController() = default;

void DocumentController::retranslate()
{
    updateTitle();
    rebuildRecentMenu();
}

// ---------------------------------------------------------------- the document

void DocumentController::setModified(bool modified)
{
    m_modified = modified;
    if (modified)
        m_autosaveDirty = true;
    updateTitle();
}

void DocumentController::updateTitle()
{
    const QString name = m_file.isEmpty() ? MainWindow::tr("Untitled") : QFileInfo(m_file).fileName();
    m_window->setWindowTitle(MainWindow::tr("%1%2 — Granota").arg(name, m_modified ? QStringLiteral("*") : QString()));
}

bool DocumentController::maybeSave()
{
    if (!m_modified)
        return true;
    const auto answer = QMessageBox::warning(m_window, MainWindow::tr("Unsaved changes"),
                                             MainWindow::tr("The document has unsaved changes. Save them?"),
                                             QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save)
        return saveDialog(false);
    return answer == QMessageBox::Discard;
}

bool DocumentController::maybeClose()
{
    if (!maybeSave())
        return false;
    m_autosave->remove(); // saved or discarded: this window's copy has done its work
    return true;
}

void DocumentController::newDocument()
{
    if (!maybeSave())
        return;
    // A fresh window's state is the blank document: every tab back to its defaults.
    MainWindow blank;
    const QByteArray defaults = serializeDocument(blank.tabs(), QStringLiteral("decasteljau"));
    QString error, current;
    if (loadDocument(defaults, m_window->tabs(), &error, &current)) {
        for (TabPage* page : m_window->tabs())
            page->undoStack()->clear();
        m_file.clear();
        setModified(false);
        m_window->showTab(current);
    }
}

bool DocumentController::openFile(const QString& file, QString* error)
{
    const std::optional<QByteArray> bytes = readUserFile(file, error);
    if (!bytes)
        return false;
    QString current;
    QApplication::setOverrideCursor(Qt::WaitCursor); // the largest documents take a second or two
    const bool loaded = loadDocument(*bytes, m_window->tabs(), error, &current);
    QApplication::restoreOverrideCursor();
    if (!loaded)
        return false;
    for (TabPage* page : m_window->tabs())
        page->undoStack()->clear();
    m_file = QFileInfo(file).absoluteFilePath();
    rememberDiskState(*bytes);
    setModified(false);
    m_autosaveDirty = false;
    m_autosave->remove(); // the window's work is now the file's
    m_window->showTab(current);
    rememberRecent(file);
    return true;
}

void DocumentController::showOpenError(const QString& error)
{
    auto* box = new QMessageBox(QMessageBox::Warning, MainWindow::tr("Open document"), error, QMessageBox::Ok, m_window);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setObjectName(QStringLiteral("openFailed"));
    box->open();
    emit message(error);
}

bool DocumentController::saveFile(const QString& file, QString* error)
{
    const TabPage* current = m_window->currentTab();
    const QByteArray bytes = serializeDocument(m_window->tabs(), current ? current->key() : QString());
    const bool existed = QFileInfo::exists(file);
    QString reason;
    if (!writeUserFile(file, bytes, &reason)) {
        // Nothing changes: the file on disk as it was, the window modified, the autosave kept.
        *error = existed ? MainWindow::tr("Cannot save “%1”: %2. The file on disk is unchanged, and your changes are "
                                          "still here: save them elsewhere (Save As).")
                               .arg(QDir::toNativeSeparators(file), reason)
                         : MainWindow::tr("Cannot save “%1”: %2. Your changes are still here: save them elsewhere (Save As).")
                               .arg(QDir::toNativeSeparators(file), reason);
        return false;
    }
    m_file = QFileInfo(file).absoluteFilePath();
    rememberDiskState(bytes);
    setModified(false);
    m_autosaveDirty = false;
    m_autosave->remove();
    rememberRecent(file);
    return true;
}

void DocumentController::rememberDiskState(const QByteArray& bytes)
{
    const QFileInfo info(m_file);
    m_disk.size = info.size();
    m_disk.modified = info.lastModified();
    m_disk.hash = QCryptographicHash::hash(bytes, QCryptographicHash::Sha256);
}

bool DocumentController::changedOnDisk() const
{
    if (m_file.isEmpty())
        return false;
    const QFileInfo info(m_file); // read afresh: QFileInfo caches nothing across instances
    if (!info.exists())
        return false; // gone: saving loses nothing
    if (info.size() == m_disk.size && info.lastModified() == m_disk.modified)
        return false;
    // A new time stamp alone (touch, a copy of the same bytes) is not a change.
    QString ignored;
    const std::optional<QByteArray> now = readUserFile(m_file, &ignored);
    return !now || QCryptographicHash::hash(*now, QCryptographicHash::Sha256) != m_disk.hash;
}

bool DocumentController::confirmOverwriteOfChangedFile(QString* file)
{
    if (!changedOnDisk())
        return true;
    QMessageBox box(QMessageBox::Warning, MainWindow::tr("Save document"),
                    MainWindow::tr("“%1” has changed on disk since this window opened or saved it — in another window "
                                   "or another program. Saving replaces those changes with this window's.")
                        .arg(QFileInfo(m_file).fileName()),
                    QMessageBox::NoButton, m_window);
    box.setObjectName(QStringLiteral("changedOnDisk"));
    QPushButton* elsewhere = box.addButton(MainWindow::tr("Save &As…"), QMessageBox::AcceptRole);
    QPushButton* replace = box.addButton(MainWindow::tr("&Replace it"), QMessageBox::DestructiveRole);
    box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(elsewhere);
    box.exec();
    if (box.clickedButton() == replace)
        return true;
    if (box.clickedButton() != elsewhere)
        return false;
    *file = askDocumentName();
    return !file->isEmpty();
}

QString DocumentController::askDocumentName()
{
    QFileDialog dialog(m_window, MainWindow::tr("Save document"), m_file.isEmpty() ? lastFileFolder() : QFileInfo(m_file).path(),
                       MainWindow::tr("Granota documents (*.granota)"));
    dialog.setObjectName(QStringLiteral("saveDocumentDialog"));
    dialog.setAcceptMode(QFileDialog::AcceptSave);
    // Added to a name typed without it before the dialog checks whether the file exists:
    // “lesson” asks before replacing “lesson.granota”.
    dialog.setDefaultSuffix(QStringLiteral("granota"));
    if (dialog.exec() != QDialog::Accepted || dialog.selectedFiles().isEmpty())
        return QString();
    QString file = dialog.selectedFiles().constFirst();
    rememberFileFolder(file);
    if (file.endsWith(QLatin1String(".granota")))
        return file;
    // A platform's own dialog may not add the suffix: add it, and ask as the dialog would.
    file += QLatin1String(".granota");
    if (QFileInfo::exists(file) &&
        QMessageBox::warning(m_window, MainWindow::tr("Save document"),
                             MainWindow::tr("“%1” already exists. Replace it?").arg(QFileInfo(file).fileName()),
                             QMessageBox::Yes | QMessageBox::No, QMessageBox::No) != QMessageBox::Yes)
        return QString();
    return file;
}

void DocumentController::openDialog()
{
    if (!maybeSave())
        return;
    const QString file = openFileName(m_window, MainWindow::tr("Open document"),
                                      MainWindow::tr("Granota documents (*.granota);;All files (*)"));
    if (file.isEmpty())
        return;
    QString error;
    if (!openFile(file, &error))
        QMessageBox::warning(m_window, MainWindow::tr("Open document"), error);
}

bool DocumentController::saveDialog(bool saveAs)
{
    QString file = m_file;
    if (saveAs || file.isEmpty()) {
        file = askDocumentName();
        if (file.isEmpty())
            return false;
    } else if (!confirmOverwriteOfChangedFile(&file)) {
        return false;
    }
    QString error;
    if (!saveFile(file, &error)) {
        QMessageBox::warning(m_window, MainWindow::tr("Save document"), error);
        return false;
    }
    emit message(MainWindow::tr("Saved %1").arg(QFileInfo(file).fileName()));
    return true;
}

// ---------------------------------------------------------------- recent files

void DocumentController::rememberRecent(const QString& file)
{
    QSettings settings;
    QStringList recent = settings.value(QStringLiteral("recentFiles")).toStringList();
    const QString path = QFileInfo(file).absoluteFilePath();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    settings.setValue(QStringLiteral("recentFiles"), recent);
    rebuildRecentMenu();
}

void DocumentController::rebuildRecentMenu()
{
    if (!m_recentMenu)
        return;
    m_recentMenu->clear();
    const QStringList recent = QSettings().value(QStringLiteral("recentFiles")).toStringList();
    for (const QString& file : recent) {
        m_recentMenu
            ->addAction(QFileInfo(file).fileName(), this,
                        [this, file] {
                            if (!maybeSave())
                                return;
                            QString error;
                            if (!openFile(file, &error))
                                QMessageBox::warning(m_window, MainWindow::tr("Open document"), error);
                        })
            ->setToolTip(file);
    }
    m_recentMenu->setEnabled(!recent.isEmpty());
}

// ---------------------------------------------------------------- autosave and recovery

QString DocumentController::autosaveFile() const { return m_autosave->path(); }

bool DocumentController::autosave()
{
    const TabPage* current = m_window->currentTab();
    const QByteArray bytes = serializeAutosave(m_window->tabs(), current ? current->key() : QString(), m_file);
    QString error;
    if (m_autosave->write(bytes, &error)) {
        m_autosaveDirty = false;
        if (!m_autosaveError.isEmpty()) {
            m_autosaveError.clear();
            m_autosaveWarning->hide();
            emit message(MainWindow::tr("The autosave works again."));
        }
        return true;
    }
    const bool first = m_autosaveError.isEmpty();
    m_autosaveError = error;
    m_autosaveWarning->setText(MainWindow::tr("⚠ Not autosaved: save your work"));
    m_autosaveWarning->setToolTip(error);
    m_autosaveWarning->show();
    if (first) { // say it once, without stopping the lesson: a window that does not block
        auto* box = new QMessageBox(QMessageBox::Warning, MainWindow::tr("Autosave failed"),
                                    MainWindow::tr("Granota cannot keep a copy of your unsaved changes: %1\n\n"
                                                   "Save the document (Ctrl+S) to keep them. Granota will keep trying.")
                                        .arg(error),
                                    QMessageBox::Ok, m_window);
        box->setAttribute(Qt::WA_DeleteOnClose);
        box->setObjectName(QStringLiteral("autosaveFailed"));
        box->open();
    }
    return false;
}

QVector<Orphan> DocumentController::recoverableAutosaves() const
{
    QVector<Orphan> out;
    for (const Orphan& orphan : m_autosave->orphans())
        if (m_file.isEmpty() || orphan.documentFile == m_file)
            out.push_back(orphan);
    return out;
}

namespace {

/// Where a kept autosave is, for a message: the place it was moved to, or where it was if
/// it could not be moved; empty if it is on disk at neither (never named as kept unseen).
QString keptWhere(const QString& movedTo, const QString& orphanPath)
{
    for (const QString& path : {movedTo, orphanPath})
        if (!path.isEmpty() && QFileInfo::exists(path))
            return QDir::toNativeSeparators(path);
    return QString();
}

} // namespace

DocumentController::RecoveryOutcome DocumentController::recoverAutosave(const QString& orphanPath)
{
    RecoveryOutcome outcome;
    QString error;
    const std::optional<QByteArray> bytes = readUserFile(orphanPath, &error);
    Recovery r;
    if (bytes)
        r = recoverDocument(*bytes, m_window->tabs());
    else
        r.error = error;
    if (!r.readable || r.recovered.isEmpty()) {
        // Nothing to take: the file is kept, out of the way of later autosaves.
        const QString kept = keptWhere(m_autosave->keepAside(orphanPath), orphanPath);
        const QString reason = r.error.isEmpty() ? MainWindow::tr("no tab's part could be read.") + QLatin1Char('\n') +
                                                       r.refused.join(QLatin1Char('\n'))
                                                 : r.error;
        outcome.message =
            kept.isEmpty() ? MainWindow::tr("The autosave could not be recovered: %1\n\nIt is no longer on disk.").arg(reason)
                           : MainWindow::tr("The autosave could not be recovered: %1\n\nIt is kept as “%2”.").arg(reason, kept);
        return outcome;
    }
    for (TabPage* page : m_window->tabs())
        page->undoStack()->clear();
    if (!r.documentFile.isEmpty()) {
        m_file = r.documentFile; // the work goes back to the document it belongs to
        // The recovered work is on top of the file as it is now: saving asks only if it
        // changes again.
        QString ignored;
        rememberDiskState(readUserFile(m_file, &ignored).value_or(QByteArray()));
    }
    setModified(true);
    m_window->showTab(r.currentTab);
    outcome.recovered = true;
    // The work is in this window now: write this window's autosave before letting go of the
    // orphan, and keep the orphan whole if some of it was refused or the write failed.
    const bool written = autosave();
    if (r.refused.isEmpty() && written) {
        Autosave::discard(orphanPath);
        outcome.complete = true;
        outcome.message = MainWindow::tr("Recovered the unsaved work of the last session.");
        return outcome;
    }
    const QString where = keptWhere(m_autosave->keepAside(orphanPath), orphanPath);
    if (where.isEmpty()) // taken away meanwhile (by hand, another program): never named as kept
        outcome.message = r.refused.isEmpty()
                              ? MainWindow::tr("Recovered the unsaved work of the last session.")
                              : MainWindow::tr("Recovered %1. Not recovered:\n%2")
                                    .arg(QLocale().createSeparatedList(r.recovered), r.refused.join(QLatin1Char('\n')));
    else if (r.refused.isEmpty())
        outcome.message =
            MainWindow::tr("Recovered the unsaved work of the last session. The autosave is kept as “%1”.").arg(where);
    else
        outcome.message = MainWindow::tr("Recovered %1. Not recovered:\n%2\n\nThe whole autosave is kept as “%3”.")
                              .arg(QLocale().createSeparatedList(r.recovered), r.refused.join(QLatin1Char('\n')), where);
    return outcome;
}

void DocumentController::offerRecovery()
{
    for (const Orphan& orphan : recoverableAutosaves()) {
        // Held while it is offered and recovered: another window starting meanwhile does
        // not offer it too (Autosave::orphans() skips locked autosaves).
        const std::unique_ptr<QLockFile> held = Autosave::holdOrphan(orphan.path);
        if (!held)
            continue; // another window has it, or has already recovered it
        const QString when = QLocale().toString(orphan.written, QLocale::ShortFormat);
        const QString question =
            orphan.documentFile.isEmpty()
                ? MainWindow::tr("A Granota session was closed without saving its Untitled document (autosaved %1). Recover it?")
                      .arg(when)
                : MainWindow::tr("A Granota session was closed without saving its changes to “%1” (autosaved %2). Recover them?")
                      .arg(QFileInfo(orphan.documentFile).fileName(), when);
        QMessageBox box(QMessageBox::Question, MainWindow::tr("Recover unsaved work"), question, QMessageBox::NoButton, m_window);
        QPushButton* recover = box.addButton(MainWindow::tr("&Recover"), QMessageBox::AcceptRole);
        QPushButton* later = box.addButton(MainWindow::tr("&Keep for later"), QMessageBox::RejectRole);
        QPushButton* discard = box.addButton(MainWindow::tr("&Discard"), QMessageBox::DestructiveRole);
        box.setDefaultButton(recover);
        box.setEscapeButton(later);
        box.exec();
        if (box.clickedButton() == discard) {
            Autosave::discard(orphan.path);
            continue;
        }
        if (box.clickedButton() != recover)
            continue;
        const RecoveryOutcome outcome = recoverAutosave(orphan.path);
        if (outcome.complete)
            emit message(outcome.message);
        else
            QMessageBox::warning(m_window, MainWindow::tr("Recover unsaved work"), outcome.message);
        if (outcome.recovered)
            return; // the window holds a document now; other autosaves wait for another window
    }
}

} // namespace granota::ui
