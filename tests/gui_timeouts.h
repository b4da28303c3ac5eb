#pragma once
// How the GUI tests wait for what a desktop does in its own time.
#include <QTest>
#include <QWidget>

/// How long a window may take to appear: a real window under Xvfb and a window manager on a
/// loaded machine (the sanitizer build, two tests at once) can take seconds more than Qt's
/// default of 5 s, and a test that gives up then fails for nothing it checks.
constexpr int kWindowExposedMs = 30000;

/// Waits until the shown top-level `window` is on screen. A window mapped while the window
/// manager was still starting may never be exposed (the manager takes it over and the first
/// map is lost, seen under openbox for a test's first window): shown once more, it is.
inline bool waitExposed(QWidget* window)
{
    if (QTest::qWaitForWindowExposed(window, kWindowExposedMs / 3))
        return true;
    window->hide();
    window->show();
    return QTest::qWaitForWindowExposed(window, kWindowExposedMs);
}

/// Waits until `window` is also the active window: only then do its shortcuts (Ctrl+Z, …)
/// answer a key press, as on a desktop. Under a window manager on a loaded machine the
/// activation can come well after the window is exposed.
inline bool waitActive(QWidget* window)
{
    window->activateWindow();
    if (QTest::qWaitForWindowActive(window, kWindowExposedMs / 3))
        return true;
    window->raise();
    window->activateWindow();
    return QTest::qWaitForWindowActive(window, kWindowExposedMs);
}
