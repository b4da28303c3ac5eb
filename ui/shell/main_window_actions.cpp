// MainWindow's actions and menus, and their texts in the interface's language: what each
// menu holds, its shortcuts (the presenter remote's keys among them) and retranslate(),
// which a live language switch calls. The window itself is in main_window.cpp.
#include "ui/shell/main_window.h"

#include "core/io/worked_examples.h"
#include "ui/bernstein/bernstein_tab.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/curve_tab.h"
#include "ui/catmull_rom/catmull_rom_tab.h"
#include "ui/decasteljau/decasteljau_tab.h"
#include "ui/files/exporter.h"
#include "ui/files/file_dialogs.h"
#include "ui/fit/fit_tab.h"
#include "ui/frog/frog_tab.h"
#include "ui/common/language.h"
#include "ui/shell/shortcuts_dialog.h"
#include "ui/shell/shortcuts_help.h"
#include "ui/common/tab_page.h"
#include "ui/shell/thesis_figures_dialog.h"
#include "ui/shell/tikz_options_dialog.h"
#include "ui/common/field_input_filter.h"
#include "ui/common/focus_frame.h"
#include "ui/common/presentation_scale.h"
#include "ui/common/vertical_scroll_area.h"
#include "ui/shell/blank_screen.h"
#include "ui/common/work_precision_panel.h"

#include <QAbstractItemView>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QFile>
#include <QFileInfo>
#include <QInputDialog>
#include <QKeyEvent>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QScreen>
#include <QSplitter>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTextEdit>
#include <QTimer>
#include <QUndoGroup>
#include <QUndoStack>
#include <QWindow>

#include <algorithm>


namespace granota::ui {

void MainWindow::createActions()
{
    m_new = new QAction(this);
    m_new->setShortcut(QKeySequence::New);
    connect(m_new, &QAction::triggered, this, [this] { m_document->newDocument(); });
    m_open = new QAction(this);
    m_open->setShortcut(QKeySequence::Open);
    connect(m_open, &QAction::triggered, this, [this] { m_document->openDialog(); });
    m_save = new QAction(this);
    m_save->setShortcut(QKeySequence::Save);
    connect(m_save, &QAction::triggered, this, [this] { m_document->saveDialog(false); });
    m_saveAs = new QAction(this);
    // QKeySequence::SaveAs is empty in some key themes (X11 without KDE, offscreen):
    // docs/classroom.md promises Ctrl+Shift+S everywhere.
    m_saveAs->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    connect(m_saveAs, &QAction::triggered, this, [this] { m_document->saveDialog(true); });
    m_quit = new QAction(this);
    m_quit->setShortcut(QKeySequence::Quit);
    connect(m_quit, &QAction::triggered, this, &QWidget::close);

    m_exportPng = new QAction(this);
    m_exportPng->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
    connect(m_exportPng, &QAction::triggered, this, [this] { exportDialog(QStringLiteral("png")); });
    m_exportSvg = new QAction(this);
    connect(m_exportSvg, &QAction::triggered, this, [this] { exportDialog(QStringLiteral("svg")); });
    m_exportPdf = new QAction(this);
    connect(m_exportPdf, &QAction::triggered, this, [this] { exportDialog(QStringLiteral("pdf")); });
    m_exportCsv = new QAction(this);
    connect(m_exportCsv, &QAction::triggered, this, [this] { exportDialog(QStringLiteral("csv")); });
    m_exportTikz = new QAction(this);
    connect(m_exportTikz, &QAction::triggered, this, [this] { exportDialog(QStringLiteral("tikz")); });
    m_exportFrames = new QAction(this);
    connect(m_exportFrames, &QAction::triggered, this, &MainWindow::exportFramesDialog);

    // Our own actions rather than QUndoGroup's: those keep the words they were made with
    // ("Undo" in English) for an empty history, whatever the language is now.
    m_undo = new QAction(this);
    m_undo->setShortcut(QKeySequence::Undo);
    m_undo->setEnabled(false);
    connect(m_undo, &QAction::triggered, m_undoGroup, &QUndoGroup::undo);
    connect(m_undoGroup, &QUndoGroup::canUndoChanged, m_undo, &QAction::setEnabled);
    connect(m_undoGroup, &QUndoGroup::undoTextChanged, this, &MainWindow::retranslateUndoRedo);
    m_redo = new QAction(this);
    m_redo->setEnabled(false);
    connect(m_redo, &QAction::triggered, m_undoGroup, &QUndoGroup::redo);
    connect(m_undoGroup, &QUndoGroup::canRedoChanged, m_redo, &QAction::setEnabled);
    connect(m_undoGroup, &QUndoGroup::redoTextChanged, this, &MainWindow::retranslateUndoRedo);
    // The platform's Redo keys (Ctrl+Shift+Z on a Linux desktop, Ctrl+Y elsewhere) and both
    // of those, each once: a key given twice is an ambiguous shortcut, and Qt runs neither.
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    for (const QKeySequence& key : {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)})
        if (!redoKeys.contains(key))
            redoKeys << key;
    m_redo->setShortcuts(redoKeys);

