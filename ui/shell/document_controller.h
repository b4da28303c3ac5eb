#pragma once
/// \file document_controller.h
/// The document of one window (docs/documents-and-autosave.md): which file it is, whether it
/// has unsaved changes, New, Open, Save and Save As with their dialogs, the recent files, the
/// autosave every 20 s with its warning, and the recovery of what ended sessions left.
///
/// The main window owns one (a child QObject) and keeps the menus, the tabs and the wiring:
/// its File actions call this class, its title and status bar show what this class says.
/// The controller reads and fills the window's tabs through the window (tabs(), currentTab(),
/// showTab()); the bytes themselves are written and read by document.h, the autosave file
/// and its lock are autosave.h.

#include "ui/shell/autosave.h"

#include <QByteArray>
#include <QDateTime>
#include <QObject>
#include <QString>
#include <QVector>

#include <memory>

class QLabel;
class QMenu;
class QTimer;

namespace granota::ui {

class MainWindow;

class DocumentController : public QObject {
    Q_OBJECT
public:
    /// Starts `window`'s autosave (a red warning in its status bar while it fails), fills
    /// `recentMenu` from the settings, and follows every tab's documentChanged().
    DocumentController(MainWindow* window, QMenu* recentMenu);
    ~DocumentController() override;

    /// The document's file (absolute), empty for Untitled.
    QString currentFile() const { return m_file; }
    /// Unsaved changes: the title shows “*”.
    bool isModified() const { return m_modified; }
    void setModified(bool modified);

    /// File operations without dialogs (the menu actions and the tests use them). A save
    /// replaces the file whole (ui/files/user_file.h): when it fails, the file on disk is
    /// as it was, the window keeps its changes and `error` says why.
    bool openFile(const QString& file, QString* error);
    bool saveFile(const QString& file, QString* error);
    /// The document's file was changed on disk since this window opened or saved it (by
    /// another window, another program): a different content, not only a new time stamp.
    /// False for Untitled and for a file that is gone.
    bool changedOnDisk() const;
    /// Says, without blocking, that `error` kept a document from opening (a double-click
    /// on a bad file opens the window with this message).
    void showOpenError(const QString& error);

    /// File ▸ New, Open…, Save and Save As…, with their dialogs. The Save As dialog adds
    /// “.granota” to a name typed without it before it asks about replacing a file; Save asks
    /// before replacing a file that changedOnDisk().
    void newDocument();
    void openDialog();
    bool saveDialog(bool saveAs);
    /// If there are unsaved changes, asks whether to save them: true if the caller may go
    /// on (nothing unsaved, saved, or discarded), false if the user cancelled or the save failed.
    bool maybeSave();
    /// The window is about to close: maybeSave(), and then this window's autosave has done
    /// its work and is removed. False: the window stays open.
    bool maybeClose();

    /// The window's title and the recent files again, in the current language.
    void retranslate();

    /// This window's autosave (ui/shell/autosave.h: one file per window, locked while it lives).
    QString autosaveFile() const;
    /// Writes the autosave now (the timer does it every 20 s while there are unsaved edits).
    /// If it cannot be written the window says so, once, and keeps a warning in the status
    /// bar until a write succeeds. False if it failed.
    bool autosave();
    /// The last autosave failure, empty once a write succeeded.
    QString autosaveError() const { return m_autosaveError; }
    /// The autosaves of ended sessions this window may recover: those of its document if it
    /// has one, else all of them. Newest first.
    QVector<Orphan> recoverableAutosaves() const;
    /// What recovering an autosave did, and the message shown to the user.
    struct RecoveryOutcome {
        bool recovered = false; ///< some tab took its part; the window is modified
        bool complete = false;  ///< every tab did, and the orphan's work is now this window's
        QString message;
    };
    /// Recovers an orphan autosave into the window: every valid tab, under the name of the
    /// document it belongs to. What could not be taken stays on disk, moved aside.
    RecoveryOutcome recoverAutosave(const QString& orphanPath);
    /// Asks, for each recoverable autosave, whether to recover it, keep it for later or
    /// discard it.
    void offerRecovery();

signals:
    /// A message for the window's status bar.
    void message(const QString& text);

private:
    void updateTitle();
    /// Remembers what the document's file holds now (its size, time and content hash).
    void rememberDiskState(const QByteArray& bytes);
    /// changedOnDisk(): asks whether to replace it, save elsewhere or cancel. True: go on.
    bool confirmOverwriteOfChangedFile(QString* file);
    /// The Save As dialog (with “.granota” as its default suffix): a name, or empty.
    QString askDocumentName();
    void rememberRecent(const QString& file);
    void rebuildRecentMenu();

    MainWindow* m_window;
    QMenu* m_recentMenu;
    QTimer* m_autosaveTimer = nullptr;
    std::unique_ptr<Autosave> m_autosave;
    QString m_autosaveError;
    QLabel* m_autosaveWarning = nullptr;
    QString m_file;
    /// What m_file held when this window last read or wrote it.
    struct DiskState {
        qint64 size = -1;
        QDateTime modified;
        QByteArray hash;
    } m_disk;
    bool m_modified = false;
    bool m_autosaveDirty = false;
};

} // namespace granota::ui
