// Where the keyboard is and what a presenter remote does (issue 34; docs/classroom.md,
// "Keyboard" and "Presenter remote"): a thick ring round every control with the focus, in
// presentation mode thicker; Page Up/Down turn the tabs (but in a control that pages itself),
// B blanks the screen, F5 is presentation mode; the Frog canvas comes early in the Tab order
// and its keyboard cursor starts on the body; the De Casteljau tab's Tab order runs forward;
// the status bar speaks of the keys while a canvas has the keyboard. Offscreen and, through
// tests/real_window/run.sh, in a real window.
#include "core/softbody/simulation.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/focus_frame.h"
#include "ui/bsplines/knot_ruler.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_tab.h"
#include "ui/shell/blank_screen.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "ui/common/tab_page.h"

#include "main_window_steps.h"

#include <QAbstractButton>
#include <QAbstractScrollArea>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QImage>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QTabBar>
#include <QTabWidget>
#include <QTest>
#include "tests/test_main.h"

#include <cmath>
#include <vector>

using granota::Point;
using granota::ui::CurveCanvas;
using granota::ui::FocusRing;
using granota::ui::FrogCanvas;
using granota::ui::MainWindow;

namespace {

void press(MainWindow& window, Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    QWidget* target = window.focusWidget() ? window.focusWidget() : &window;
    QTest::keyClick(target, key, modifiers);
}

/// A control Tab stops at, as a user sees it: not a part of a spin box or combo box, a
/// scroll bar, a scroll area's viewport or the tab bar's scroll buttons.
bool isOwnControl(QWidget* w)
{
    if (!(w->focusPolicy() & Qt::TabFocus) || qobject_cast<QScrollBar*>(w))
        return false;
    for (QWidget* p = w->parentWidget(); p; p = p->parentWidget())
        if (qobject_cast<QAbstractSpinBox*>(p) || qobject_cast<QComboBox*>(p))
            return false;
    if (auto* area = qobject_cast<QAbstractScrollArea*>(w->parentWidget()); area && area->viewport() == w)
        return false;
    return !qobject_cast<QTabBar*>(w->parentWidget());
}

QRect inWindow(const QWidget* w) { return {w->mapTo(w->window(), QPoint()), w->size()}; }

QLabel* hintLabel(MainWindow& window) { return window.findChild<QLabel*>(QStringLiteral("tabHint")); }

int tabIndex(MainWindow& window) { return static_cast<int>(window.tabs().indexOf(window.currentTab())); }

} // namespace

