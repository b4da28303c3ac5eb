#include "ui/shell/main_window.h"

#include "core/io/worked_examples.h"
#include "ui/bernstein/bernstein_tab.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/curve_tab.h"
#include "ui/bsplines/bspline_tab.h"
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

namespace {
/// Which work-precision reports (work_precision.h) belong to which tab.
std::vector<std::string> reportsOf(const QString& key)
{
    if (key == QLatin1String("decasteljau"))
        return {"curve-sampling", "bezier-evaluation", "arc-length"};
    if (key == QLatin1String("bernstein"))
        return {"bezier-evaluation"};
    if (key == QLatin1String("fit"))
        return {"least-squares"};
    if (key == QLatin1String("catmull-rom"))
        return {"catmull-rom-sampling"};
    if (key == QLatin1String("bspline")) // de Boor against the Bézier extraction and the basis sum
        return {"bspline-evaluation", "curve-sampling"};
    return {"integrators", "energy-drift", "soft-body"};
}

/// The window's size in a classroom (and of the README's screenshots).
constexpr QSize kClassroomSize(1280, 800);
/// A window manager's frame before the window is shown and the manager says how thick it is:
/// a title bar of up to 40 px (openbox's is 20, GNOME's about 37) and borders of 8.
constexpr QMargins kFrameGuess(8, 40, 8, 8);
constexpr double kPresentationFont = 1.5; ///< font scale in presentation mode
/// The height of canvas the work-precision section leaves a tab when it opens (or all the canvas
/// had, if less): on an 800×600 screen it had shrunk the Frog canvas to 240×145 (issue 34).
constexpr int kCanvasKeptUnderReport = 220;
/// The status bar's, smaller: its hints are for the one at the keyboard, and a whole hint fits 1024 px.
constexpr double kPresentationStatusFont = 1.25;
} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), m_tabs(new QTabWidget(this))
{
    setObjectName(QStringLiteral("MainWindow"));
    FieldInputFilter::install(); // the wheel scrolls the panels; Ctrl+Z in a field is the document's
    m_normalFont = QApplication::font();
    auto* deCasteljau = new DeCasteljauTab(this);
    m_pages = {deCasteljau,       new BernsteinTab(deCasteljau->curveModel(), this),
               new FitTab(this),  new CatmullRomTab(this),
               new FrogTab(this), new BSplineTab(this)};
    m_undoGroup = new QUndoGroup(this);
    for (TabPage* page : m_pages) {
        // Below every tab, its work-precision section (docs/work-precision.md), collapsed until View ▸ Error
        // against run time opens it.
        // The section scrolls rather than pushing the window past a small screen (800×600).
        auto* splitter = new QSplitter(Qt::Vertical, this);
        auto* report = new WorkPrecisionPanel(reportsOf(page->key()));
        auto* reportArea = new VerticalScrollArea(report, splitter);
        splitter->addWidget(page);
        splitter->addWidget(reportArea);
        splitter->setCollapsible(0, false);
        splitter->setStretchFactor(0, 3);
        splitter->setStretchFactor(1, 2);
        reportArea->hide();
        m_splitters.push_back(splitter);
        m_reports.push_back(report);
        m_reportAreas.push_back(reportArea);
        m_tabs->addTab(splitter, page->title());
        m_undoGroup->addStack(page->undoStack());
        connect(page, &TabPage::reportRequested, this, [this, report](const QString& name) {
            report->selectReport(name.toStdString());
            setWorkPrecisionVisible(true);
        });
        // Only the tab shown speaks: a hidden tab's message would belong to another screen.
        connect(page, &TabPage::statusMessage, this, [this, page](const QString& text) {
            if (page == currentTab())
                showMessage(text);
        });
    }
    m_tabs->setDocumentMode(true);
    connect(m_tabs, &QTabWidget::currentChanged, this, [this](int index) {
        if (index >= 0 && index < m_pages.size()) {
            m_undoGroup->setActiveStack(m_pages[index]->undoStack());
            statusBar()->clearMessage(); // the last tab's passing message is not about this one
            updateHint();
            if (m_reportsAction)
                m_reportsAction->setChecked(!m_reportAreas[index]->isHidden());
        }
    });
    m_undoGroup->setActiveStack(m_pages.front()->undoStack());
    setCentralWidget(m_tabs);

    // The shown tab's hint, under the passing messages (QStatusBar hides it while one shows).
    m_hintLabel = new QLabel(this);
    m_hintLabel->setObjectName(QStringLiteral("tabHint"));
    m_hintLabel->setMinimumWidth(0);
    m_hintLabel->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    statusBar()->addWidget(m_hintLabel, 1);
    // QStatusBar hides its widgets under a message only if they are visible then: a message
    // given before the window is shown (--example) would be drawn over the hint.
    connect(statusBar(), &QStatusBar::messageChanged, m_hintLabel,
            [this](const QString& message) { m_hintLabel->setVisible(message.isEmpty()); });
    m_cursorLabel = new QLabel(this);
    statusBar()->addPermanentWidget(m_cursorLabel);

    m_blank = new BlankScreen(this);
    m_focusRing = new FocusRing(this);
    createActions();
    createMenus();
    // Alt+letter, then Esc: the menu closes and the keyboard goes back where it was, as after
    // a second Esc (Qt keeps it in the menu bar, nothing highlighted, Tab and arrows dead).
    for (QAction* a : menuBar()->actions())
        if (QMenu* menu = a->menu())
            connect(menu, &QMenu::aboutToHide, this, [this] {
                // Queued: Qt gives the menu bar the keyboard after the menu is hidden.
                QTimer::singleShot(0, this, [this] {
                    if (menuBar()->hasFocus() && !QApplication::activePopupWidget()) {
                        QKeyEvent escape(QEvent::KeyPress, Qt::Key_Escape, Qt::NoModifier);
                        QCoreApplication::sendEvent(menuBar(), &escape);
                    }
                });
            });
    // The keys a control of this window uses itself before the window's single-key shortcuts
    // (Page Up/Down, B): see eventFilter.
    qApp->installEventFilter(this);
    // The status bar speaks of the keys while a canvas has the keyboard, of the mouse otherwise.
    connect(qApp, &QApplication::focusChanged, this, [this] { updateHint(); });

    m_document = new DocumentController(this, m_recentMenu);
    connect(m_document, &DocumentController::message, this, &MainWindow::showMessage);

    resize(fittedSize());
    retranslate();
}

