// Issue 34, items 2 and 3: the mouse wheel and the undo keys over the side panels' fields
// (ui/common/field_input_filter.h, docs/classroom.md "Wheel and undo in the fields"), and the
// Frog run a parameter change replaces, kept for Undo (docs/rewind.md "A change of the scene").
// The events go through Qt's own delivery as a desktop's do: wheel events spontaneous, to the
// widget under the pointer (Qt passes an ignored one on to its parents); keys through the
// shortcut machinery (QTest::keyClick sends the ShortcutOverride first, and the window's
// shortcuts answer once it is active). tests/real_window/run.sh runs the same suite under Xvfb
// and openbox.
#include "core/softbody/recorded_run.h"
#include "core/softbody/simulation.h"
#include "core/softbody/simulation_trace.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_tab.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "ui/common/tab_page.h"

#include "main_window_steps.h"

#include <QAbstractScrollArea>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QScrollArea>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollBar>
#include <QSpinBox>
#include <QStatusBar>
#include <QTest>
#include <QUndoStack>
#include <QWheelEvent>
#include "tests/test_main.h"
#include "gui_timeouts.h"

#include <string>
#include <vector>

using granota::Point;
using granota::Simulation;
using granota::SolverKind;
using granota::ui::FrogCanvas;
using granota::ui::FrogTab;
using granota::ui::MainWindow;
using granota::ui::TabPage;

