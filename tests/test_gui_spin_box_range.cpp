// Issue 34, item 11: a spin box never rewrites a typed value without a word
// (ui/common/field_input_filter.h, docs/classroom.md "Wheel and undo in the fields"). Typed
// out of range, a value is refused and the status bar says what the field accepts: "2" in
// the Frog polygon's sides (3 to 10 000) is not applied on Enter and stays to be corrected;
// leaving the field puts the last value back, and says so; a digit that takes the number past
// the maximum is refused, and that is said too. The keys are real QTest key clicks into the
// spin box, as a student types them.
#include "ui/frog/frog_tab.h"
#include "ui/common/language.h"
#include "ui/shell/main_window.h"

#include "main_window_steps.h"

#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QScrollArea>
#include <QStatusBar>
#include <QTest>
#include "tests/test_main.h"

using granota::ui::MainWindow;

namespace {

/// The message expected for the sides field, written out here from the box's own range (an
/// integer field: its minimum and maximum as whole numbers, no group separator in English).
QString sidesMessage(const QDoubleSpinBox& sides)
{
    return QStringLiteral("Sides N must be between %1 and %2.")
        .arg(static_cast<int>(sides.minimum()))
        .arg(static_cast<int>(sides.maximum()));
}

} // namespace

class TestGuiSpinBoxRange : public QObject {
    Q_OBJECT

    MainWindow* m_window = nullptr;
    QDoubleSpinBox* m_sides = nullptr;

private slots:
    void initTestCase()
    {
        useTestSettings();
        granota::ui::setLanguage(QStringLiteral("en"), false); // the message is checked in English
    }

    void init()
    {
        m_window = new MainWindow;
        QVERIFY(showOnTab(*m_window, QStringLiteral("frog")));
        QString error;
        QVERIFY2(m_window->frogTab()->setScene(QStringLiteral("polygon"), &error), qPrintable(error));
        m_sides = m_window->frogTab()->findChild<QDoubleSpinBox*>(QStringLiteral("param_sides__0"));
        QVERIFY(m_sides);
        QVERIFY(m_sides->minimum() == 3);
        QVERIFY(m_sides->maximum() > 10);
        for (QWidget* p = m_sides->parentWidget(); p; p = p->parentWidget())
            if (auto* area = qobject_cast<QScrollArea*>(p))
                area->ensureWidgetVisible(m_sides);
        m_sides->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(m_sides->hasFocus(), kEventWaitMs);
        m_window->statusBar()->clearMessage();
    }

    void cleanup()
    {
        delete m_window;
        m_window = nullptr;
    }

    // "2" and Enter: nothing applied, the text stays to be corrected, and the status bar says why.
    void belowTheMinimumIsRefusedOnEnter()
    {
        const double before = m_sides->value();
        m_sides->selectAll(); // as a double click on the old value
        QTest::keyClicks(m_sides, QStringLiteral("2"));
        QTest::keyClick(m_sides, Qt::Key_Return);
        QCOMPARE(m_sides->value(), before);
        QCOMPARE(m_sides->text(), QStringLiteral("2"));
        const QString message = m_window->statusBar()->currentMessage();
        QVERIFY2(message.startsWith(sidesMessage(*m_sides)), qPrintable(message));
        QVERIFY2(message.contains(QStringLiteral("2 was not applied")), qPrintable(message));

        // Corrected, it applies.
        m_sides->selectAll();
        QTest::keyClicks(m_sides, QStringLiteral("5"));
        QTest::keyClick(m_sides, Qt::Key_Return);
        QCOMPARE(m_sides->value(), 5.0);
    }

    // "2" and then leaving the field: Qt puts the last value back, and the status bar says so.
    void belowTheMinimumIsExplainedWhenLeaving()
    {
        const double before = m_sides->value();
        m_sides->selectAll();
        QTest::keyClicks(m_sides, QStringLiteral("2"));
        m_sides->clearFocus();
        QCOMPARE(m_sides->value(), before);
        const QString message = m_window->statusBar()->currentMessage();
        QVERIFY2(message.startsWith(sidesMessage(*m_sides)), qPrintable(message));
    }

    // One digit more than the maximum allows: the key is refused (as before), with a word.
    void aDigitPastTheMaximumIsExplained()
    {
        const QString maximum = QString::number(static_cast<int>(m_sides->maximum()));
        m_sides->selectAll();
        QTest::keyClicks(m_sides, maximum);
        QCOMPARE(m_sides->text(), maximum);
        QVERIFY(m_window->statusBar()->currentMessage().isEmpty()); // in range: nothing said
        QTest::keyClicks(m_sides, QStringLiteral("0"));
        QCOMPARE(m_sides->text(), maximum); // refused, as Qt does
        const QString message = m_window->statusBar()->currentMessage();
        QCOMPARE(message, sidesMessage(*m_sides));
        m_sides->selectAll(); // not the heaviest polygon when the window closes
        QTest::keyClicks(m_sides, QStringLiteral("5"));
    }
};

GRANOTA_TEST_MAIN(TestGuiSpinBoxRange)
#include "test_gui_spin_box_range.moc"
