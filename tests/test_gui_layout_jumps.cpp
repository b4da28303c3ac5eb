// Issue 34, item 11: nothing on the screen moves under the pointer because a text changed.
// At 1024×768 (less a title bar), in English and in Catalan:
// - the De Casteljau Play/Pause and the Frog Run/Pause buttons keep their geometry, and the
//   canvas beside them its size, when they are pressed (ui/common/widest_text_width.h);
// - the De Casteljau readout (s(t), L and κ(t)) keeps its height while t plays through [0, 1];
// - the Frog canvas keeps its size when the stopwatch's second line appears under it;
// - the Frog side panel keeps its scroll position when a refusal under it goes away.
// Each was measured on the code before the change: the play button changed width, the
// readout wrapped at some t, the canvas lost a line's height and the panel scrolled up.
#include "main_window_steps.h"
#include "ui/common/curve_canvas.h"
#include "ui/decasteljau/decasteljau_tab.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_tab.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"
#include "ui/common/tab_page.h"
#include "gui_timeouts.h"

#include <QAbstractButton>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QTest>
#include "tests/test_main.h"

using granota::ui::MainWindow;

namespace {


/// The geometry of `w` in its window's coordinates.
QRect inWindow(const QWidget* w) { return QRect(w->mapTo(w->window(), QPoint()), w->size()); }

/// The first widget of `tab` that draws a curve or the Frog scene (the tab's canvas).
QWidget* canvasOf(QWidget* tab)
{
    if (auto* frog = tab->findChild<granota::ui::FrogCanvas*>())
        return frog;
    return tab->findChild<granota::ui::CurveCanvas*>();
}

QString rectText(const QRect& r) { return QStringLiteral("%1,%2 %3×%4").arg(r.x()).arg(r.y()).arg(r.width()).arg(r.height()); }

} // namespace