namespace {

/// Every control of `page` whose value the wheel could change (scroll bars aside).
QList<QWidget*> valueControls(QWidget* page)
{
    QList<QWidget*> out;
    for (QWidget* w : page->findChildren<QWidget*>()) {
        if (qobject_cast<QScrollBar*>(w))
            continue;
        if (qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QComboBox*>(w) || qobject_cast<QAbstractSlider*>(w))
            out << w;
    }
    return out;
}

/// What a control shows: its text (a spin box, a combo box) or its value (a slider).
QString valueOf(const QWidget* w)
{
    if (const auto* box = qobject_cast<const QAbstractSpinBox*>(w))
        return box->text();
    if (const auto* combo = qobject_cast<const QComboBox*>(w))
        return QString::number(combo->currentIndex());
    return QString::number(static_cast<const QAbstractSlider*>(w)->value());
}

/// One notch of a mouse wheel (120 eighths of a degree; negative: towards the user, down
/// the page) at `pos` of `window`, as the window hands it on: to the widget under the pointer,
/// spontaneous, so that QApplication gives the focus as the widget's policy says and passes an
/// ignored event on to the parents.
void wheelAt(QWidget& window, const QPoint& pos, int delta)
{
    QWidget* under = window.childAt(pos);
    if (!under)
        under = &window;
    QWheelEvent event(under->mapFrom(&window, QPointF(pos)), window.mapToGlobal(QPointF(pos)), QPoint(), QPoint(0, delta),
                      Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QSpontaneKeyEvent::setSpontaneous(&event); // as from the window system (sendEvent would make it synthetic)
    qApp->notify(under, &event);
    QCoreApplication::processEvents();
}


/// The scroll area that scrolls `w`, or null.
QAbstractScrollArea* scrollAreaOf(QWidget* w)
{
    for (QWidget* p = w->parentWidget(); p; p = p->parentWidget())
        if (auto* area = qobject_cast<QAbstractScrollArea*>(p); area && area->viewport()->isAncestorOf(w))
            return area;
    return nullptr;
}

/// What the tabs keep as a document, the Frog's recorded run aside (it grows with the clock).
QList<QJsonObject> settingsOf(const MainWindow& window)
{
    QList<QJsonObject> out;
    for (const TabPage* page : window.tabs()) {
        QJsonObject state = page->saveState();
        state.remove(QStringLiteral("recording"));
        out << state;
    }
    return out;
}

/// Where the run is: its trace row (every position, velocity and readout the CLI's trace
/// writes) and every body vertex, exactly.
struct RunState {
    long step = 0, recorded = 0;
    std::string row;
    std::vector<Point> vertices;
    bool operator==(const RunState& o) const
    {
        return step == o.step && recorded == o.recorded && row == o.row && vertices == o.vertices;
    }
};
RunState runState(const FrogCanvas& canvas)
{
    const Simulation& sim = *canvas.frogRun()->simulation();
    RunState s{sim.stepCount(), canvas.frogRun()->recordedSteps(), granota::simulationTraceRow(sim), {}};
    std::vector<Point> v;
    for (int b = 0; b < sim.bodyCount(); ++b) {
        sim.bodyVertices(b, v);
        s.vertices.insert(s.vertices.end(), v.begin(), v.end());
    }
    return s;
}

/// The mean of body 0's vertices, scene px.
Point centroid(const Simulation& sim)
{
    std::vector<Point> v;
    sim.bodyVertices(0, v);
    Point c(0, 0);
    for (const Point& p : v)
        c += p;
    return Point(c.x / double(v.size()), c.y / double(v.size()));
}

/// A run of 60 + 30 + 90 = 180 steps on `tab`'s canvas with a grab and a throw made with the
/// canvas's own mouse events, so that the run has recorded events as well as steps.
void recordAThrow(FrogTab& tab)
{
    FrogCanvas* canvas = tab.canvas();
    for (int i = 0; i < 60; ++i)
        canvas->frogRun()->step();
    const QPoint at = canvas->toWidget(centroid(*canvas->frogRun()->simulation())).toPoint();
    QTest::mouseMove(canvas, at);
    QTest::mousePress(canvas, Qt::LeftButton, Qt::NoModifier, at);
    for (int i = 1; i <= 15; ++i) {
        QTest::mouseMove(canvas, at + QPoint(8 * i, -5 * i));
        canvas->frogRun()->step();
        canvas->frogRun()->step();
    }
    QTest::mouseRelease(canvas, Qt::LeftButton, Qt::NoModifier, at + QPoint(120, -75));
    for (int i = 0; i < 90; ++i)
        canvas->frogRun()->step();
}

/// The value of a spin box, whole or decimal.
double numberIn(const QAbstractSpinBox* box)
{
    if (const auto* whole = qobject_cast<const QSpinBox*>(box))
        return whole->value();
    return static_cast<const QDoubleSpinBox*>(box)->value();
}

/// The spin box whose label (its buddy) reads `text` on `page`.
QAbstractSpinBox* spinBoxLabelled(QWidget* page, const QString& text)
{
    for (QLabel* label : page->findChildren<QLabel*>())
        if (label->text().remove(QLatin1Char('&')) == text)
            if (auto* box = qobject_cast<QAbstractSpinBox*>(label->buddy()))
                return box;
    return nullptr;
}

} // namespace

class TestGuiFieldInput : public QObject {
    Q_OBJECT

private slots:
    void initTestCase()
    {
        useTestSettings();
        granota::ui::setLanguage(QStringLiteral("en"), false); // the controls are found by their English text
    }

