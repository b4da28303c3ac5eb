#pragma once
/// \file tab_page.h
/// What every tab gives the main window: its part of the document, its undo stack, its
/// view for the exports, its data as CSV and TikZ, the worked examples it can load, and
/// its texts again after a language switch. The main window speaks to every tab through
/// this interface only; what the tabs say alike (key, title, undo stack, export view) is
/// held here once, what each says in its own way is virtual.

#include "ui/files/tikz_writer.h"

#include <QEvent>
#include <QJsonObject>
#include <QUndoStack>
#include <QWidget>

#include <utility>

namespace granota {
struct WorkedExample;
}

namespace granota::ui {

class Drawable;

class TabPage : public QWidget {
    Q_OBJECT
public:
    /// `key`: see key(); `title`: the tab's title untranslated, marked QT_TR_NOOP in the tab's
    /// own class, whose translation context title() uses.
    TabPage(QString key, const char* title, QWidget* parent = nullptr)
        : QWidget(parent), m_undo(new QUndoStack(this)), m_key(std::move(key)), m_title(title)
    {
    }
    /// A tab that shows another tab's data shares its history (`sharedUndo`, owned by that
    /// tab): the Bernstein tab and the De Casteljau tab, one curve and one t.
    TabPage(QString key, const char* title, QUndoStack* sharedUndo, QWidget* parent)
        : QWidget(parent), m_undo(sharedUndo), m_key(std::move(key)), m_title(title)
    {
    }

    /// The key (docs/classroom.md) (`--tab`): decasteljau, bernstein, fit, catmull-rom, frog, bspline.
    QString key() const { return m_key; }
    /// The tab's title, translated (in the context of the tab's class, e.g. granota::ui::FitTab).
    QString title() const { return metaObject()->tr(m_title, nullptr); }
    /// Sets every visible text again (menus, labels, tooltips) in the current language.
    virtual void retranslate() = 0;

    /// The tab's points and settings, for the .granota document.
    virtual QJsonObject saveState() const = 0;
    /// Restores what saveState() wrote. On bad data returns false with a translated message
    /// in `error`, and leaves the tab as it was.
    virtual bool loadState(const QJsonObject& state, QString* error) = 0;
    /// Loads a worked example of the thesis whose `tab` is this tab's key (undoable). A tab
    /// without worked examples (the frog: chapter 2 has none) keeps this one: false.
    virtual bool loadExample(const granota::WorkedExample& example)
    {
        (void)example;
        return false;
    }

    /// What the user can do here, in a line, in the current language: the main window's status
    /// bar shows the hint of the tab shown (passing messages cover it for a few seconds).
    virtual QString hint() const = 0;
    /// The same while the tab's canvas (its export view) has the keyboard focus: its keys, not
    /// the mouse's. Empty: hint() then too.
    virtual QString keyboardHint() const { return QString(); }

    /// The undo stack of the tab's edits (the main window's Edit menu follows the current tab).
    /// Every change the document keeps is one step on it (docs/tabs.md, "Undo").
    QUndoStack* undoStack() const { return m_undo; }
    /// The view that File ▸ Export draws (the main canvas or plot of the tab, setExportView()).
    Drawable* exportView() const { return m_exportView; }
    /// The tab's data as CSV (points, samples, table).
    virtual QString csv() const = 0;
    /// The tab's picture as TikZ for LaTeX slides, at the size and with the axes and grid
    /// `options` ask for (File ▸ Export ▸ TikZ).
    QString tikz(const TikzOptions& options = TikzOptions()) const
    {
        TikzWriter writer(options);
        drawTikz(writer);
        return writer.str();
    }

    /// Presentation mode: larger lines, handles and labels (docs/classroom.md).
    virtual void setPresentation(bool on) { (void)on; }
    /// The panel beside the canvas (settings, tables, exact results): in presentation mode the
    /// main window folds it away like a drawer, so that the canvas has the width, and View ▸
    /// Side panel (F9) opens it again (docs/classroom.md, "Presentation mode").
    QWidget* sidePanel() const { return m_sidePanel; }

    /// View ▸ Zoom in/out (factor > 1 zooms in) and View ▸ Fit.
    virtual void zoom(double factor) { (void)factor; }
    virtual void fitView() {}

signals:
    /// Something the document saves changed (points, settings): the title shows “*”.
    void documentChanged();
    /// A message for the status bar (hints, refusals, readouts).
    void statusMessage(const QString& text);
    /// Open the work-precision section below the tab at report `name` (docs/work-precision.md).
    void reportRequested(const QString& name);

protected:
    /// What tikz() draws: the tab's curves, polygons and labelled points in model coordinates.
    virtual void drawTikz(TikzWriter& writer) const = 0;

    /// The tab's view for File ▸ Export (it stays the tab's; set in the constructor).
    void setExportView(Drawable* view) { m_exportView = view; }
    /// The tab's side panel (sidePanel(); set in the constructor).
    void setSidePanel(QWidget* panel) { m_sidePanel = panel; }

    void changeEvent(QEvent* event) override
    {
        if (event->type() == QEvent::LanguageChange)
            retranslate();
        QWidget::changeEvent(event);
    }

    QUndoStack* const m_undo; ///< the tab's edits (its parent is the tab, or the tab it shares it with)

private:
    const QString m_key;
    const char* const m_title;
    Drawable* m_exportView = nullptr;
    QWidget* m_sidePanel = nullptr;
};

} // namespace granota::ui