MainWindow::~MainWindow()
{
    // The tabs' undo stacks leave the group as the widgets below are deleted, and the group
    // says so: not to this window any more, which is half destroyed by then.
    disconnect(m_undoGroup, nullptr, this, nullptr);
    // Nor the focus moving as the window closes (updateHint would read deleted tabs).
    disconnect(qApp, nullptr, this, nullptr);
    qApp->removeEventFilter(this);
    // Nor a tab's message: a field still being typed in commits its text as it loses the
    // focus while the window closes, and the tab says so to a status bar already deleted.
    for (TabPage* page : m_pages)
        disconnect(page, nullptr, this, nullptr);
}

QMargins MainWindow::frameAllowance() const
{
    // The larger of the guess and the frame known: a maximised window has no borders, and a
    // dialog it opens has (openbox: 1 px at the sides, 5 below).
    const QWindow* handle = windowHandle();
    const QMargins known = handle ? handle->frameMargins() : QMargins();
    return {std::max(known.left(), kFrameGuess.left()), std::max(known.top(), kFrameGuess.top()),
            std::max(known.right(), kFrameGuess.right()), std::max(known.bottom(), kFrameGuess.bottom())};
}

QSize MainWindow::fittedSize() const
{
    const QScreen* screen = this->screen();
    if (!screen)
        return kClassroomSize;
    const QMargins frame = frameAllowance();
    const QSize room = screen->availableGeometry().size().shrunkBy(frame);
    return kClassroomSize.boundedTo(room);
}

void MainWindow::showFitted()
{
    resize(fittedSize());
    // A screen with no room for the classroom size and a frame (1024×768, 800×600, a
    // 1366×768 laptop): maximised, the window manager fits the frame to the screen.
    if (fittedSize() != kClassroomSize)
        setWindowState(windowState() | Qt::WindowMaximized);
    show();
}

// ---------------------------------------------------------------- tabs and examples

bool MainWindow::showTab(const QString& key)
{
    for (int i = 0; i < m_pages.size(); ++i)
        if (m_pages[i]->key() == key) {
            m_tabs->setCurrentIndex(i);
            return true;
        }
    return false;
}

TabPage* MainWindow::tab(const QString& key) const
{
    for (TabPage* page : m_pages)
        if (page->key() == key)
            return page;
    return nullptr;
}

TabPage* MainWindow::currentTab() const
{
    const int index = m_tabs->currentIndex();
    return index >= 0 && index < m_pages.size() ? m_pages[index] : nullptr;
}

FrogTab* MainWindow::frogTab() const { return qobject_cast<FrogTab*>(tab(QStringLiteral("frog"))); }

