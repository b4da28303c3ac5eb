#pragma once
/// \file main_window.h
/// Granota's main window: one tab per part of the thesis (docs/tabs.md), the menus, exports
/// (docs/tabs.md), the Examples menu, languages and presentation mode (docs/classroom.md). The
/// document (save, open, recent files, autosave and recovery) is its DocumentController
/// (document_controller.h); the window wires the File menu to it.

#include <QFont>
#include <QMargins>
#include <QMainWindow>
#include <QVector>

#include "ui/shell/document_controller.h"
#include "ui/files/tikz_options.h"

class QAction;
class QActionGroup;
class QLabel;
class QMenu;
class QScrollArea;
class QSplitter;
class QTabWidget;
class QUndoGroup;

namespace granota::ui {

class TabPage;
class FrogTab;
class BlankScreen;
class FocusRing;
class ShortcutsDialog;
class ThesisFiguresDialog;
class WorkPrecisionPanel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Tab keys (docs/classroom.md): decasteljau, bernstein, fit, catmull-rom, frog, bspline.
    bool showTab(const QString& key);
    TabPage* tab(const QString& key) const;
    TabPage* currentTab() const;
    /// Help ▸ Keyboard shortcuts, as rich text: every action's keys, then the canvases' and
    /// the Frog tab's (shortcuts_help.h).
    QString shortcutsHelp() const;
    /// Help ▸ Keyboard shortcuts, shown (made once): the keys in two columns that scroll,
    /// within the screen (shortcuts_dialog.h).
    void showShortcuts();
    const QVector<TabPage*>& tabs() const { return m_pages; }
    FrogTab* frogTab() const;

    /// Loads worked example `id` ("2.7") into its tab and shows the tab. False if unknown.
    bool loadExample(const QString& id);
    /// Help ▸ Thesis figures: the gallery of the thesis's figures (thesis_figures_dialog.h),
    /// beside the window, made once.
    void showThesisFigures();

    /// The window's document: its file, unsaved changes, autosave and recovery
    /// (document_controller.h). The members below that speak of the document call it.
    DocumentController* document() const { return m_document; }

    /// File operations without dialogs (the menu actions and the tests use them).
    bool openFile(const QString& file, QString* error) { return m_document->openFile(file, error); }
    bool saveFile(const QString& file, QString* error) { return m_document->saveFile(file, error); }
    QString currentFile() const { return m_document->currentFile(); }
    bool isModified() const { return m_document->isModified(); }

    /// Exports the current tab's view: format png, svg, pdf, csv or tikz (drawn as `tikz`
    /// asks). Empty or a message.
    QString exportCurrent(const QString& format, const QString& file, int dpi = 96, const TikzOptions& tikz = TikzOptions());

    /// Presentation mode: larger text and lines; `fullScreen` false keeps the window's size
    /// (screenshots of presentation mode at 1280×800). Leaving it gives the window back the
    /// state it had (maximised or not), its frame within the screen.
    void setPresentation(bool on, bool fullScreen = true);

    /// Shows the window as `granota` opens it: at the classroom size when that size and a
    /// window manager's frame fit the screen's available area, else maximised, so that the
    /// frame (title bar included) never reaches past the screen (docs/classroom.md, "Small
    /// screens").
    void showFitted();
    /// The window's size before it is shown: the classroom size 1280×800, but never more than
    /// the screen's available area less a window manager's frame (frameAllowance()).
    QSize fittedSize() const;
    /// The room a window manager's frame takes: a generous guess (a title bar of 40 px,
    /// borders of 8), or the window's own frame where that is larger.
    QMargins frameAllowance() const;

    /// The tabs' side panels (TabPage::sidePanel) shown or folded away: View ▸ Side panel (F9).
    /// Presentation mode folds them, so that the canvas has the width; leaving it shows them.
    void setSidePanelsShown(bool shown);
    bool sidePanelsShown() const;

    /// The work-precision section below each tab (docs/work-precision.md), hidden until asked for.
    WorkPrecisionPanel* workPrecisionPanel(const QString& key) const;
    void setWorkPrecisionVisible(bool visible);
    bool workPrecisionVisible() const;
    bool presentation() const { return m_presentation; }

