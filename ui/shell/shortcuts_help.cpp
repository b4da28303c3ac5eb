#include "ui/shell/shortcuts_help.h"

#include <QAction>
#include <QKeySequence>

namespace granota::ui {

namespace {

QString row(const QString& keys, const QString& what)
{
    return QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(keys.toHtmlEscaped(), what.toHtmlEscaped());
}

QString table(const QString& title, const QString& rows)
{
    return QStringLiteral("<h4>%1</h4><table cellspacing=\"2\" cellpadding=\"3\">%2</table>").arg(title.toHtmlEscaped(), rows);
}

} // namespace

QString ShortcutsHelp::html(const QList<QAction*>& actions)
{
    const Parts parts = sections(actions);
    return parts.window + parts.canvases;
}

QString ShortcutsHelp::twoColumnHtml(const QList<QAction*>& actions)
{
    // Two cells side by side: the window's keys, then the canvases' and the Frog tab's.
    const Parts parts = sections(actions);
    return QStringLiteral("<table width=\"100%\" cellspacing=\"0\" cellpadding=\"0\"><tr>"
                          "<td valign=\"top\" width=\"50%\">%1</td><td width=\"16\"></td>"
                          "<td valign=\"top\">%2</td></tr></table>")
        .arg(parts.window, parts.canvases);
}

ShortcutsHelp::Parts ShortcutsHelp::sections(const QList<QAction*>& actions)
{
    QString window;
    for (const QAction* a : actions) {
        if (a->shortcuts().isEmpty())
            continue;
        QStringList keys;
        for (const QKeySequence& k : a->shortcuts())
            keys << k.toString(QKeySequence::NativeText);
        window += row(keys.join(tr(", ")), QString(a->text()).remove(QLatin1Char('&')));
    }
    const QString curves = row(tr("Tab, Shift+Tab"),
                               tr("Move the focus into and out of the canvas, to the next or previous control")) +
                           row(tr("] and ["), tr("Select the next or the previous point")) +
                           row(tr("Arrows (Shift: ten times more)"), tr("Nudge the selected point by a round step")) +
                           row(tr("Alt+arrows (Shift: ten times more)"),
                               tr("De Casteljau: mold the curve at t, c(t) moving by the same step")) +
                           row(tr("Alt+arrows (Shift: ten times more)"),
                               tr("Catmull-Rom, Hermite family: move the selected point's tangent by 1/10")) +
                           row(tr("Delete, Backspace"), tr("Remove the selected point"));
    const QString frog =
        row(tr("P"), tr("Pause and run")) + row(tr("S or ."), tr("One step (pausing first)")) +
        row(tr(","), tr("One step back in the recorded run (pausing first)")) + row(tr("R"), tr("Reset the scene")) +
        row(tr("M"), tr("Stopwatch: mark the step shown, or clear the mark")) +
        row(tr("[ and ]"), tr("Slower and faster (⅛× to 4×)")) +
        row(tr("Arrows (Shift: five times further)"), tr("On the canvas: move the keyboard cursor, and what it holds")) +
        row(tr("G or Enter"), tr("On the canvas: grab the body at the cursor (or the nearest one), again to let go")) +
        row(tr("Esc"), tr("On the canvas: let go, or clear the ruler")) +
        row(tr("L"), tr("On the canvas: a ruler from the cursor; move it with the arrows, L again to fix it")) +
        row(tr("Right drag, or Ctrl+drag"), tr("On the canvas: measure in px with the ruler")) +
        row(tr("Space"), tr("On the canvas: a new body at the cursor, held until released"));
    return {
        table(tr("The window"), window),
        table(tr("De Casteljau, Fitting and Catmull-Rom canvases"), curves) +
            table(
                tr("Frog tab (P, S, the comma and the period, R, M, [ and ] whenever the tab is shown, unless a field is being typed in)"),
                frog)};
}

} // namespace granota::ui