bool MainWindow::loadExample(const QString& id)
{
    const WorkedExample* example = findWorkedExample(id.toStdString());
    if (!example)
        return false;
    TabPage* page = tab(QString::fromStdString(example->tab));
    if (!page)
        return false;
    // The tab first, so that its hint does not replace what the example says about itself.
    showTab(page->key());
    showMessage(tr("Loaded Ex %1 of the thesis.").arg(id));
    return page->loadExample(*example); // its own message, when it has one, follows
}

void MainWindow::showThesisFigures()
{
    if (!m_figuresDialog)
        m_figuresDialog = new ThesisFiguresDialog(this);
    m_figuresDialog->show();
    m_figuresDialog->raise();
}

void MainWindow::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange) {
        retranslate();
        const bool catalan = currentLanguage() == QLatin1String("ca");
        m_catalan->setChecked(catalan);
        m_english->setChecked(!catalan);
    }
    QMainWindow::changeEvent(event);
}

// ---------------------------------------------------------------- the document (document_controller.h)

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (!m_document->maybeClose()) {
        event->ignore();
        return;
    }
    event->accept();
}

// ---------------------------------------------------------------- exports

QString MainWindow::exportCurrent(const QString& format, const QString& file, int dpi, const TikzOptions& tikz)
{
    TabPage* page = currentTab();
    if (!page)
        return tr("No tab is shown.");
    const QString title = tr("Granota — %1").arg(page->title());
    if (format == QLatin1String("png"))
        return exportPng(*page->exportView(), file, dpi);
    if (format == QLatin1String("svg"))
        return exportSvg(*page->exportView(), file, title);
    if (format == QLatin1String("pdf"))
        return exportPdf(*page->exportView(), file, title);
    if (format == QLatin1String("csv"))
        return writeTextFile(file, page->csv());
    if (format == QLatin1String("tikz"))
        return writeTextFile(file, page->tikz(tikz));
    return tr("Unknown export format “%1”.").arg(format);
}

void MainWindow::exportDialog(const QString& format)
{
    TabPage* page = currentTab();
    if (!page)
        return;
    int dpi = 96;
    if (format == QLatin1String("png")) {
        bool ok = false;
        const QStringList choices = {QStringLiteral("96"), QStringLiteral("150"), QStringLiteral("300"), QStringLiteral("600")};
        const QString choice = QInputDialog::getItem(this, tr("Export PNG"), tr("Resolution (dots per inch; 300 for print):"),
                                                     choices, 2, false, &ok);
        if (!ok)
            return;
        dpi = choice.toInt();
    }
    TikzOptions tikz;
    if (format == QLatin1String("tikz") && !TikzOptionsDialog::ask(this, &tikz))
        return;
    const QString extension = format == QLatin1String("tikz") ? QStringLiteral("tex") : format;
    const QString file = saveFileName(this, tr("Export"), page->key() + QLatin1Char('.') + extension,
                                      tr("%1 files (*.%2)").arg(format.toUpper(), extension));
    if (file.isEmpty())
        return;
    const QString error = exportCurrent(format, file, dpi, tikz);
    if (error.isEmpty())
        showMessage(tr("Exported %1").arg(QFileInfo(file).fileName()));
    else
        QMessageBox::warning(this, tr("Export"), error);
}

void MainWindow::exportFramesDialog()
{
    FrogTab* frog = frogTab();
    // The frames start at the step shown now: the run goes on behind the dialogs.
    const long shown = frog->shownStep();
    bool ok = false;
    const int frames = QInputDialog::getInt(this, tr("Frog animation"), tr("Number of frames (60 per second):"), 120, 1, 3600, 1,
                                            &ok);
    if (!ok)
        return;
    const QList<QSize> sizes = {FrogTab::kFrameSize, {1920, 1080}, {854, 480}};
    QStringList names;
    for (const QSize& s : sizes)
        names << tr("%1 × %2 pixels").arg(s.width()).arg(s.height());
    const QString name = QInputDialog::getItem(this, tr("Frog animation"), tr("Size of the frames (video):"), names, 0, false,
                                               &ok);
    if (!ok)
        return;
    const QString directory = existingFolder(this, tr("Folder for the frames"));
    if (directory.isEmpty())
        return;
    const QString error = frog->exportFrames(directory, frames, sizes.value(names.indexOf(name), FrogTab::kFrameSize), shown);
    if (error.isEmpty())
        showMessage(tr("Wrote %n frames.", nullptr, frames));
    else
        QMessageBox::warning(this, tr("Frog animation"), error);
}

// ---------------------------------------------------------------- classroom

