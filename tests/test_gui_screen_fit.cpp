// The window on a projector's screen (issue 34; docs/classroom.md, "Small screens" and
// "Keyboard"): the frame — title bar included — within the screen's available area when the
// window opens and after presentation mode; Help ▸ Keyboard shortcuts within the screen, its
// text scrolling; after Alt+letter and Esc the keyboard back in the window. ctest runs it
// offscreen and, through tests/real_window/run.sh, under Xvfb and openbox on screens of
// 1280×1024, 1024×768 and 800×600 (tests/CMakeLists.txt), where a window manager's frame
// exists: the frame is known only once the manager has framed the window, so each check
// waits for that first (waitFramed) and then for the frame to fit — a wait, never a time.
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "ui/shell/shortcuts_dialog.h"
#include "ui/common/tab_page.h"

#include "main_window_steps.h"

#include <QApplication>
#include <QGuiApplication>
#include <QMenuBar>
#include <QPushButton>
#include <QScreen>
#include <QScrollBar>
#include <QStatusBar>
#include <QTest>
#include <QTextBrowser>
#include "tests/test_main.h"

using granota::ui::MainWindow;
using granota::ui::ShortcutsDialog;

namespace {

/// Under a window manager (xcb), not offscreen, where windows have no frame.
bool framedPlatform() { return QGuiApplication::platformName() != QLatin1String("offscreen"); }

/// Waits until the window manager has framed `window` (its frame geometry differs from its
/// client area): only then does frameGeometry() say where the title bar is.
bool waitFramed(QWidget* window)
{
    if (!framedPlatform())
        return true;
    if (QTest::qWaitFor([window] { return window->frameGeometry() != window->geometry(); }, kEventWaitMs))
        return true;
    qWarning().noquote() << "the window manager never framed" << describeWindow(window);
    return false;
}

QString rectText(const QRect& r)
{
    return QStringLiteral("%1×%2 at (%3, %4)").arg(r.width()).arg(r.height()).arg(r.x()).arg(r.y());
}

/// Empty if `window`'s frame lies within its screen's available area, else what is wrong.
QString frameProblem(const QWidget* window)
{
    const QRect available = window->screen()->availableGeometry();
    const QRect frame = window->frameGeometry();
    if (available.contains(frame))
        return QString();
    return QStringLiteral("%1's frame %2 is not within the screen's available %3 (client %4)")
        .arg(describeWindow(window), rectText(frame), rectText(available), rectText(window->geometry()));
}

} // namespace