    // F9, as a file manager's side bar: the tabs' side panels, folded away in presentation mode.
    m_sidePanelAction = new QAction(this);
    m_sidePanelAction->setObjectName(QStringLiteral("sidePanelAction"));
    m_sidePanelAction->setCheckable(true);
    m_sidePanelAction->setChecked(true);
    m_sidePanelAction->setShortcut(QKeySequence(Qt::Key_F9));
    connect(m_sidePanelAction, &QAction::toggled, this, &MainWindow::setSidePanelsShown);

    m_reportsAction = new QAction(this);
    m_reportsAction->setCheckable(true);
    m_reportsAction->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_T));
    connect(m_reportsAction, &QAction::toggled, this, &MainWindow::setWorkPrecisionVisible);

    m_presentationAction = new QAction(this);
    m_presentationAction->setCheckable(true);
    // F5: a presenter remote's "start the slide show" key.
    m_presentationAction->setShortcuts(
        {QKeySequence(Qt::Key_F11), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P), QKeySequence(Qt::Key_F5)});
    // B: a presenter remote's blank key (blank_screen.h).
    m_blankAction = new QAction(this);
    m_blankAction->setObjectName(QStringLiteral("blankScreenAction"));
    m_blankAction->setCheckable(true);
    m_blankAction->setShortcut(QKeySequence(Qt::Key_B));
    connect(m_blankAction, &QAction::toggled, m_blank, &BlankScreen::setBlank);
    connect(m_blank, &BlankScreen::dismissed, this, [this] { m_blankAction->setChecked(false); });
    connect(m_presentationAction, &QAction::toggled, this, [this](bool on) { setPresentation(on); });
    m_zoomIn = new QAction(this);
    m_zoomIn->setShortcuts({QKeySequence::ZoomIn, QKeySequence(Qt::CTRL | Qt::Key_Equal)});
    connect(m_zoomIn, &QAction::triggered, this, [this] {
        if (TabPage* t = currentTab())
            t->zoom(1.25);
    });
    m_zoomOut = new QAction(this);
    m_zoomOut->setShortcut(QKeySequence::ZoomOut);
    connect(m_zoomOut, &QAction::triggered, this, [this] {
        if (TabPage* t = currentTab())
            t->zoom(1 / 1.25);
    });
    m_fit = new QAction(this);
    m_fit->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_0));
    connect(m_fit, &QAction::triggered, this, [this] {
        if (TabPage* t = currentTab())
            t->fitView();
    });
    for (int i = 0; i < m_pages.size(); ++i) {
        auto* a = new QAction(this);
        a->setShortcut(QKeySequence(Qt::CTRL | (Qt::Key_1 + i)));
        connect(a, &QAction::triggered, this, [this, i] { m_tabs->setCurrentIndex(i); });
        m_tabActions.push_back(a);
    }
    // Ctrl+Tab and Ctrl+Page Down, Ctrl+Shift+Tab and Ctrl+Page Up, wherever the focus is
    // (QTabWidget's own only while the focus is inside it, and never Page Up/Down); Page Down
    // and Page Up alone too, a presenter remote's next and previous slide, but for a control
    // that pages itself (eventFilter).
    const auto cycle = [this](int by) {
        m_tabs->setCurrentIndex((m_tabs->currentIndex() + by + m_tabs->count()) % m_tabs->count());
        // The keyboard on the new tab's canvas, else on the tab bar: where the next Page
        // Up/Down still turns the tab (Qt would give it to the tab's first field).
        QWidget* canvas = nullptr;
        if (TabPage* page = currentTab())
            for (QWidget* w : page->findChildren<QWidget*>())
                if (drawsOwnFocusFrame(w) && w->isVisible() && (w->focusPolicy() & Qt::TabFocus)) {
                    canvas = w;
                    break;
                }
        (canvas ? canvas : m_tabs->tabBar())->setFocus(Qt::TabFocusReason);
    };
    m_nextTab = new QAction(this);
    m_nextTab->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::Key_Tab), QKeySequence(Qt::CTRL | Qt::Key_PageDown), QKeySequence(Qt::Key_PageDown)});
    connect(m_nextTab, &QAction::triggered, this, [cycle] { cycle(1); });
    m_previousTab = new QAction(this);
    m_previousTab->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Tab), QKeySequence(Qt::CTRL | Qt::Key_PageUp),
                                 QKeySequence(Qt::Key_PageUp)});
    connect(m_previousTab, &QAction::triggered, this, [cycle] { cycle(-1); });

    auto* languages = new QActionGroup(this);
    m_catalan = new QAction(QStringLiteral("Català"), languages);
    m_english = new QAction(QStringLiteral("English"), languages);
    for (QAction* a : {m_catalan, m_english})
        a->setCheckable(true);
    (currentLanguage() == QLatin1String("ca") ? m_catalan : m_english)->setChecked(true);
    connect(m_catalan, &QAction::triggered, this, [] { setLanguage(QStringLiteral("ca")); });
    connect(m_english, &QAction::triggered, this, [] { setLanguage(QStringLiteral("en")); });

    for (const WorkedExample& example : workedExamples()) { // Ex 2.1 … 2.13, in the thesis's order
        auto* a = new QAction(this);
        const QString key = QString::fromStdString(example.id);
        a->setData(key);
        connect(a, &QAction::triggered, this, [this, key] {
            if (!loadExample(key))
                showMessage(tr("Ex %1 could not be loaded.").arg(key));
        });
        m_exampleActions.push_back(a);
    }

    m_guide = new QAction(this);
    m_guide->setShortcut(QKeySequence::HelpContents);
    connect(m_guide, &QAction::triggered, this, &MainWindow::showGuide);
    m_shortcutsAction = new QAction(this);
    m_shortcutsAction->setObjectName(QStringLiteral("keyboardShortcuts"));
    connect(m_shortcutsAction, &QAction::triggered, this, &MainWindow::showShortcuts);
    m_figuresAction = new QAction(this);
    m_figuresAction->setObjectName(QStringLiteral("thesisFiguresAction"));
    connect(m_figuresAction, &QAction::triggered, this, &MainWindow::showThesisFigures);
    m_about = new QAction(this);
    connect(m_about, &QAction::triggered, this, &MainWindow::showAbout);
}

