#pragma once
// What several GUI tests do to a whole main window before they check it: load worked
// examples, put it on screen on one tab, take its document as File ▸ Save writes it, and
// a file to save it in.
#include "ui/shell/document.h"
#include "ui/shell/main_window.h"
#include "ui/common/tab_page.h"
#include "gui_timeouts.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QStandardPaths>
#include <QString>
#include <QTemporaryDir>
#include <QTest>

#include <initializer_list>

/// Settings and autosaves of a GUI test in QStandardPaths' test folders, under a name of
/// their own: a test never reads or writes the user's.
inline void useTestSettings()
{
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName(QStringLiteral("GranotaTest"));
    QCoreApplication::setApplicationName(QStringLiteral("GranotaTest"));
}

/// Loads the worked examples `ids` ("2.3") into `window`, in order, as the Examples menu
/// does: false at the first that does not load.
inline bool loadExamples(granota::ui::MainWindow& window, std::initializer_list<const char*> ids)
{
    for (const char* id : ids)
        if (!window.loadExample(QString::fromLatin1(id)))
            return false;
    return true;
}

/// The document of `window` as File ▸ Save writes it: every tab, on the tab shown.
inline QByteArray documentOf(const granota::ui::MainWindow& window)
{
    return granota::ui::serializeDocument(window.tabs(), window.currentTab()->key());
}

/// Shows `window` at the classroom size 1280×800, waits until it is on screen and active and shows the
/// tab `key`: false if the window never appeared or has no such tab.
inline bool showOnTab(granota::ui::MainWindow& window, const QString& key)
{
    window.resize(1280, 800);
    window.show();
    return waitExposed(&window) && waitActive(&window) && window.showTab(key);
}

/// showOnTab, then the window at a 1024×768 projector's size (kProjectorWindow) with its
/// layouts settled.
inline bool showOnProjector(granota::ui::MainWindow& window, const QString& key)
{
    if (!showOnTab(window, key))
        return false;
    window.resize(kProjectorWindow);
    settle();
    return true;
}

/// A document file `name` in a fresh temporary folder, removed with it: where a round trip
/// saves a window's document and opens it again.
class TemporaryDocument {
public:
    explicit TemporaryDocument(const QString& name) : m_path(m_dir.filePath(name)) {}
    QString path() const { return m_path; }

private:
    QTemporaryDir m_dir;
    QString m_path;
};