    // Item 2: on every tab at 1024×768, a wheel turned over each spin box, combo box and slider
    // that does not have the keyboard focus changes neither the control nor the document, and
    // adds no undo step; where the control is in a panel that scrolls, the panel scrolls.
    void wheelScrollsThePanelNotTheField_data()
    {
        QTest::addColumn<QString>("tab");
        for (const char* key : {"decasteljau", "bernstein", "fit", "catmull-rom", "frog", "bspline"})
            QTest::newRow(key) << QString::fromLatin1(key);
    }
    void wheelScrollsThePanelNotTheField()
    {
        QFETCH(QString, tab);
        MainWindow window;
        window.resize(1024, 768);
        window.show();
        QVERIFY(waitExposed(&window));
        QVERIFY(window.showTab(tab));
        TabPage* page = window.currentTab();
        if (auto* pause = page->findChild<QPushButton*>(QStringLiteral("frogPause")))
            pause->setChecked(true); // the run stands still: its state is what is compared
        settle();
        const QList<QJsonObject> settings = settingsOf(window);
        QList<int> undoCounts;
        for (const TabPage* p : window.tabs())
            undoCounts << p->undoStack()->count();
        int tried = 0, scrolled = 0;
        for (QWidget* control : valueControls(page)) {
            if (!control->isVisible() || !control->isEnabled())
                continue;
            QAbstractScrollArea* area = scrollAreaOf(control);
            if (auto* scroll = qobject_cast<QScrollArea*>(area))
                scroll->ensureWidgetVisible(control);
            settle();
            if (QWidget* focus = window.focusWidget())
                focus->clearFocus(); // the wheel is for a control only while it has the focus
            const QPoint centre = control->mapTo(&window, control->rect().center());
            QWidget* under = window.childAt(centre);
            if (under != control && !control->isAncestorOf(under))
                continue; // covered (another panel, or scrolled out of its viewport)
            ++tried;
            const QString before = valueOf(control);
            QScrollBar* bar = area ? area->verticalScrollBar() : nullptr;
            const bool canScroll = bar && bar->maximum() > bar->minimum();
            const int barBefore = bar ? bar->value() : 0;
            // Down the page where there is more below, else up.
            const int delta = !canScroll || barBefore < bar->maximum() ? -120 : 120;
            wheelAt(window, centre, delta);
            QVERIFY2(valueOf(control) == before,
                     qPrintable(QStringLiteral("%1 (%2): %3 → %4")
                                    .arg(control->objectName(), QString::fromLatin1(control->metaObject()->className()), before,
                                         valueOf(control))));
            QVERIFY2(!control->hasFocus(), qPrintable(control->objectName()));
            if (canScroll) {
                QVERIFY2(bar->value() != barBefore,
                         qPrintable(QStringLiteral("%1 (%2): the panel did not scroll")
                                        .arg(control->objectName(), QString::fromLatin1(control->metaObject()->className()))));
                ++scrolled;
            }
        }
        QVERIFY(tried >= 2); // every tab has a few
        if (tab == QLatin1String("frog"))
            QVERIFY(scrolled > 0); // its panel needs scrolling at 1024×768 (issue 34)
        QCOMPARE(settingsOf(window), settings);
        for (int i = 0; i < window.tabs().size(); ++i)
            QCOMPARE(window.tabs()[i]->undoStack()->count(), undoCounts[i]);
    }

    // …but a field that has the keyboard focus (clicked or tabbed into) still answers the wheel.
    void aFocusedFieldStillTakesTheWheel()
    {
        MainWindow window;
        QVERIFY(showOnTab(window, QStringLiteral("frog")));
        auto* factor = window.currentTab()->findChild<QDoubleSpinBox*>(QStringLiteral("param_area_factor__0"));
        QVERIFY(factor);
        qobject_cast<QScrollArea*>(scrollAreaOf(factor))->ensureWidgetVisible(factor);
        factor->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(factor->hasFocus(), kEventWaitMs);
        const auto centre = [&] { return factor->mapTo(&window, factor->rect().center()); };
        QTRY_VERIFY_WITH_TIMEOUT(factor->isAncestorOf(window.childAt(centre())), kEventWaitMs); // laid out
        const double before = factor->value();
        wheelAt(window, centre(), 120);
        QCOMPARE(factor->value(), before + factor->singleStep());
    }