void MainWindow::setPresentation(bool on, bool fullScreen)
{
    if (on == m_presentation)
        return;
    m_presentation = on;
    if (m_presentationAction->isChecked() != on)
        m_presentationAction->setChecked(on);
    QFont font = m_normalFont;
    if (on)
        font.setPointSizeF(m_normalFont.pointSizeF() * kPresentationFont);
    QApplication::setFont(font);
    QFont statusFont = m_normalFont;
    if (on)
        statusFont.setPointSizeF(m_normalFont.pointSizeF() * kPresentationStatusFont);
    statusBar()->setFont(statusFont);
    for (TabPage* page : m_pages)
        page->setPresentation(on);
    for (WorkPrecisionPanel* report : m_reports)
        report->setPresentation(on);
    m_focusRing->setScale(presentationScale(on));
    // The canvas has the room in presentation mode; F9 opens the side panel like a drawer.
    setSidePanelsShown(!on);
    if (on && fullScreen) {
        m_stateBeforePresentation = windowState() & Qt::WindowMaximized;
        showFullScreen();
    } else if (!on && isFullScreen()) {
        // The normal font's layouts first: the window's minimum size is still presentation
        // mode's, and a window manager would keep the window that large (975 px wide on an
        // 800 px screen).
        // Every posted event first (the font changes are posted too), then the layouts.
        QCoreApplication::sendPostedEvents();
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        if (layout())
            layout()->activate();
        // Back as it was: at its own size, never past the screen (full screen may have grown
        // it past a small one), then maximised if it was.
        showNormal();
        resize(size().boundedTo(fittedSize()));
        if (m_stateBeforePresentation & Qt::WindowMaximized)
            showMaximized();
        m_refitAfterPresentation = true; // resizeEvent: the size the window system gives it next
    }
}

void MainWindow::setSidePanelsShown(bool shown)
{
    for (TabPage* page : m_pages)
        if (QWidget* panel = page->sidePanel())
            panel->setVisible(shown);
    if (m_sidePanelAction->isChecked() != shown)
        m_sidePanelAction->setChecked(shown);
}

bool MainWindow::sidePanelsShown() const { return m_sidePanelAction->isChecked(); }

void MainWindow::resizeEvent(QResizeEvent* event)
{
    QMainWindow::resizeEvent(event);
    // Back from full screen on a small screen, a window system may give the window the width
    // presentation mode's layout needed (992 px on an 800 px screen): once, as it arrives, the
    // window is fitted again (maximised again if it was).
    const QScreen* screen = this->screen();
    if (!m_refitAfterPresentation || m_presentation || isFullScreen() || !screen)
        return;
    const QSize room = screen->availableGeometry().size();
    if (width() <= room.width() && height() <= room.height())
        return;
    m_refitAfterPresentation = false;
    const bool maximised = isMaximized();
    showNormal();
    resize(fittedSize());
    if (maximised)
        showMaximized();
}

WorkPrecisionPanel* MainWindow::workPrecisionPanel(const QString& key) const
{
    for (int i = 0; i < m_pages.size(); ++i)
        if (m_pages[i]->key() == key)
            return m_reports[i];
    return nullptr;
}

void MainWindow::setWorkPrecisionVisible(bool visible)
{
    const int index = m_tabs->currentIndex();
    if (index < 0)
        return;
    // The canvas's height before the section takes its share (the splitter lays out at once):
    // the export view, or the curve canvas of a tab that exports more than it (Fitting).
    const QWidget* canvas = dynamic_cast<const QWidget*>(m_pages[index]->exportView());
    if (auto* curves = qobject_cast<const CurveTab*>(m_pages[index]); curves && !canvas)
        canvas = curves->canvas();
    const int canvasHeight = canvas && canvas->isVisible() ? canvas->height() : -1;
    const bool opening = visible && m_reportAreas[index]->isHidden(); // not again from the action's toggle
    m_reportAreas[index]->setVisible(visible);
    if (opening) {
        const int handle = m_splitters[index]->handleWidth();
        const int total = m_splitters[index]->height() - handle;
        // Two fifths, but never the canvas's last kCanvasKeptUnderReport px (the section and
        // the handle come out of the canvas's height): on a small screen the section is lower,
        // and scrolls.
        int report = total * 2 / 5;
        if (canvasHeight >= 0)
            report = std::min(report, std::max(canvasHeight - std::min(canvasHeight, kCanvasKeptUnderReport) - handle,
                                               m_reportAreas[index]->minimumSizeHint().height()));
        m_splitters[index]->setSizes({total - report, report});
    }
    if (m_reportsAction->isChecked() != visible)
        m_reportsAction->setChecked(visible);
}

