#pragma once
/// \file main_window.h
/// Granota's main window: one tab per part of the thesis (docs/tabs.md), the document (save,
/// open, recent files, autosave and recovery), exports (docs/tabs.md), the Examples menu,
/// languages and presentation mode (docs/classroom.md).

#include <QFont>
#include <QMainWindow>
#include <QVector>

#include "ui/shell/autosave.h"

#include <memory>

class QAction;
class QActionGroup;
class QLabel;
class QMenu;
class QSplitter;
class QTabWidget;
class QTimer;
class QUndoGroup;

namespace granota::ui {

class TabPage;
class FrogTab;
class WorkPrecisionPanel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Tab keys (docs/classroom.md): decasteljau, bernstein, fit, catmull-rom, frog.
    bool showTab(const QString& key);
    TabPage* tab(const QString& key) const;
    TabPage* currentTab() const;
    const QVector<TabPage*>& tabs() const { return m_pages; }
    FrogTab* frogTab() const;

    /// Loads worked example `id` ("2.7") into its tab and shows the tab. False if unknown.
    bool loadExample(const QString& id);

    /// File operations without dialogs (the menu actions and the tests use them).
    bool openFile(const QString& file, QString* error);
    bool saveFile(const QString& file, QString* error);
    QString currentFile() const { return m_file; }
    bool isModified() const { return m_modified; }

    /// Exports the current tab's view: format png, svg, pdf, csv or tikz. Empty or a message.
    QString exportCurrent(const QString& format, const QString& file, int dpi = 96);

    /// Presentation mode: larger text and lines; `fullScreen` false keeps the window's size
    /// (screenshots of presentation mode at 1280×800).
    void setPresentation(bool on, bool fullScreen = true);

    /// The work-precision section below each tab (docs/work-precision.md), hidden until asked for.
    WorkPrecisionPanel* workPrecisionPanel(const QString& key) const;
    void setWorkPrecisionVisible(bool visible);
    bool workPrecisionVisible() const;
    bool presentation() const { return m_presentation; }

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
    /// Recovers an orphan autosave into this window: every valid tab, under the name of the
    /// document it belongs to. What could not be taken stays on disk, moved aside.
    RecoveryOutcome recoverAutosave(const QString& orphanPath);
    /// Asks, for each recoverable autosave, whether to recover it, keep it for later or
    /// discard it.
    void offerRecovery();

protected:
    void closeEvent(QCloseEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void createActions();
    void createMenus();
    void retranslate();
    void setModified(bool modified);
    void updateTitle();
    bool maybeSave();
    void newDocument();
    void openDialog();
    bool saveDialog(bool saveAs);
    void exportDialog(const QString& format);
    void exportFramesDialog();
    void rememberRecent(const QString& file);
    void rebuildRecentMenu();
    void showMessage(const QString& text);
    void showGuide();
    void showAbout();

    QTabWidget* m_tabs = nullptr;
    QVector<TabPage*> m_pages;
    QVector<WorkPrecisionPanel*> m_reports; ///< one per tab, below it in a splitter
    QVector<QSplitter*> m_splitters;
    QUndoGroup* m_undoGroup = nullptr;
    QLabel* m_cursorLabel = nullptr;
    QTimer* m_autosaveTimer = nullptr;
    std::unique_ptr<Autosave> m_autosave;
    QString m_autosaveError;
    QLabel* m_autosaveWarning = nullptr;
    QString m_file;
    bool m_modified = false;
    bool m_autosaveDirty = false;
    bool m_presentation = false;
    QFont m_normalFont;

    QMenu *m_fileMenu = nullptr, *m_recentMenu = nullptr, *m_exportMenu = nullptr, *m_editMenu = nullptr,
          *m_viewMenu = nullptr, *m_examplesMenu = nullptr, *m_languageMenu = nullptr, *m_helpMenu = nullptr;
    QAction *m_new = nullptr, *m_open = nullptr, *m_save = nullptr, *m_saveAs = nullptr, *m_quit = nullptr;
    QAction *m_exportPng = nullptr, *m_exportSvg = nullptr, *m_exportPdf = nullptr, *m_exportCsv = nullptr,
            *m_exportTikz = nullptr, *m_exportFrames = nullptr;
    QAction *m_undo = nullptr, *m_redo = nullptr;
    QAction* m_reportsAction = nullptr;
    QAction *m_presentationAction = nullptr, *m_zoomIn = nullptr, *m_zoomOut = nullptr, *m_fit = nullptr;
    QAction *m_catalan = nullptr, *m_english = nullptr;
    QAction *m_guide = nullptr, *m_about = nullptr;
    QVector<QAction*> m_tabActions;
    QVector<QAction*> m_exampleActions;
};

} // namespace granota::ui
