#include "ui/common/vertical_scroll_area.h"

#include <QScrollBar>

namespace granota::ui {

VerticalScrollArea::VerticalScrollArea(QWidget* content, QWidget* parent) : QScrollArea(parent)
{
    setWidget(content);
    setWidgetResizable(true);
    setFrameShape(QFrame::NoFrame);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    // Tab goes straight to the controls inside (docs/classroom.md, "Keyboard"); the wheel
    // and the scroll bar still scroll it.
    setFocusPolicy(Qt::NoFocus);
}

QSize VerticalScrollArea::minimumSizeHint() const
{
    // As wide as the content's rows and a scroll bar; as low as a few lines.
    const int width = widget() ? widget()->minimumSizeHint().width() : 0;
    return {width + verticalScrollBar()->sizeHint().width(), fontMetrics().height() * 2};
}

} // namespace granota::ui
