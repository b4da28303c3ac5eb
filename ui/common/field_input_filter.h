#pragma once
/// \file field_input_filter.h
/// What the mouse wheel and the undo keys do over the side panels' fields (docs/classroom.md,
/// "Wheel and undo in the fields"), for every tab and dialog of the application at once:
///
/// - **The wheel scrolls the panel.** A spin box, combo box or slider answers the wheel only
///   while it has the keyboard focus (clicked or tabbed into); under a passing pointer the
///   wheel goes on to what holds it — the panel's scroll area scrolls — so a student who
///   scrolls a long panel never changes a parameter on the way (issue 34). These controls
///   take the focus from a click or Tab, not from the wheel (Qt::StrongFocus).
/// - **Ctrl+Z and Ctrl+Shift+Z / Ctrl+Y in a spin box are the document's.** The field's text is
///   committed first (QAbstractSpinBox::interpretText), then the key goes to the window's
///   Edit ▸ Undo or Redo instead of the field's own text undo (QLineEdit would take it as a
///   ShortcutOverride).
/// - **A typed value out of range is refused with a word.** Qt's spin box drops a digit that
///   takes the number past its maximum, and on Enter or when the field is left puts the last
///   value back, both in silence (sides `2` became 10 again; `20000` in a box of maximum 2000
///   was 2000). The status bar (a tooltip in a dialog) says "… must be between 3 and 64."; Enter
///   leaves the typed text in the field to be corrected, applying nothing (issue 34, item 11).
///
/// Installed once on the QApplication (MainWindow's constructor does it).
#include <QObject>

namespace granota::ui {

class FieldInputFilter : public QObject {
public:
    /// Installs the filter on the application, once however often it is called.
    static void install();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    using QObject::QObject;
};

} // namespace granota::ui
