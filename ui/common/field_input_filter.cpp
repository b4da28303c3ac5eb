#include "ui/common/field_input_filter.h"

#include "ui/common/number_text.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMainWindow>
#include <QPointer>
#include <QRegularExpression>
#include <QScrollBar>
#include <QSpinBox>
#include <QStatusBar>
#include <QTextDocumentFragment>
#include <QToolTip>

#include <optional>

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

/// The text of a label: without its mnemonic '&' and a closing ':'.
QString labelText(const QLabel* label)
{
    QString text = label->text();
    if (Qt::mightBeRichText(text))
        text = QTextDocumentFragment::fromHtml(text).toPlainText();
    text.remove(QRegularExpression(QStringLiteral("&(?!&)")));
    text = text.trimmed();
    if (text.endsWith(QLatin1Char(':')))
        text.chop(1);
    return text.trimmed();
}

/// What the screen calls `box`: its accessible name, the label it is the buddy of, or the
/// label before it in its form or grid row; empty if nothing names it.
QString fieldName(const QAbstractSpinBox* box)
{
    if (!box->accessibleName().isEmpty())
        return box->accessibleName();
    QWidget* parent = box->parentWidget();
    if (!parent)
        return {};
    for (const QLabel* label : parent->findChildren<QLabel*>())
        if (label->buddy() == box && !label->text().isEmpty())
            return labelText(label);
    if (auto* form = qobject_cast<QFormLayout*>(parent->layout()))
        if (auto* label = qobject_cast<QLabel*>(form->labelForField(const_cast<QAbstractSpinBox*>(box))))
            return labelText(label);
    if (auto* grid = qobject_cast<QGridLayout*>(parent->layout())) {
        const int index = grid->indexOf(box);
        if (index >= 0) {
            int row = 0, column = 0, rowSpan = 0, columnSpan = 0;
            grid->getItemPosition(index, &row, &column, &rowSpan, &columnSpan);
            for (int c = column - 1; c >= 0; --c)
                if (QLayoutItem* item = grid->itemAtPosition(row, c))
                    if (auto* label = qobject_cast<QLabel*>(item->widget()); label && !label->text().isEmpty())
                        return labelText(label);
        }
    }
    return {};
}

/// The range of `box` as a person reads it ("3", "0,5"); false for a box that has no numeric range.
bool rangeOf(const QAbstractSpinBox* box, QString& low, QString& high)
{
    if (const auto* spin = qobject_cast<const QSpinBox*>(box)) {
        low = displayNumber(spin->minimum());
        high = displayNumber(spin->maximum());
        return true;
    }
    if (const auto* spin = qobject_cast<const QDoubleSpinBox*>(box)) {
        low = displayNumber(spin->minimum());
        high = displayNumber(spin->maximum());
        return true;
    }
    return false;
}

/// The number `text` says in `box` (its prefix and suffix aside, a point or the locale's
/// decimal sign), if it is one.
std::optional<double> typedNumber(const QAbstractSpinBox* box, QString text)
{
    QString prefix, suffix;
    if (const auto* spin = qobject_cast<const QSpinBox*>(box))
        prefix = spin->prefix(), suffix = spin->suffix();
    else if (const auto* spin = qobject_cast<const QDoubleSpinBox*>(box))
        prefix = spin->prefix(), suffix = spin->suffix();
    if (!prefix.isEmpty() && text.startsWith(prefix))
        text.remove(0, prefix.size());
    if (!suffix.isEmpty() && text.endsWith(suffix))
        text.chop(suffix.size());
    text = text.trimmed();
    text.replace(QLatin1Char('.'), box->locale().decimalPoint());
    bool ok = false;
    const double v = box->locale().toDouble(text, &ok);
    if (!ok)
        return std::nullopt;
    return v;
}

