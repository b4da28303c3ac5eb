#pragma once
/// \file shortcuts_help.h
/// Help ▸ Keyboard shortcuts: every key of the window, so that a keyboard or a projector
/// remote alone can drive every tab (docs/classroom.md, "Keyboard"). The window's part is
/// read from its actions (text and shortcuts, as the menus show them), so it cannot go stale;
/// the keys of the canvases and of the Frog tab, which are no actions, are listed here once.

#include <QCoreApplication>
#include <QList>
#include <QString>

class QAction;

namespace granota::ui {

class ShortcutsHelp {
    Q_DECLARE_TR_FUNCTIONS(granota::ui::ShortcutsHelp)
public:
    /// The help as rich text: a table of the actions that have a shortcut (in the order
    /// given), then the keys of the curve canvases, the Frog tab and its canvas.
    static QString html(const QList<QAction*>& actions);
    /// The same in two columns, the window's keys beside the rest: what the dialog shows, so
    /// that it fits a projector's 768 px or 600 px (ShortcutsDialog).
    static QString twoColumnHtml(const QList<QAction*>& actions);

private:
    struct Parts {
        QString window;   ///< the actions' table
        QString canvases; ///< the canvases' and the Frog tab's tables
    };
    static Parts sections(const QList<QAction*>& actions);
};

} // namespace granota::ui