    /// This window's autosave, written every 20 s while there are unsaved edits, and the
    /// recovery of ended sessions' autosaves: see DocumentController.
    QString autosaveFile() const { return m_document->autosaveFile(); }
    bool autosave() { return m_document->autosave(); }
    QString autosaveError() const { return m_document->autosaveError(); }
    QVector<Orphan> recoverableAutosaves() const { return m_document->recoverableAutosaves(); }
    using RecoveryOutcome = DocumentController::RecoveryOutcome;
    RecoveryOutcome recoverAutosave(const QString& orphanPath) { return m_document->recoverAutosave(orphanPath); }
    void offerRecovery() { m_document->offerRecovery(); }
    /// A document that could not be opened at start (a double-click): says why, without
    /// blocking, in the window.
    void showOpenError(const QString& error) { m_document->showOpenError(error); }

    /// The ring round the focused control (focus_frame.h) and the blank screen (B).
    FocusRing* focusRing() const { return m_focusRing; }
    BlankScreen* blankScreen() const { return m_blank; }

protected:
    void closeEvent(QCloseEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void createActions();
    void createMenus();
    void retranslate();
    /// Edit ▸ Undo and Redo: "Undo" or "Undo <step>", in the current language.
    void retranslateUndoRedo();
    void exportDialog(const QString& format);
    void exportFramesDialog();
    void showMessage(const QString& text);
    /// The status bar's hint: the shown tab's keys while its canvas has the keyboard focus,
    /// its mouse hint otherwise.
    void updateHint();
    void showGuide();
    void showAbout();
    /// The menus' actions, in menu order, submenus flattened: what the shortcuts help lists.
    QList<QAction*> shortcutActions() const;

    QTabWidget* m_tabs = nullptr;
    QVector<TabPage*> m_pages;
    QVector<WorkPrecisionPanel*> m_reports; ///< one per tab, below it in a splitter
    QVector<QScrollArea*> m_reportAreas;    ///< each report's scroll area, shown or hidden with it
    QVector<QSplitter*> m_splitters;
    QUndoGroup* m_undoGroup = nullptr;
    QLabel* m_hintLabel = nullptr; ///< the shown tab's hint (TabPage::hint)
    QLabel* m_cursorLabel = nullptr;
    DocumentController* m_document = nullptr;
    bool m_presentation = false;
    /// Maximised or not before presentation mode, to come back to.
    Qt::WindowStates m_stateBeforePresentation;
    bool m_refitAfterPresentation = false; ///< see resizeEvent
    QFont m_normalFont;

    QMenu *m_fileMenu = nullptr, *m_recentMenu = nullptr, *m_exportMenu = nullptr, *m_editMenu = nullptr, *m_viewMenu = nullptr,
          *m_examplesMenu = nullptr, *m_languageMenu = nullptr, *m_helpMenu = nullptr;
    QAction *m_new = nullptr, *m_open = nullptr, *m_save = nullptr, *m_saveAs = nullptr, *m_quit = nullptr;
    QAction *m_exportPng = nullptr, *m_exportSvg = nullptr, *m_exportPdf = nullptr, *m_exportCsv = nullptr,
            *m_exportTikz = nullptr, *m_exportFrames = nullptr;
    QAction *m_undo = nullptr, *m_redo = nullptr;
    QAction* m_reportsAction = nullptr;
    QAction* m_blankAction = nullptr;
    QAction* m_sidePanelAction = nullptr;
    BlankScreen* m_blank = nullptr;
    FocusRing* m_focusRing = nullptr;
    QAction *m_presentationAction = nullptr, *m_zoomIn = nullptr, *m_zoomOut = nullptr, *m_fit = nullptr;
    QAction *m_catalan = nullptr, *m_english = nullptr;
    QAction *m_guide = nullptr, *m_about = nullptr, *m_shortcutsAction = nullptr, *m_figuresAction = nullptr;
    ThesisFiguresDialog* m_figuresDialog = nullptr;
    ShortcutsDialog* m_shortcutsDialog = nullptr;
    QAction *m_nextTab = nullptr, *m_previousTab = nullptr;
    QVector<QAction*> m_tabActions;
    QVector<QAction*> m_exampleActions;
};

} // namespace granota::ui