bool MainWindow::workPrecisionVisible() const
{
    const int index = m_tabs->currentIndex();
    return index >= 0 && !m_reportAreas[index]->isHidden();
}

void MainWindow::updateHint()
{
    TabPage* page = currentTab();
    if (!page || !m_hintLabel)
        return;
    // A canvas draws its own focus ring (focus_frame.h): while one of the tab has the keyboard.
    const QWidget* focus = focusWidget();
    const bool keyboard = focus && drawsOwnFocusFrame(focus) && page->isAncestorOf(focus) && !page->keyboardHint().isEmpty();
    m_hintLabel->setText(keyboard ? page->keyboardHint() : page->hint());
}

bool MainWindow::eventFilter(QObject* watched, QEvent* event)
{
    // A single key the window uses (Page Up/Down for the tabs, B for the blank screen) stays
    // with a control of this window that uses it itself: a spin box steps by ten with Page
    // Up/Down, a list or a table pages, a slider jumps; a list or a combo box finds an entry
    // by its letter (a field being typed in keeps its letters without help).
    if (event->type() == QEvent::ShortcutOverride && watched->isWidgetType()) {
        auto* key = static_cast<QKeyEvent*>(event);
        auto* widget = static_cast<QWidget*>(watched);
        const bool page = key->key() == Qt::Key_PageUp || key->key() == Qt::Key_PageDown;
        const bool letter = key->key() == Qt::Key_B;
        if ((page || letter) && key->modifiers() == Qt::NoModifier && widget->window() == this)
            for (QWidget* w = widget; w && w != this; w = w->parentWidget()) {
                const bool pages = qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QAbstractSlider*>(w) ||
                                   qobject_cast<QAbstractItemView*>(w) || qobject_cast<QTextEdit*>(w) ||
                                   qobject_cast<QPlainTextEdit*>(w) || qobject_cast<QComboBox*>(w);
                const bool searches = qobject_cast<QAbstractItemView*>(w) || qobject_cast<QComboBox*>(w);
                if ((page && pages) || (letter && searches)) {
                    event->accept();
                    return true;
                }
            }
    }
    return QMainWindow::eventFilter(watched, event);
}

void MainWindow::showMessage(const QString& text) { statusBar()->showMessage(text, 8000); }

void MainWindow::showGuide()
{
    QMessageBox box(this);
    box.setWindowTitle(tr("User guide"));
    box.setTextFormat(Qt::RichText);
    box.setText(tr("<h3>Granota in five tabs</h3>"
                   "<p><b>De Casteljau</b> (§2.1.1): drag the control points, move t, watch every level.</p>"
                   "<p><b>Bernstein</b> (§2.1.2): the basis polynomials and their weights at the same t.</p>"
                   "<p><b>Fitting</b> (§2.1.3): a Bézier curve through data by least squares.</p>"
                   "<p><b>Catmull-Rom</b> (§2.2): curves through the points, one per tension τ.</p>"
                   "<p><b>Frog</b> (chapter 4): the soft body, stage by stage.</p>"
                   "<p>Double-click to add a point, Delete to remove it, arrows to nudge it, "
                   "Ctrl+Z to undo. The Examples menu loads every worked example of chapter 2. "
                   "F11 switches presentation mode.</p>") +
                tr("<p>Everything can be done with the keyboard alone: Help ▸ Keyboard shortcuts lists every key.</p>") +
                tr("<p>Where a printed example of the thesis slips, the tab says so beside the right value; "
                   "docs/thesis-errata.md, in Granota's sources, lists every slip and where Granota shows it.</p>"));
    box.exec();
}

QList<QAction*> MainWindow::shortcutActions() const
{
    QList<QAction*> actions;
    for (QMenu* menu : {m_fileMenu, m_editMenu, m_viewMenu, m_examplesMenu, m_helpMenu})
        for (QAction* a : menu->actions())
            if (a->menu())
                actions += a->menu()->actions();
            else
                actions += a;
    return actions;
}

QString MainWindow::shortcutsHelp() const { return ShortcutsHelp::html(shortcutActions()); }

void MainWindow::showShortcuts()
{
    if (!m_shortcutsDialog)
        m_shortcutsDialog = new ShortcutsDialog(this);
    m_shortcutsDialog->present(ShortcutsHelp::twoColumnHtml(shortcutActions()), frameAllowance());
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About Granota"),
                       tr("<h3>Granota</h3><p>Splines and soft bodies for the classroom, from the thesis "
                          "“Animació procedimental per a cossos tous”.</p>"));
}

} // namespace granota::ui
