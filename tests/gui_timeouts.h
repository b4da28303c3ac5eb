#pragma once
// How the GUI tests wait for what a desktop does in its own time.
#include <QCoreApplication>
#include <QDebug>
#include <QSize>
#include <QTest>
#include <QWidget>

/// How long a window may take to appear: a real window under Xvfb and a window manager on a
/// loaded machine (the sanitizer build, two tests at once) can take seconds more than Qt's
/// default of 5 s, and a test that gives up then fails for nothing it checks.
constexpr int kWindowExposedMs = 30000;

/// How long a QTRY_… or QTest::qWaitFor may wait for what the event loop brings in its own
/// time (timers, focus, a repaint). Qt's default of 5 s is not enough for a machine under
/// full load, and the wait ends as soon as the condition holds, so a generous bound costs a
/// passing test nothing.
constexpr int kEventWaitMs = 30000;

/// How a failed wait names the window it waited for: its class, object name and title.
inline QString describeWindow(const QWidget* window)
{
    return QStringLiteral("%1 '%2' (title '%3')")
        .arg(QString::fromLatin1(window->metaObject()->className()), window->objectName(), window->windowTitle());
}

/// Waits until the shown top-level `window` is on screen. A window mapped while the window
/// manager was still starting may never be exposed (the manager takes it over and the first
/// map is lost, seen under openbox for a test's first window): shown once more, it is.
inline bool waitExposed(QWidget* window)
{
    if (QTest::qWaitForWindowExposed(window, kWindowExposedMs / 3))
        return true;
    window->hide();
    window->show();
    if (QTest::qWaitForWindowExposed(window, kWindowExposedMs))
        return true;
    qWarning().noquote() << "the window system never exposed the window" << describeWindow(window) << "in"
                         << (kWindowExposedMs + kWindowExposedMs / 3) / 1000 << "s";
    return false;
}

/// Waits until `window` is also the active window: only then do its shortcuts (Ctrl+Z, …)
/// answer a key press, as on a desktop. Under a window manager on a loaded machine the
/// activation can come well after the window is exposed. Tests that only need a key to
/// reach a widget send it to that widget instead (QTest::keyClick(widget, …)): only a
/// window's shortcuts and the focus chain need the window manager's activation.
inline bool waitActive(QWidget* window)
{
    window->activateWindow();
    if (QTest::qWaitForWindowActive(window, kWindowExposedMs / 3))
        return true;
    window->raise();
    window->activateWindow();
    if (QTest::qWaitForWindowActive(window, kWindowExposedMs))
        return true;
    qWarning().noquote() << "the window manager never activated the window" << describeWindow(window) << "in"
                         << (kWindowExposedMs + kWindowExposedMs / 3) / 1000 << "s";
    return false;
}

/// A 1024×768 projector's screen less a title bar: the window size the classroom tests use.
inline const QSize kProjectorWindow(1024, 738);

/// Lets the layouts settle: the requests they post, and what the tabs queue after them (the
/// Frog's side panel fits its width in a queued call).
inline void settle()
{
    for (int round = 0; round < 3; ++round) {
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        QCoreApplication::processEvents();
    }
}
