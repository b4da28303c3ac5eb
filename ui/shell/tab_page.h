#pragma once
/// \file tab_page.h
/// What every tab gives the main window: its part of the document, its undo stack, its
/// view for the exports, its data as CSV and TikZ, the worked examples it can load, and
/// its texts again after a language switch.

#include <QEvent>
#include <QJsonObject>
#include <QWidget>

class QUndoStack;

namespace granota {
struct WorkedExample;
}

namespace granota::ui {

class Drawable;

class TabPage : public QWidget {
    Q_OBJECT
public:
    using QWidget::QWidget;

    /// The key (docs/classroom.md) (`--tab`): decasteljau, bernstein, fit, catmull-rom, frog.
    virtual QString key() const = 0;
    /// The tab's title, translated.
    virtual QString title() const = 0;
    /// Sets every visible text again (menus, labels, tooltips) in the current language.
    virtual void retranslate() = 0;

    /// The tab's points and settings, for the .granota document.
    virtual QJsonObject saveState() const = 0;
    /// Restores what saveState() wrote. On bad data returns false with a translated message
    /// in `error`, and leaves the tab as it was.
    virtual bool loadState(const QJsonObject& state, QString* error) = 0;
    /// Loads a worked example of the thesis whose `tab` is this tab's key (undoable).
    virtual bool loadExample(const granota::WorkedExample& example) = 0;

    /// The undo stack of the tab's edits (the main window's Edit menu follows the current tab).
    virtual QUndoStack* undoStack() const = 0;
    /// The view that File ▸ Export draws (the main canvas or plot of the tab).
    virtual Drawable* exportView() = 0;
    /// The tab's data as CSV (points, samples, table) and as a TikZ picture for LaTeX slides.
    virtual QString csv() const = 0;
    virtual QString tikz() const = 0;

    /// Presentation mode: larger lines, handles and labels (docs/classroom.md).
    virtual void setPresentation(bool on) { (void)on; }
    /// View ▸ Zoom in/out (factor > 1 zooms in) and View ▸ Fit.
    virtual void zoom(double factor) { (void)factor; }
    virtual void fitView() {}

signals:
    /// Something the document saves changed (points, settings): the title shows “*”.
    void documentChanged();
    /// A message for the status bar (hints, refusals, readouts).
    void statusMessage(const QString& text);

protected:
    void changeEvent(QEvent* event) override
    {
        if (event->type() == QEvent::LanguageChange)
            retranslate();
        QWidget::changeEvent(event);
    }
};

} // namespace granota::ui