void MainWindow::createMenus()
{
    m_fileMenu = menuBar()->addMenu(QString());
    m_fileMenu->addAction(m_new);
    m_fileMenu->addAction(m_open);
    m_recentMenu = m_fileMenu->addMenu(QString());
    m_fileMenu->addAction(m_save);
    m_fileMenu->addAction(m_saveAs);
    m_fileMenu->addSeparator();
    m_exportMenu = m_fileMenu->addMenu(QString());
    for (QAction* a : {m_exportPng, m_exportSvg, m_exportPdf, m_exportCsv, m_exportTikz})
        m_exportMenu->addAction(a);
    m_exportMenu->addSeparator();
    m_exportMenu->addAction(m_exportFrames);
    m_fileMenu->addSeparator();
    m_fileMenu->addAction(m_quit);

    m_editMenu = menuBar()->addMenu(QString());
    m_editMenu->addAction(m_undo);
    m_editMenu->addAction(m_redo);

    m_viewMenu = menuBar()->addMenu(QString());
    m_viewMenu->addAction(m_presentationAction);
    m_viewMenu->addAction(m_blankAction);
    m_viewMenu->addAction(m_sidePanelAction);
    m_viewMenu->addAction(m_reportsAction);
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_zoomIn);
    m_viewMenu->addAction(m_zoomOut);
    m_viewMenu->addAction(m_fit);
    m_viewMenu->addSeparator();
    for (QAction* a : m_tabActions)
        m_viewMenu->addAction(a);
    m_viewMenu->addAction(m_nextTab);
    m_viewMenu->addAction(m_previousTab);
    m_viewMenu->addSeparator();
    m_languageMenu = m_viewMenu->addMenu(QString());
    m_languageMenu->addAction(m_catalan);
    m_languageMenu->addAction(m_english);

    m_examplesMenu = menuBar()->addMenu(QString());
    for (QAction* a : m_exampleActions)
        m_examplesMenu->addAction(a);

    m_helpMenu = menuBar()->addMenu(QString());
    m_helpMenu->addAction(m_guide);
    m_helpMenu->addAction(m_shortcutsAction);
    m_helpMenu->addAction(m_figuresAction);
    m_helpMenu->addAction(m_about);
}

