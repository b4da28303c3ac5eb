// The keyboard and accessibility pass (docs/classroom.md, "Keyboard"): a projector remote or
// a keyboard alone drives every tab of the shown main window, with real key events on the
// widget that has the focus (QTest::keyClick), and a screen reader finds a name for every
// control and a summary of every canvas. The same executable runs offscreen and, through
// tests/real_window/run.sh, under Xvfb with a window manager.
#include "core/curves/bezier/de_casteljau.h"
#include "core/exact/rational.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/number_text.h"
#include "ui/common/point_editor.h"
#include "ui/decasteljau/decasteljau_tab.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_tab.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "ui/common/tab_page.h"

#include "main_window_steps.h"

#include <QAbstractButton>
#include <QAbstractScrollArea>
#include <QAbstractSpinBox>
#include <QAccessible>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QImage>
#include <QPushButton>
#include <QScrollBar>
#include <QTabBar>
#include <QUndoStack>
#include <QTabWidget>
#include <QTest>
#include "tests/test_main.h"

#include <cmath>
#include <vector>

using granota::Point;
using granota::ui::CurveCanvas;
using granota::ui::DeCasteljauTab;
using granota::ui::FrogCanvas;
using granota::ui::MainWindow;

namespace {

/// A key as the user presses it: on the window's focus widget, else on the window. (The
/// window's own focus widget, not QApplication's: that one is null until the window manager
/// has activated the window, which a busy machine may not have done yet.)
void press(MainWindow& window, Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    QWidget* target = window.focusWidget() ? window.focusWidget() : &window;
    QTest::keyClick(target, key, modifiers);
}

/// The Frog tab shown on the frog stage, paused, its canvas holding the focus; null if not.
FrogCanvas* focusedFrogCanvas(MainWindow& window)
{
    if (!showOnTab(window, QStringLiteral("frog")) || !window.frogTab()->setScene(QStringLiteral("frog"), nullptr))
        return nullptr;
    auto* canvas = window.frogTab()->findChild<FrogCanvas*>();
    if (!canvas)
        return nullptr;
    canvas->frogRun()->setRunning(false);
    canvas->setFocus(Qt::TabFocusReason);
    return QTest::qWaitFor([canvas] { return canvas->hasFocus(); }, kEventWaitMs) ? canvas : nullptr;
}

/// The curve canvas of the tab shown.
CurveCanvas* curveCanvas(MainWindow& window) { return window.currentTab()->findChild<CurveCanvas*>(); }

Point centroid(const granota::Simulation& sim)
{
    std::vector<Point> v;
    sim.bodyVertices(0, v);
    Point c{0, 0};
    for (const Point& p : v)
        c = {c.x + p.x / double(v.size()), c.y + p.y / double(v.size())};
    return c;
}

QString accessibleText(QWidget* w, QAccessible::Text t)
{
    QAccessibleInterface* a = QAccessible::queryAccessibleInterface(w);
    return a ? a->text(t) : QString();
}

/// Widgets a screen reader does not present as controls of their own: those that take no
/// keyboard focus and show nothing to read (containers, layouts' frames), the parts of a
/// composite control (a spin box's or a combo box's line edit, a scroll area's viewport and
/// its scroll bars, a tab widget's scroll buttons), which the control itself names.
bool isOwnControl(QWidget* w)
{
    if (!(w->focusPolicy() & Qt::TabFocus))
        return false;
    if (qobject_cast<QScrollBar*>(w))
        return false;
    for (QWidget* p = w->parentWidget(); p; p = p->parentWidget())
        if (qobject_cast<QAbstractSpinBox*>(p) || qobject_cast<QComboBox*>(p))
            return false;
    if (auto* area = qobject_cast<QAbstractScrollArea*>(w->parentWidget()); area && area->viewport() == w)
        return false;
    if (qobject_cast<QTabBar*>(w->parentWidget()))
        return false; // QTabBar's scroll buttons
    return true;
}

} // namespace