class TestGuiKeyboardFocus : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        useTestSettings();
        granota::ui::setLanguage(QStringLiteral("en"), false);
    }

    void aRingSurroundsEveryControl_data()
    {
        QTest::addColumn<bool>("presentation");
        QTest::newRow("normal") << false;
        QTest::newRow("presentation") << true;
    }

    // Every control of every tab, given the focus, has the ring round it: at least 3 px wide
    // (5 px in presentation mode, 3 × 1.6 rounded), just outside the control; a canvas draws
    // its own inside itself instead.
    void aRingSurroundsEveryControl()
    {
        QFETCH(bool, presentation);
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        if (presentation) {
            window.setPresentation(true, false);
            window.setSidePanelsShown(true); // the drawer open: every control to check
        }
        FocusRing* ring = window.focusRing();
        QVERIFY(ring);
        const int width = presentation ? 5 : 3;
        int controls = 0;
        for (granota::ui::TabPage* page : window.tabs()) {
            QVERIFY(window.showTab(page->key()));
            QApplication::processEvents();
            for (QWidget* w : page->findChildren<QWidget*>()) {
                if (!w->isVisible() || !isOwnControl(w) || !w->isEnabled())
                    continue;
                // In view, as Tab would scroll it (the ring is cut to what is in view).
                for (QWidget* p = w->parentWidget(); p; p = p->parentWidget())
                    if (auto* area = qobject_cast<QScrollArea*>(p))
                        area->ensureWidgetVisible(w, 0, 10);
                w->setFocus(Qt::TabFocusReason);
                QTRY_VERIFY_WITH_TIMEOUT(
                    window.focusWidget() && (w == window.focusWidget() || w->isAncestorOf(window.focusWidget())), kEventWaitMs);
                w = window.focusWidget(); // a tab widget's is its tab bar
                // The knot ruler is drawn like a canvas and draws its own ring too.
                const bool canvas = qobject_cast<CurveCanvas*>(w) || qobject_cast<FrogCanvas*>(w) ||
                                    qobject_cast<granota::ui::KnotRuler*>(w);
                const QString name = page->key() + QStringLiteral(": ") + QString::fromLatin1(w->metaObject()->className()) +
                                     QLatin1Char(' ') + w->objectName();
                if (canvas) {
                    QVERIFY2(!ring->isVisible(), qPrintable(name));
                    continue;
                }
                ++controls;
                QVERIFY2(ring->target() == w && ring->isVisible(), qPrintable(name));
                QCOMPARE(ring->ringWidth(), width);
                QCOMPARE(ring->ringRect(), inWindow(w).adjusted(-width, -width, width, width));
                QVERIFY(QRect(QPoint(), window.size()).contains(QRect(ring->mapTo(&window, QPoint()), ring->size())));
            }
        }
        QVERIFY(controls > 40);
        // On screen: the Frog tab's Pause button, ring and all, in the ring's colour.
        QVERIFY(window.showTab(QStringLiteral("frog")));
        auto* pause = window.frogTab()->findChild<QPushButton*>(QStringLiteral("frogPause"));
        QVERIFY(pause);
        for (QWidget* p = pause->parentWidget(); p; p = p->parentWidget())
            if (auto* area = qobject_cast<QScrollArea*>(p))
                area->ensureWidgetVisible(pause, 0, 10);
        pause->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(ring->target() == pause, kEventWaitMs);
        const QRect r = inWindow(pause);
        const QImage shot = window.grab().toImage();
        const double dpr = shot.devicePixelRatio();
        // Above and below the button (at its sides the panel's edge may cut the ring).
        for (const QPoint p :
             {QPoint(r.center().x(), r.top() - width / 2 - 1), QPoint(r.center().x(), r.bottom() + width / 2 + 1)})
            QCOMPARE(QColor(shot.pixel(int(p.x() * dpr), int(p.y() * dpr))).name(), granota::ui::kFocusRingColour.name());
        pause->clearFocus();
        QTRY_VERIFY_WITH_TIMEOUT(!ring->isVisible(), kEventWaitMs);
        if (presentation)
            window.setPresentation(false, false);
    }

    // Page Down and Page Up, a presenter remote's next and previous, turn the tabs from the
    // canvas or a button; in a spin box they step it by ten as ever, and the tab stays.
    void pageKeysTurnTheTabs()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        CurveCanvas* canvas = window.currentTab()->findChild<CurveCanvas*>();
        canvas->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(canvas->hasFocus(), kEventWaitMs);
        press(window, Qt::Key_PageDown);
        QCOMPARE(tabIndex(window), 1);
        // The keyboard stays where Page Up/Down still turn the tabs (the new tab's canvas, or
        // the tab bar), never in a field of the new tab that would take them.
        QVERIFY(window.focusWidget() && !qobject_cast<QAbstractSpinBox*>(window.focusWidget()));
        press(window, Qt::Key_PageUp);
        press(window, Qt::Key_PageUp);
        QCOMPARE(tabIndex(window), int(window.tabs().size()) - 1); // round
        // A spin box keeps its page keys.
        QVERIFY(window.showTab(QStringLiteral("fit")));
        QSpinBox* spin = nullptr;
        for (QSpinBox* s : window.currentTab()->findChildren<QSpinBox*>())
            if (s->isVisible() && s->isEnabled() && s->value() + 10 <= s->maximum()) {
                spin = s;
                break;
            }
        QVERIFY(spin);
        spin->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(spin->hasFocus(), kEventWaitMs);
        const int before = spin->value();
        press(window, Qt::Key_PageUp);
        QCOMPARE(window.currentTab()->key(), QStringLiteral("fit"));
        QVERIFY2(spin->value() > before, qPrintable(QStringLiteral("%1 → %2").arg(before).arg(spin->value())));
    }

    // B blanks the window and B brings it back; F5 turns presentation mode on and off.
    void bBlanksAndF5Presents()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        CurveCanvas* canvas = window.currentTab()->findChild<CurveCanvas*>();
        canvas->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(canvas->hasFocus(), kEventWaitMs);
        granota::ui::BlankScreen* blank = window.blankScreen();
        QVERIFY(!blank->blank());
        press(window, Qt::Key_B);
        QVERIFY(blank->blank());
        QCOMPARE(blank->geometry(), window.rect());
        // Black everywhere, the menu bar included.
        const QImage shot = window.grab().toImage();
        for (const QPoint p :
             {QPoint(2, 2), QPoint(shot.width() / 2, shot.height() / 2), QPoint(shot.width() - 3, shot.height() - 3)})
            QCOMPARE(QColor(shot.pixel(p)), QColor(Qt::black));
        press(window, Qt::Key_B);
        QVERIFY(!blank->blank());
        press(window, Qt::Key_F5);
        QVERIFY(window.presentation());
        press(window, Qt::Key_F5);
        QVERIFY(!window.presentation());
    }

    // The Frog tab: from the tab bar, Tab reaches the canvas before any control of the side
    // panel; the canvas's keyboard cursor starts on the body, not at the corner (0, 0).
    void theFrogCanvasComesFirstAndItsCursorOnTheBody()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("frog")));
        QVERIFY(window.frogTab()->setScene(QStringLiteral("frog"), nullptr));
        auto* canvas = window.frogTab()->findChild<FrogCanvas*>();
        auto* scene = window.frogTab()->findChild<QComboBox*>(QStringLiteral("frogScene"));
        QVERIFY(canvas && scene);
        canvas->frogRun()->setRunning(false);
        QTabBar* bar = window.findChild<QTabWidget*>()->tabBar();
        QStringList order;
        for (QWidget* w = bar->nextInFocusChain(); w != bar; w = w->nextInFocusChain()) {
            if (w == canvas || w == scene) {
                QVERIFY2(w == canvas, "the scene box comes before the canvas");
                break;
            }
            if (window.frogTab()->isAncestorOf(w) && w->isVisible() && isOwnControl(w))
                order << w->objectName();
        }
        QVERIFY2(order.isEmpty(), qPrintable(QStringLiteral("before the canvas: ") + order.join(QStringLiteral(", "))));
        canvas->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(canvas->hasFocus(), kEventWaitMs);
        // The body's centre, the mean of its vertices, computed here from the simulation.
        std::vector<Point> v;
        canvas->frogRun()->simulation()->bodyVertices(0, v);
        Point c{0, 0};
        for (const Point& p : v)
            c = {c.x + p.x / double(v.size()), c.y + p.y / double(v.size())};
        const Point cursor = canvas->keyboardCursor();
        QVERIFY2(std::hypot(cursor.x - c.x, cursor.y - c.y) < 1e-9,
                 qPrintable(QStringLiteral("cursor (%1, %2), body at (%3, %4)").arg(cursor.x).arg(cursor.y).arg(c.x).arg(c.y)));
    }

    // The De Casteljau tab: Tab from the tab bar goes through the tab in reading order,
    // never back up and to the left (a step up is to the next column, on the right).
    void theDeCasteljauTabOrderRunsForward()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        QTabBar* bar = window.findChild<QTabWidget*>()->tabBar();
        bar->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(bar->hasFocus(), kEventWaitMs);
        QStringList path;
        QWidget* previous = nullptr;
        for (int i = 0; i < 80; ++i) {
            press(window, Qt::Key_Tab);
            QWidget* now = window.focusWidget();
            QVERIFY(now);
            if (!window.currentTab()->isAncestorOf(now))
                break; // out of the tab
            const QRect b = inWindow(now);
            path << QStringLiteral("%1 %2 at (%3, %4)")
                        .arg(QString::fromLatin1(now->metaObject()->className()), now->objectName())
                        .arg(b.x())
                        .arg(b.y());
            if (previous) {
                // Back: above the previous control's top and not to the right of its left edge.
                const QRect a = inWindow(previous);
                QVERIFY2(b.top() >= a.top() || b.left() > a.left(),
                         qPrintable(QStringLiteral("jumps back: ") + path.join(QStringLiteral(" → "))));
            }
            previous = now;
        }
        QVERIFY2(path.size() > 5, qPrintable(path.join(QStringLiteral(" → "))));
    }

    // The status bar speaks of the keys while a canvas has the keyboard, of the mouse when not.
    void theHintFollowsTheKeyboard()
    {
        MainWindow window;
        for (const char* key : {"decasteljau", "fit", "catmull-rom", "frog", "bspline"}) {
            QVERIFY(showOnTab(window, QString::fromLatin1(key)));
            granota::ui::TabPage* page = window.currentTab();
            QVERIFY(!page->keyboardHint().isEmpty());
            QVERIFY(page->keyboardHint() != page->hint());
            QWidget* canvas = page->findChild<CurveCanvas*>();
            if (!canvas)
                canvas = page->findChild<FrogCanvas*>();
            QVERIFY(canvas);
            canvas->setFocus(Qt::TabFocusReason);
            QTRY_COMPARE_WITH_TIMEOUT(hintLabel(window)->text(), page->keyboardHint(), kEventWaitMs);
            page->findChild<QAbstractButton*>()->setFocus(Qt::TabFocusReason);
            QTRY_COMPARE_WITH_TIMEOUT(hintLabel(window)->text(), page->hint(), kEventWaitMs);
        }
    }
};

GRANOTA_TEST_MAIN(TestGuiKeyboardFocus)
#include "test_gui_keyboard_focus.moc"
