#include "ui/common/field_input_filter.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QPointer>
#include <QScrollBar>

namespace granota::ui {

namespace {

/// A control whose value the wheel would change: a spin box, a combo box or a slider
/// (a scroll bar is what the wheel is for, and stays as it is).
bool isValueControl(const QObject* object)
{
    if (qobject_cast<const QScrollBar*>(object))
        return false;
    return qobject_cast<const QAbstractSpinBox*>(object) || qobject_cast<const QComboBox*>(object) ||
           qobject_cast<const QAbstractSlider*>(object);
}

/// The spin box `object` is, or whose line edit it is; null otherwise.
QAbstractSpinBox* spinBoxOf(QObject* object)
{
    if (auto* box = qobject_cast<QAbstractSpinBox*>(object))
        return box;
    if (auto* edit = qobject_cast<QLineEdit*>(object))
        return qobject_cast<QAbstractSpinBox*>(edit->focusProxy()); // a spin box's line edit hands it the focus
    return nullptr;
}

bool isUndoOrRedo(const QKeyEvent* key) { return key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo); }

} // namespace

void FieldInputFilter::install()
{
    static QPointer<FieldInputFilter> installed;
    if (installed || !qApp)
        return;
    installed = new FieldInputFilter(qApp);
    qApp->installEventFilter(installed);
}

bool FieldInputFilter::eventFilter(QObject* watched, QEvent* event)
{
    switch (event->type()) {
    case QEvent::Polish: {
        // Qt gives spin boxes and combo boxes Qt::WheelFocus: a wheel turned over one would
        // give it the focus first, and then change it. A click or Tab still gives it.
        auto* widget = qobject_cast<QWidget*>(watched);
        if (widget && widget->focusPolicy() == Qt::WheelFocus &&
            (isValueControl(widget) || (widget->parent() && isValueControl(widget->parent()))))
            widget->setFocusPolicy(Qt::StrongFocus);
        break;
    }
    case QEvent::Wheel:
        if (isValueControl(watched) && !static_cast<QWidget*>(watched)->hasFocus()) {
            // Not for this control: QApplication hands an ignored wheel event on to the
            // parents, up to the scroll area's viewport, which scrolls.
            event->ignore();
            return true;
        }
        break;
    case QEvent::ShortcutOverride:
    case QEvent::KeyPress: {
        auto* key = static_cast<QKeyEvent*>(event);
        if (!isUndoOrRedo(key))
            break;
        QAbstractSpinBox* box = spinBoxOf(watched);
        if (!box)
            break;
        // The typed text becomes the value (an undo step of its own where the tab makes
        // one), and the key is left to the window's Undo or Redo: neither the line edit nor
        // the spin box (which hands the event to its line edit) may claim it.
        if (event->type() == QEvent::ShortcutOverride)
            box->interpretText();
        event->ignore();
        return true;
    }
    default: break;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace granota::ui
