#include "ui/common/tab_order.h"

#include <QVector>
#include <QWidget>

namespace granota::ui {

namespace {

bool takesTab(const QWidget* w) { return (w->focusPolicy() & Qt::TabFocus) != 0; }

/// The stops of `part`: itself if it takes Tab, else its controls that do (not the parts of
/// one of them, such as a spin box's line edit), in the window's present Tab order.
QVector<QWidget*> stopsOf(QWidget* part)
{
    if (takesTab(part))
        return {part};
    QVector<QWidget*> stops;
    for (QWidget* w = part->nextInFocusChain(); w != part; w = w->nextInFocusChain()) {
        if (!part->isAncestorOf(w) || !takesTab(w))
            continue;
        bool inner = false; // within a control of the part that takes Tab itself
        for (QWidget* p = w->parentWidget(); p && p != part && !inner; p = p->parentWidget())
            inner = takesTab(p);
        if (!inner)
            stops.push_back(w);
    }
    return stops;
}

} // namespace

void setTabOrderOf(std::initializer_list<QWidget*> parts)
{
    QWidget* previous = nullptr;
    for (QWidget* part : parts)
        for (QWidget* stop : stopsOf(part)) {
            if (previous)
                QWidget::setTabOrder(previous, stop);
            previous = stop;
        }
}

} // namespace granota::ui