void MainWindow::retranslateUndoRedo()
{
    const QString undo = m_undoGroup->undoText(), redo = m_undoGroup->redoText();
    m_undo->setText(undo.isEmpty() ? tr("&Undo") : tr("&Undo %1").arg(undo));
    m_redo->setText(redo.isEmpty() ? tr("&Redo") : tr("&Redo %1").arg(redo));
    m_undo->setEnabled(m_undoGroup->canUndo());
    m_redo->setEnabled(m_undoGroup->canRedo());
}

void MainWindow::retranslate()
{
    m_tabs->setAccessibleName(tr("Tabs"));
    updateHint();
    m_fileMenu->setTitle(tr("&File"));
    m_new->setText(tr("&New"));
    m_open->setText(tr("&Open…"));
    m_recentMenu->setTitle(tr("Open &Recent"));
    m_save->setText(tr("&Save"));
    m_saveAs->setText(tr("Save &As…"));
    m_exportMenu->setTitle(tr("&Export"));
    m_exportPng->setText(tr("PNG image…"));
    m_exportSvg->setText(tr("SVG drawing…"));
    m_exportPdf->setText(tr("PDF document…"));
    m_exportCsv->setText(tr("CSV data…"));
    m_exportTikz->setText(tr("TikZ picture for LaTeX…"));
    m_exportFrames->setText(tr("Frog animation as PNG frames…"));
    m_quit->setText(tr("&Quit"));
    m_editMenu->setTitle(tr("&Edit"));
    retranslateUndoRedo();
    m_viewMenu->setTitle(tr("&View"));
    m_presentationAction->setText(tr("&Presentation mode"));
    m_presentationAction->setToolTip(tr("Full screen, larger text and thicker lines for the classroom."));
    m_sidePanelAction->setText(tr("&Side panel"));
    m_sidePanelAction->setToolTip(tr("The settings and results beside the canvas; presentation mode folds them away "
                                     "so that the canvas has the width."));
    m_blankAction->setText(tr("&Blank the screen"));
    m_blankAction->setToolTip(tr("Black over the whole window until B again or a click (a presenter remote's blank key)."));
    m_reportsAction->setText(tr("&Error against run time"));
    m_reportsAction->setToolTip(tr("Show, below the tab, how accurate each numerical method is for the time it "
                                   "takes (work-precision plot)."));
    m_zoomIn->setText(tr("Zoom &in"));
    m_zoomOut->setText(tr("Zoom &out"));
    m_fit->setText(tr("&Fit to view"));
    for (int i = 0; i < m_pages.size(); ++i) {
        m_tabActions[i]->setText(tr("Show %1").arg(m_pages[i]->title()));
        m_tabs->setTabText(i, m_pages[i]->title());
    }
    m_nextTab->setText(tr("&Next tab"));
    m_previousTab->setText(tr("Pre&vious tab"));
    m_languageMenu->setTitle(tr("&Language"));
    m_examplesMenu->setTitle(tr("E&xamples"));
    const QString exampleTitles[] = {
        tr("Ex 2.1 — Cubic spline through four points (Def 2.3)"),  tr("Ex 2.2 — De Casteljau, degree 4"),
        tr("Ex 2.3 — De Casteljau, a closed curve of degree 4"),    tr("Ex 2.4 — Bernstein polynomials up to degree 5"),
        tr("Ex 2.5 — Ex 2.2's curve in the Bernstein basis"),       tr("Ex 2.6 — Ex 2.3's curve in the Bernstein basis"),
        tr("Ex 2.7 — Least squares, degree 2, uniform parameters"), tr("Ex 2.8 — Least squares, degree 3, uniform parameters"),
        tr("Ex 2.9 — Least squares, degree 2, chord lengths"),      tr("Ex 2.10 — Least squares, degree 3, chord lengths"),
        tr("Ex 2.11 — A Catmull-Rom segment for τ = 0, 1/2, 2"),    tr("Ex 2.12 — Blending functions for several tensions"),
        tr("Ex 2.13 — Catmull-Rom curve, cyclic and open"),
    };
    for (int i = 0; i < m_exampleActions.size(); ++i)
        m_exampleActions[i]->setText(exampleTitles[i]);
    m_helpMenu->setTitle(tr("&Help"));
    m_guide->setText(tr("&User guide"));
    m_shortcutsAction->setText(tr("&Keyboard shortcuts"));
    m_figuresAction->setText(tr("Thesis &figures…"));
    m_about->setText(tr("&About Granota"));
    m_cursorLabel->setToolTip(tr("Position of the mouse in the plane"));
    m_document->retranslate();
}

} // namespace granota::ui