class TestGuiScreenFit : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        useTestSettings();
        granota::ui::setLanguage(QStringLiteral("en"), false);
    }
    void cleanupTestCase() { granota::ui::setLanguage(QStringLiteral("en"), false); }

    // The size asked before the window is shown leaves room for a frame: a window manager
    // that keeps that size (it may not maximise) still shows the title bar and the status bar.
    void sizeAskedLeavesRoomForAFrame()
    {
        MainWindow window;
        const QRect available = window.screen()->availableGeometry();
        const QSize asked = window.fittedSize();
        const QMargins frame = window.frameAllowance();
        QVERIFY(frame.top() >= 20); // a title bar: openbox's is 20 px, most are taller
        QVERIFY2(asked.width() + frame.left() + frame.right() <= available.width() &&
                     asked.height() + frame.top() + frame.bottom() <= available.height(),
                 qPrintable(QStringLiteral("%1×%2 asked on %3").arg(asked.width()).arg(asked.height()).arg(rectText(available))));
        QCOMPARE(window.size(), asked);
    }

    // As `granota` opens (showFitted): the frame, title bar and all, within the screen, and
    // so the status bar, where every hint and refusal appears, on it.
    void frameFitsAtStart()
    {
        MainWindow window;
        window.showFitted();
        QVERIFY(waitExposed(&window));
        QVERIFY(waitFramed(&window));
        QTRY_VERIFY2_WITH_TIMEOUT(frameProblem(&window).isEmpty(), qPrintable(frameProblem(&window)), kEventWaitMs);
        const QRect status(window.statusBar()->mapToGlobal(QPoint()), window.statusBar()->size());
        QVERIFY(window.screen()->availableGeometry().contains(status));
    }

    void frameFitsAfterPresentation_data()
    {
        QTest::addColumn<QString>("tab");
        for (const char* tab : {"decasteljau", "bernstein", "fit", "catmull-rom", "frog", "bspline"})
            QTest::newRow(tab) << QString::fromLatin1(tab);
    }

    // In and out of presentation mode on each tab: the window comes back within the screen
    // (it used to come back 975 px wide on an 800 px screen).
    void frameFitsAfterPresentation()
    {
        QFETCH(QString, tab);
        MainWindow window;
        QVERIFY(window.showTab(tab));
        window.showFitted();
        QVERIFY(waitExposed(&window));
        QVERIFY(waitFramed(&window));
        QTRY_VERIFY2_WITH_TIMEOUT(frameProblem(&window).isEmpty(), qPrintable(frameProblem(&window)), kEventWaitMs);
        window.setPresentation(true);
        QTRY_VERIFY_WITH_TIMEOUT(window.isFullScreen(), kEventWaitMs);
        // Full screen has no frame: wait until the manager has taken it off.
        QTRY_VERIFY_WITH_TIMEOUT(window.frameGeometry() == window.geometry(), kEventWaitMs);
        window.setPresentation(false);
        QVERIFY(!window.isFullScreen());
        QVERIFY(waitFramed(&window));
        // Under openbox on an 800 px screen the Bernstein tab came back 992 px wide, the width
        // its row of t needs in presentation mode: the font changes were still posted when
        // the window was resized.
        QTRY_VERIFY2_WITH_TIMEOUT(frameProblem(&window).isEmpty(), qPrintable(frameProblem(&window)), kEventWaitMs);
    }

    void shortcutsDialogFits_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<bool>("presentation");
        for (const char* language : {"en", "ca"})
            for (bool presentation : {false, true})
                QTest::addRow("%s%s", language, presentation ? " presentation" : "")
                    << QString::fromLatin1(language) << presentation;
    }

    // Help ▸ Keyboard shortcuts within the screen, its Close button on it, and every row
    // reachable: the text shows whole or scrolls (it used to be 1182 px tall, unscrollable).
    void shortcutsDialogFits()
    {
        QFETCH(QString, language);
        QFETCH(bool, presentation);
        QVERIFY(granota::ui::setLanguage(language, false));
        MainWindow window;
        window.showFitted();
        QVERIFY(waitExposed(&window));
        if (presentation)
            window.setPresentation(true);
        window.showShortcuts();
        auto* dialog = window.findChild<ShortcutsDialog*>();
        QVERIFY(dialog);
        QVERIFY(waitExposed(dialog));
        QVERIFY(waitFramed(dialog));
        QTRY_VERIFY2_WITH_TIMEOUT(frameProblem(dialog).isEmpty(), qPrintable(frameProblem(dialog)), kEventWaitMs);
        auto* close = dialog->findChild<QPushButton*>();
        QVERIFY(close && close->isVisible());
        const QRect closeOnScreen(close->mapToGlobal(QPoint()), close->size());
        QVERIFY(dialog->screen()->availableGeometry().contains(closeOnScreen));
        QTextBrowser* text = dialog->browser();
        const double textHeight = text->document()->size().height();
        QVERIFY(textHeight > 0);
        QVERIFY2(
            textHeight <= text->viewport()->height() || text->verticalScrollBar()->maximum() > 0,
            qPrintable(
                QStringLiteral("text %1 px tall in %2 px that do not scroll").arg(textHeight).arg(text->viewport()->height())));
        // The last row can be scrolled into view: the scroll range covers what is hidden.
        QVERIFY(text->verticalScrollBar()->maximum() + text->viewport()->height() >= int(textHeight));
        dialog->close();
        if (presentation)
            window.setPresentation(false);
        granota::ui::setLanguage(QStringLiteral("en"), false);
    }

    // Alt+F opens the File menu, Esc closes it, and the keyboard is back in the window: Tab
    // moves the focus to the next visible control. (Qt used to leave the keyboard in the menu
    // bar with nothing highlighted: Tab and the arrows did nothing until a second Esc.)
    void escapeFromAMenuGivesTheKeyboardBack()
    {
        MainWindow window;
        QVERIFY(window.showTab(QStringLiteral("decasteljau")));
        window.showFitted();
        QVERIFY(waitExposed(&window));
        QVERIFY(waitActive(&window)); // Alt+F is the window's shortcut
        // The tab's first control that takes Tab.
        QWidget* start = window.currentTab();
        do
            start = start->nextInFocusChain();
        while (!(start->focusPolicy() & Qt::TabFocus) || !start->isVisible());
        start->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(start->hasFocus(), kEventWaitMs);
        QTest::keyClick(start, Qt::Key_F, Qt::AltModifier);
        QTRY_VERIFY_WITH_TIMEOUT(QApplication::activePopupWidget(), kEventWaitMs);
        QTest::keyClick(QApplication::activePopupWidget(), Qt::Key_Escape);
        QTRY_VERIFY_WITH_TIMEOUT(!QApplication::activePopupWidget(), kEventWaitMs);
        QTRY_VERIFY2_WITH_TIMEOUT(!window.menuBar()->hasFocus() && window.focusWidget() == start,
                                  qPrintable(QStringLiteral("the keyboard is with %1")
                                                 .arg(window.focusWidget() ? window.focusWidget()->metaObject()->className()
                                                                           : "nothing")),
                                  kEventWaitMs);
        QTest::keyClick(window.focusWidget(), Qt::Key_Tab);
        QWidget* next = window.focusWidget();
        QVERIFY(next && next != start && next != window.menuBar());
        QVERIFY(next->isVisible());
        QVERIFY(QRect(QPoint(), window.size()).intersects(QRect(next->mapTo(&window, QPoint()), next->size())));
    }
};

GRANOTA_TEST_MAIN(TestGuiScreenFit)
#include "test_gui_screen_fit.moc"