class TestGuiLayoutJumps : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { useTestSettings(); }

    void playButtonKeepsItsPlace_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("tab");
        QTest::addColumn<QString>("button");
        for (const char* language : {"en", "ca"}) {
            QTest::addRow("%s De Casteljau", language) << language << "decasteljau"
                                                       << "decasteljauPlay";
            QTest::addRow("%s Frog", language) << language << "frog"
                                               << "frogPause";
        }
    }

    void playButtonKeepsItsPlace()
    {
        QFETCH(QString, language);
        QFETCH(QString, tab);
        QFETCH(QString, button);
        QVERIFY(granota::ui::setLanguage(language, false));
        MainWindow window;
        QVERIFY(showOnTab(window, tab));
        window.resize(kProjectorWindow);
        settle();
        auto* play = window.currentTab()->findChild<QAbstractButton*>(button);
        QVERIFY(play);
        QWidget* canvas = canvasOf(window.currentTab());
        QVERIFY(canvas);
        const QString before = play->text();
        const QRect buttonBefore = inWindow(play), canvasBefore = inWindow(canvas);
        for (int press = 0; press < 2; ++press) {
            play->toggle();
            settle();
            QVERIFY(play->text() != before || press == 1); // the text did change
            QVERIFY2(inWindow(play) == buttonBefore,
                     qPrintable(QStringLiteral("%1 → %2").arg(rectText(buttonBefore), rectText(inWindow(play)))));
            QVERIFY2(inWindow(canvas) == canvasBefore,
                     qPrintable(QStringLiteral("%1 → %2").arg(rectText(canvasBefore), rectText(inWindow(canvas)))));
        }
    }

    // t through [0, 1] as Play moves it, on Ex 2.3's curve and on the default one.
    void deCasteljauReadoutKeepsItsHeight_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << "en";
        QTest::newRow("ca") << "ca";
    }

    void deCasteljauReadoutKeepsItsHeight()
    {
        QFETCH(QString, language);
        QVERIFY(granota::ui::setLanguage(language, false));
        MainWindow window;
        QVERIFY(showOnProjector(window, QStringLiteral("decasteljau")));
        auto* tab = qobject_cast<granota::ui::DeCasteljauTab*>(window.currentTab());
        QVERIFY(tab);
        auto* readout = tab->findChild<QLabel*>(QStringLiteral("decasteljauReadout"));
        QVERIFY(readout);
        QWidget* canvas = canvasOf(tab);
        QVERIFY(canvas);
        int lowest = 1 << 30, highest = 0;
        QRect canvasFirst;
        for (int i = 0; i <= 200; ++i) {
            tab->setT(i / 200.0);
            settle();
            lowest = std::min(lowest, readout->height());
            highest = std::max(highest, readout->height());
            if (i == 0)
                canvasFirst = inWindow(canvas);
            QVERIFY2(
                inWindow(canvas) == canvasFirst,
                qPrintable(
                    QStringLiteral("t = %1: %2 → %3").arg(i / 200.0).arg(rectText(canvasFirst), rectText(inWindow(canvas)))));
        }
        QVERIFY2(lowest == highest, qPrintable(QStringLiteral("the readout is %1 to %2 px tall").arg(lowest).arg(highest)));
    }

    void stopwatchLineKeepsTheCanvas()
    {
        QVERIFY(granota::ui::setLanguage(QStringLiteral("en"), false));
        MainWindow window;
        QVERIFY(showOnProjector(window, QStringLiteral("frog")));
        granota::ui::FrogTab* tab = window.frogTab();
        tab->findChild<QPushButton*>(QStringLiteral("frogPause"))->setChecked(true);
        for (int i = 0; i < 30; ++i)
            tab->frogRun()->step();
        settle();
        auto* label = tab->findChild<QLabel*>(QStringLiteral("frogTimelineLabel"));
        QVERIFY(label);
        QVERIFY(!label->text().contains(QLatin1Char('\n')));
        const QRect before = inWindow(tab->canvas());
        tab->findChild<QPushButton*>(QStringLiteral("frogStopwatch"))->click();
        for (int i = 0; i < 30; ++i)
            tab->frogRun()->step();
        settle();
        QVERIFY(label->text().contains(QLatin1Char('\n'))); // the stopwatch's line is shown
        QVERIFY2(inWindow(tab->canvas()) == before,
                 qPrintable(QStringLiteral("%1 → %2").arg(rectText(before), rectText(inWindow(tab->canvas())))));
    }

    void sidePanelKeepsItsScrollWhenARefusalGoes()
    {
        QVERIFY(granota::ui::setLanguage(QStringLiteral("en"), false));
        MainWindow window;
        QVERIFY(showOnProjector(window, QStringLiteral("frog")));
        granota::ui::FrogTab* tab = window.frogTab();
        QString error;
        // many-bodies refuses 200 bodies of radius 40 (test_gui_acceptance): a refusal under the panel.
        QVERIFY2(tab->setScene(QStringLiteral("many-bodies"), &error), qPrintable(error));
        settle();
        auto* bodies = tab->findChild<QDoubleSpinBox*>(QStringLiteral("param_bodies__0"));
        QVERIFY(bodies);
        const double accepted = bodies->value();
        bodies->setValue(200);
        settle();
        auto* note = tab->findChild<QLabel*>(QStringLiteral("frogNote"));
        QVERIFY(note);
        QVERIFY(note->isVisible());
        QScrollArea* area = nullptr;
        for (QWidget* p = note->parentWidget(); p && !area; p = p->parentWidget())
            area = qobject_cast<QScrollArea*>(p);
        QVERIFY(area);
        QScrollBar* bar = area->verticalScrollBar();
        QVERIFY2(bar->maximum() > 0, "the panel scrolls at 1024×768");
        bar->setValue(bar->maximum()); // the user scrolled down to read the refusal
        const int scrolled = bar->value();
        bodies->setValue(accepted == 2 ? 3 : 2); // a value that fits: the refusal goes
        settle();
        QVERIFY(!note->isVisible());
        QCOMPARE(bar->value(), scrolled);
    }
};

GRANOTA_TEST_MAIN(TestGuiLayoutJumps)
#include "test_gui_layout_jumps.moc"