/// Says `text` where the user looks: the status bar of the main window `box` is in, or a
/// tool tip at the field in a dialog (which has no status bar).
void tell(QAbstractSpinBox* box, const QString& text)
{
    if (auto* window = qobject_cast<QMainWindow*>(box->window())) {
        window->statusBar()->showMessage(text, 8000);
        return;
    }
    QToolTip::showText(box->mapToGlobal(QPoint(0, box->height())), text, box);
}

/// "Sides must be between 3 and 64." for `box`, or without a name when nothing names it.
QString rangeMessage(const QAbstractSpinBox* box, const QString& low, const QString& high)
{
    const QString name = fieldName(box);
    if (name.isEmpty())
        return QCoreApplication::translate("granota::ui::FieldInputFilter", "The value must be between %1 and %2.")
            .arg(low, high);
    return QCoreApplication::translate("granota::ui::FieldInputFilter", "%1 must be between %2 and %3.").arg(name, low, high);
}

/// A key that would put text in `box` which the box refuses because its number is out of
/// range (a spin box with maximum 2000 drops the last 0 of "20000"): the user is told.
void explainRefusedKey(QAbstractSpinBox* box, const QKeyEvent* key)
{
    const QString typed = key->text();
    if (typed.isEmpty() || !typed.at(0).isPrint() ||
        (key->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier)))
        return;
    auto* edit = box->findChild<QLineEdit*>();
    if (!edit)
        return;
    QString text = edit->text();
    int pos = edit->cursorPosition();
    if (edit->hasSelectedText()) {
        pos = edit->selectionStart();
        text.remove(pos, edit->selectedText().size());
    }
    text.insert(pos, typed);
    pos += typed.size();
    QString low, high;
    if (!rangeOf(box, low, high) || box->validate(text, pos) != QValidator::Invalid)
        return;
    if (typedNumber(box, text)) // a number, and still refused: out of range
        tell(box, rangeMessage(box, low, high));
}

/// The text of `box` about to become its value (Enter, leaving the field, an undo key): if it
/// is out of range, Qt would put the last value back without a word; true if it is.
bool explainOutOfRange(QAbstractSpinBox* box)
{
    QString text = box->text();
    int pos = text.size();
    QString low, high;
    if (!rangeOf(box, low, high) || box->validate(text, pos) != QValidator::Intermediate)
        return false;
    const std::optional<double> typed = typedNumber(box, box->text());
    if (!typed)
        return false;
    QString message = rangeMessage(box, low, high);
    message += QLatin1Char(' ') +
               QCoreApplication::translate("granota::ui::FieldInputFilter", "%1 was not applied.").arg(displayNumber(*typed));
    tell(box, message);
    return true;
}

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
    case QEvent::FocusOut:
        // Leaving the field: Qt puts the last value back if the text is out of range.
        if (auto* box = qobject_cast<QAbstractSpinBox*>(watched); box && !box->isReadOnly())
            explainOutOfRange(box);
        break;
    case QEvent::ShortcutOverride:
    case QEvent::KeyPress: {
        auto* key = static_cast<QKeyEvent*>(event);
        if (!isUndoOrRedo(key)) {
            // Typed into the spin box itself (it hands the keys on to its line edit): a value out
            // of range is refused with a word rather than silently (issue 34, item 11).
            auto* box = qobject_cast<QAbstractSpinBox*>(watched);
            if (event->type() != QEvent::KeyPress || !box || box->isReadOnly())
                break;
            if (key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter) {
                // The text stays as typed, to be corrected, and nothing is applied.
                if (explainOutOfRange(box))
                    return true;
                break;
            }
            explainRefusedKey(box, key);
            break;
        }
        QAbstractSpinBox* box = spinBoxOf(watched);
        if (!box)
            break;
        // The typed text becomes the value (an undo step of its own where the tab makes
        // one), and the key is left to the window's Undo or Redo: neither the line edit nor
        // the spin box (which hands the event to its line edit) may claim it.
        if (event->type() == QEvent::ShortcutOverride) {
            explainOutOfRange(box);
            box->interpretText();
        }
        event->ignore();
        return true;
    }
    default: break;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace granota::ui