class TestGuiKeyboard : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QApplication::setApplicationName(QStringLiteral("granota-test-keyboard"));
        granota::ui::setLanguage(QStringLiteral("en"), false);
    }

    // Tab moves the focus out of a curve canvas to the next control (it used to select the
    // next point and keep the focus for ever); ] selects the next point instead.
    void tabLeavesACurveCanvas()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        QVERIFY(window.loadExample(QStringLiteral("2.2")));
        CurveCanvas* canvas = curveCanvas(window);
        QVERIFY(canvas);
        canvas->setFocus(Qt::OtherFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(canvas->hasFocus(), kEventWaitMs);
        auto* editor = window.currentTab()->findChild<granota::ui::PointEditor*>();
        QVERIFY(editor);
        editor->setSelected(0);
        press(window, Qt::Key_BracketRight);
        QCOMPARE(editor->selected(), 1);
        QVERIFY(canvas->hasFocus());
        press(window, Qt::Key_Tab);
        QVERIFY(!canvas->hasFocus());
        QVERIFY(window.focusWidget());
        QVERIFY(window.focusWidget() != canvas);
        QCOMPARE(editor->selected(), 1); // Tab selected nothing on its way out
        press(window, Qt::Key_Backtab, Qt::ShiftModifier);
        QVERIFY(canvas->hasFocus());
    }

    // Alt+arrows mold the curve at the current t (the keyboard's drag of the curve): c(t) moves
    // by one nudge step, the control points by the least change that does it,
    //   ΔP_i = B_i^n(t) Δ / Σ_j B_j^n(t)²  (molding.h),
    // a run of keys is one undo step, and Ctrl+Z gives the points back exactly. The plain
    // arrows still nudge the selected control point; no window shortcut takes Alt+arrows.
    void altArrowsMoldTheCurveAtT()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        auto* tab = qobject_cast<DeCasteljauTab*>(window.currentTab());
        QVERIFY(tab);
        tab->setT(0.25);
        CurveCanvas* canvas = curveCanvas(window);
        canvas->setFocus(Qt::OtherFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(canvas->hasFocus(), kEventWaitMs);
        auto* editor = tab->pointEditor();
        const std::vector<Point> before = editor->points();
        const int steps = tab->undoStack()->count();
        const double h = granota::toDouble(editor->nudgeStep(false));
        QVERIFY(h > 0);
        const double t = 0.25;
        // The cubic's Bernstein values at t, by hand: (1−t)³, 3t(1−t)², 3t²(1−t), t³.
        const double B[4] = {std::pow(1 - t, 3), 3 * t * std::pow(1 - t, 2), 3 * t * t * (1 - t), std::pow(t, 3)};
        const double sumSquares = B[0] * B[0] + B[1] * B[1] + B[2] * B[2] + B[3] * B[3];
        QCOMPARE(before.size(), std::size_t(4));
        const auto expectAfter = [&](Point delta) {
            const auto& now = editor->points();
            QCOMPARE(now.size(), before.size());
            for (std::size_t i = 0; i < 4; ++i) {
                const Point want = before[i] + (B[i] / sumSquares) * delta;
                QVERIFY2(granota::distance(now[i], want) < 1e-12, qPrintable(QStringLiteral("P%1").arg(i)));
            }
            const Point c0 = granota::deCasteljauPoint(before, t), c1 = granota::deCasteljauPoint(now, t);
            QVERIFY(granota::distance(c1 - c0, delta) < 1e-12);
        };
        press(window, Qt::Key_Right, Qt::AltModifier);
        expectAfter({h, 0});
        press(window, Qt::Key_Up, Qt::AltModifier);
        press(window, Qt::Key_Up, Qt::AltModifier);
        expectAfter({h, 2 * h});
        QCOMPARE(tab->undoStack()->count(), steps + 1); // the run is one step
        QCOMPARE(editor->selected(), -1);               // no control point was nudged
        // Shift: ten steps.
        press(window, Qt::Key_Left, Qt::AltModifier | Qt::ShiftModifier);
        expectAfter({-9 * h, 2 * h});
        QCOMPARE(tab->undoStack()->count(), steps + 1);
        press(window, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(editor->points(), before);
        // The plain arrow nudges the selected control point, as before.
        editor->setSelected(1);
        press(window, Qt::Key_Right);
        QVERIFY(editor->points()[1].x > before[1].x);
        QCOMPARE(editor->points()[0], before[0]);
        QCOMPARE(editor->points()[2], before[2]);
        // No action of the window has Alt with an arrow.
        for (const QAction* a : window.findChildren<QAction*>())
            for (const QKeySequence& k : a->shortcuts())
                for (Qt::Key key : {Qt::Key_Left, Qt::Key_Right, Qt::Key_Up, Qt::Key_Down})
                    for (Qt::KeyboardModifiers m : {Qt::KeyboardModifiers(Qt::AltModifier), Qt::AltModifier | Qt::ShiftModifier})
                        QVERIFY2(k != QKeySequence(QKeyCombination(m, key)), qPrintable(a->text()));
    }

    // The canvas draws a frame while it has the focus: its pixels differ with and without.
    void aFocusedCanvasShowsItsFocus()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        CurveCanvas* canvas = curveCanvas(window);
        QVERIFY(canvas);
        window.currentTab()->findChild<QAbstractButton*>()->setFocus(Qt::OtherFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(!canvas->hasFocus(), kEventWaitMs);
        const QImage without = canvas->grab().toImage();
        canvas->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(canvas->hasFocus(), kEventWaitMs);
        const QImage with = canvas->grab().toImage();
        QCOMPARE(with.size(), without.size());
        // The frame runs along the edge: the corner pixel changes, the middle does not.
        QVERIFY(with.pixel(1, 1) != without.pixel(1, 1));
        QVERIFY(with.pixel(with.width() / 2, 1) != without.pixel(with.width() / 2, 1));
    }

    // Ctrl+Tab and Ctrl+Page Down go to the next tab, Ctrl+Shift+Tab and Ctrl+Page Up back,
    // from a canvas as from anywhere.
    void ctrlTabCyclesTabs()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        curveCanvas(window)->setFocus(Qt::OtherFocusReason);
        const auto index = [&] { return window.tabs().indexOf(window.currentTab()); };
        const int n = static_cast<int>(window.tabs().size());
        press(window, Qt::Key_Tab, Qt::ControlModifier);
        QCOMPARE(index(), 1);
        press(window, Qt::Key_PageDown, Qt::ControlModifier);
        QCOMPARE(index(), 2);
        press(window, Qt::Key_Backtab, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(index(), 1);
        press(window, Qt::Key_PageUp, Qt::ControlModifier);
        press(window, Qt::Key_PageUp, Qt::ControlModifier);
        QCOMPARE(index(), n - 1); // round again
    }

    // Ctrl+5 shows the Frog tab; P, S and R work at once, without a click; Tab reaches
    // Pause, Step and Reset.
    void frogKeysWorkWithoutAClick()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        curveCanvas(window)->setFocus(Qt::OtherFocusReason);
        press(window, Qt::Key_5, Qt::ControlModifier);
        QCOMPARE(window.currentTab()->key(), QStringLiteral("frog"));
        // Nothing in the tab has the focus, as when the tab was chosen on the tab bar.
        QTabBar* bar = window.findChild<QTabWidget*>()->tabBar();
        bar->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(bar->hasFocus(), kEventWaitMs);
        auto* canvas = window.frogTab()->findChild<FrogCanvas*>();
        QVERIFY(canvas && canvas->frogRun()->running());
        press(window, Qt::Key_P);
        QVERIFY(!canvas->frogRun()->running());
        const long before = canvas->frogRun()->simulation()->stepCount();
        press(window, Qt::Key_S);
        QCOMPARE(canvas->frogRun()->simulation()->stepCount(), before + 1);
        press(window, Qt::Key_R);
        QCOMPARE(canvas->frogRun()->simulation()->stepCount(), 0L);
        // [ and ] slow down and speed up (issue 16), also without a click.
        const double speed = canvas->frogRun()->speed();
        press(window, Qt::Key_BracketRight);
        QCOMPARE(canvas->frogRun()->speed(), 2 * speed);
        press(window, Qt::Key_BracketLeft);
        press(window, Qt::Key_BracketLeft);
        QCOMPARE(canvas->frogRun()->speed(), speed / 2);
        press(window, Qt::Key_BracketRight);
        QCOMPARE(canvas->frogRun()->speed(), speed);

        // (The canvas, its timeline and the stopwatch come first: tests/test_gui_keyboard_focus.cpp.)
        const QSet<QString> buttons{QStringLiteral("frogPause"), QStringLiteral("frogStep"), QStringLiteral("frogReset")};
        QSet<QString> reached;
        for (int i = 0; i < 60 && reached.size() < 3; ++i) {
            press(window, Qt::Key_Tab);
            if (QWidget* f = window.focusWidget())
                if (buttons.contains(f->objectName()))
                    reached.insert(f->objectName());
        }
        QCOMPARE(reached, buttons);
    }

    // The keyboard's grab: G grabs the body at the keyboard cursor, the arrows drag it, Esc
    // lets go. The body's centroid follows the presses.
    void aKeyboardGrabMovesTheBody()
    {
        MainWindow window;
        FrogCanvas* canvas = focusedFrogCanvas(window);
        QVERIFY(canvas);
        for (int i = 0; i < 30; ++i) // let it settle
            canvas->frogRun()->step();
        const Point start = centroid(*canvas->frogRun()->simulation());
        press(window, Qt::Key_G);
        QVERIFY(canvas->frogRun()->simulation()->grabbing());
        for (int i = 0; i < 8; ++i)
            press(window, Qt::Key_Right);
        for (int i = 0; i < 60; ++i)
            canvas->frogRun()->step();
        const Point moved = centroid(*canvas->frogRun()->simulation());
        QVERIFY2(moved.x > start.x + 0.5 * 8 * FrogCanvas::kKeyboardStep,
                 qPrintable(QStringLiteral("%1 → %2").arg(start.x).arg(moved.x)));
        press(window, Qt::Key_Escape);
        QVERIFY(!canvas->frogRun()->simulation()->grabbing());
    }

    // Issue 16, the ruler from the keyboard: L lays one end at the keyboard cursor, the
    // arrows take the other, L fixes it; Esc clears it, and with nothing held or laid Esc
    // changes nothing else. In a real window too (no shortcut takes L or Esc first).
    void aKeyboardRulerMeasures()
    {
        MainWindow window;
        FrogCanvas* canvas = focusedFrogCanvas(window);
        QVERIFY(canvas);
        press(window, Qt::Key_L);
        for (int i = 0; i < 5; ++i)
            press(window, Qt::Key_Down);
        press(window, Qt::Key_L);
        QVERIFY(canvas->ruler());
        QCOMPARE(canvas->ruler()->second.y - canvas->ruler()->first.y, 5 * FrogCanvas::kKeyboardStep);
        QCOMPARE(canvas->ruler()->second.x, canvas->ruler()->first.x);
        QVERIFY(!canvas->frogRun()->simulation()->grabbing());
        QVERIFY(canvas->hasFocus());
        press(window, Qt::Key_Escape);
        QVERIFY(!canvas->ruler());
        QVERIFY(canvas->hasFocus());
        QCOMPARE(window.currentTab(), static_cast<granota::ui::TabPage*>(window.frogTab()));
    }

    // Every control of every tab has a name for a screen reader (the rule: isOwnControl).
    void everyControlHasAnAccessibleName()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        QStringList unnamed;
        for (const auto* page : window.tabs()) {
            QVERIFY(window.showTab(page->key()));
            for (QWidget* w : window.findChildren<QWidget*>())
                if (w->isVisible() && isOwnControl(w) && accessibleText(w, QAccessible::Name).trimmed().isEmpty())
                    unnamed << QStringLiteral("%1: %2 (%3)")
                                   .arg(page->key(), w->objectName(), QString::fromLatin1(w->metaObject()->className()));
        }
        unnamed.removeDuplicates();
        QVERIFY2(unnamed.isEmpty(), qPrintable(unnamed.join(QStringLiteral(", "))));
    }

    // The De Casteljau canvas tells a screen reader the curve, t and c(t), and follows t.
    void theDeCasteljauCanvasDescribesTAndCOfT()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("decasteljau")));
        auto* tab = qobject_cast<DeCasteljauTab*>(window.currentTab());
        QVERIFY(tab);
        CurveCanvas* canvas = curveCanvas(window);
        for (double t : {0.25, 0.75}) {
            tab->setT(t);
            const Point c = granota::deCasteljau(tab->findChild<granota::ui::PointEditor*>()->points(), t).point();
            const QString text = accessibleText(canvas, QAccessible::Description);
            QVERIFY2(text.contains(granota::ui::displayNumber(t)), qPrintable(text));
            QVERIFY2(text.contains(granota::ui::displayPoint(c.x, c.y)), qPrintable(text));
        }
        QVERIFY(!accessibleText(canvas, QAccessible::Name).isEmpty());
    }

    // The Frog canvas tells the scene, the solver and the area error.
    void theFrogCanvasDescribesTheAreaError()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("frog")));
        auto* canvas = window.frogTab()->findChild<FrogCanvas*>();
        canvas->frogRun()->setRunning(false);
        canvas->frogRun()->step();
        const QString text = accessibleText(canvas, QAccessible::Description);
        const QString error = granota::ui::displayFixed(canvas->frogRun()->simulation()->readouts().areaErrorPercent, 1);
        QVERIFY2(text.contains(QStringLiteral("area error ") + error), qPrintable(text));
    }

    // Help ▸ Keyboard shortcuts lists every key of every action of the window.
    void theShortcutsHelpListsEveryShortcut()
    {
        MainWindow window;
        const QString help = window.shortcutsHelp();
        int keys = 0;
        for (const QAction* a : window.findChildren<QAction*>())
            for (const QKeySequence& k : a->shortcuts()) {
                ++keys;
                QVERIFY2(help.contains(k.toString(QKeySequence::NativeText).toHtmlEscaped()),
                         qPrintable(k.toString(QKeySequence::NativeText)));
            }
        QVERIFY(keys > 20);
        QVERIFY(help.contains(QStringLiteral("Ctrl+Tab")));
    }
};

GRANOTA_TEST_MAIN(TestGuiKeyboard)
#include "test_gui_keyboard.moc"