    // Item 3: Ctrl+Z typed in a spin box's line edit undoes the document's last step (the
    // field's text committed first); Ctrl+Shift+Z and Ctrl+Y redo it.
    void undoKeysInAFieldAreTheDocuments_data()
    {
        QTest::addColumn<QString>("tab");
        QTest::addColumn<QString>("field"); // its label, or its object name
        QTest::addColumn<QString>("typed");
        QTest::addColumn<QString>("typedLater"); // without Enter
        QTest::newRow("Fitting, degree 3") << "fit"
                                           << "Degree n:"
                                           << "3"
                                           << "4";
        QTest::newRow("Frog, area factor") << "frog"
                                           << "param_area_factor__0"
                                           << "1.5"
                                           << "1.2";
        QTest::newRow("De Casteljau, samples") << "decasteljau"
                                               << "Samples:"
                                               << "50"
                                               << "60";
    }
    void undoKeysInAFieldAreTheDocuments()
    {
        QFETCH(QString, tab);
        QFETCH(QString, field);
        QFETCH(QString, typed);
        QFETCH(QString, typedLater);
        MainWindow window;
        QVERIFY(loadExamples(window, {"2.9"})); // five points fitted with degree 2: room for 3
        QVERIFY(showOnTab(window, tab));
        TabPage* page = window.currentTab();
        QAbstractSpinBox* box = page->findChild<QAbstractSpinBox*>(field);
        if (!box)
            box = spinBoxLabelled(page, field);
        QVERIFY2(box, qPrintable(field));
        if (auto* scroll = qobject_cast<QScrollArea*>(scrollAreaOf(box)))
            scroll->ensureWidgetVisible(box);
        box->setFocus(Qt::TabFocusReason);
        QLineEdit* edit = box->findChild<QLineEdit*>();
        QTRY_VERIFY_WITH_TIMEOUT(edit->hasFocus(), kEventWaitMs);
        QUndoStack* undo = page->undoStack();
        const int index = undo->index();
        const QString before = box->text();
        // Type the value and Enter: one undo step.
        QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(edit, typed);
        QTest::keyClick(edit, Qt::Key_Return);
        QCOMPARE(undo->index(), index + 1);
        const QString after = box->text();
        QVERIFY(after != before);
        // Ctrl+Z in the field: the document's undo.
        QTest::keyClick(edit, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(undo->index(), index);
        QCOMPARE(box->text(), before);
        // Ctrl+Shift+Z, and Ctrl+Y after another Ctrl+Z: its redo.
        QTest::keyClick(edit, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(undo->index(), index + 1);
        QCOMPARE(box->text(), after);
        QTest::keyClick(edit, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(box->text(), before);
        QTest::keyClick(edit, Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(undo->index(), index + 1);
        QCOMPARE(box->text(), after);
        // Typed without Enter, the text is committed first (a step, which may merge with the
        // last change of the same field) and then undone; Redo brings the typed value back.
        QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(edit, typedLater);
        QTest::keyClick(edit, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY2(box->text() == after || box->text() == before, qPrintable(box->text()));
        QTest::keyClick(edit, Qt::Key_Y, Qt::ControlModifier);
        QCOMPARE(numberIn(box), typedLater.toDouble()); // the test types in English (a point)
    }

    // Item 2: a parameter change replaces the Frog's run (the scene is built again), and
    // Undo brings the run back as it was — its steps, its recorded events and every position
    // — while Redo brings back the run of the new value; the status bar says so.
    void undoBringsBackTheRunAParameterChangeReplaced_data()
    {
        QTest::addColumn<int>("solver");
        QTest::newRow("seed") << int(SolverKind::Seed);
        QTest::newRow("stable") << int(SolverKind::Stable);
    }
    void undoBringsBackTheRunAParameterChangeReplaced()
    {
        QFETCH(int, solver);
        FrogTab tab;
        tab.resize(1280, 760);
        tab.show();
        QVERIFY(waitExposed(&tab));
        QVERIFY(tab.setScene(QStringLiteral("frog"), nullptr));
        QVERIFY(tab.setSolver(SolverKind(solver), nullptr));
        tab.findChild<QPushButton*>(QStringLiteral("frogPause"))->setChecked(true);
        QStringList messages;
        connect(&tab, &TabPage::statusMessage, &tab, [&messages](const QString& text) { messages << text; });
        FrogCanvas* canvas = tab.canvas();
        recordAThrow(tab);
        tab.toggleMark();             // the stopwatch at step 180
        canvas->frogRun()->seek(150); // shown at step 150 of 180
        const RunState run = runState(*canvas);
        QCOMPARE(run.step, 150L);
        QCOMPARE(run.recorded, 180L);
        const std::size_t events = canvas->frogRun()->recorded()->recording().events.size();
        QVERIFY(events > 10);
        // Two notches of the area factor (one merged undo step), as a spin box gives them.
        auto* factor = tab.findChild<QDoubleSpinBox*>(QStringLiteral("param_area_factor__0"));
        QVERIFY(factor);
        const double was = factor->value();
        const int count = tab.undoStack()->count();
        factor->stepUp();
        factor->stepUp();
        const double changedTo = factor->value();
        QVERIFY(changedTo > was);
        QCOMPARE(tab.undoStack()->count(), count + 1);
        QCOMPARE(canvas->frogRun()->recordedSteps(), 0L); // a new run
        QVERIFY2(messages.join('\n').contains(QStringLiteral("Undo brings back the run of 180 step")),
                 qPrintable(messages.join('\n')));
        for (int i = 0; i < 40; ++i)
            canvas->frogRun()->step();
        const RunState changed = runState(*canvas);
        tab.undoStack()->undo();
        QCOMPARE(factor->value(), was);
        QVERIFY(runState(*canvas) == run);
        QCOMPARE(canvas->frogRun()->recorded()->recording().events.size(), events);
        QCOMPARE(tab.markedStep(), 180L);
        QCOMPARE(tab.timeline()->maximum(), 180);
        QCOMPARE(tab.timeline()->value(), 150);
        // The run goes on as it went: to its end, as recorded.
        canvas->frogRun()->seek(180);
        QCOMPARE(canvas->frogRun()->simulation()->stepCount(), 180L);
        // Redo: the new value with the 40 steps it had run.
        tab.undoStack()->redo();
        QCOMPARE(factor->value(), changedTo);
        QVERIFY(runState(*canvas) == changed);
        tab.undoStack()->undo();
        QCOMPARE(canvas->frogRun()->simulation()->stepCount(), 180L);
        QCOMPARE(canvas->frogRun()->recordedSteps(), 180L);
    }

    // The same for the stage and the solver, chosen in their boxes.
    void undoBringsBackTheRunTheStageOrSolverReplaced()
    {
        FrogTab tab;
        tab.resize(1280, 760);
        tab.show();
        QVERIFY(waitExposed(&tab));
        QVERIFY(tab.setScene(QStringLiteral("frog"), nullptr));
        tab.findChild<QPushButton*>(QStringLiteral("frogPause"))->setChecked(true);
        FrogCanvas* canvas = tab.canvas();
        recordAThrow(tab);
        const RunState run = runState(*canvas);
        auto* solverBox = tab.findChild<QComboBox*>(QStringLiteral("frogSolver"));
        // As a user chooses in a box: the box's current item, and its activated() signal.
        const auto choose = [](QComboBox* box, int index) {
            box->setCurrentIndex(index);
            emit box->activated(index);
        };
        choose(solverBox, 1 - solverBox->currentIndex());
        QCOMPARE(tab.solver(), SolverKind::Stable);
        QCOMPARE(canvas->frogRun()->recordedSteps(), 0L);
        for (int i = 0; i < 20; ++i)
            canvas->frogRun()->step();
        auto* sceneBox = tab.findChild<QComboBox*>(QStringLiteral("frogScene"));
        choose(sceneBox, 0);
        QCOMPARE(tab.sceneName(), QStringLiteral("polygon"));
        QCOMPARE(canvas->frogRun()->recordedSteps(), 0L);
        tab.undoStack()->undo();
        QCOMPARE(tab.sceneName(), QStringLiteral("frog"));
        QCOMPARE(canvas->frogRun()->recordedSteps(), 20L); // the stable solver's run of 20 steps
        tab.undoStack()->undo();
        QVERIFY(runState(*canvas) == run);
        QCOMPARE(canvas->frogRun()->simulation()->solver(), SolverKind::Seed);
    }
};

GRANOTA_TEST_MAIN(TestGuiFieldInput)
#include "test_gui_field_input.moc"
