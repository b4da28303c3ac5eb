#include "ui/common/focus_frame.h"

#include <QPainter>
#include <QPalette>
#include <QPen>

namespace granota::ui {

void drawFocusFrame(QPainter& painter, const QRectF& rect, const QPalette& palette, double scale)
{
    const double width = 3.0 * scale;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(
        QPen(palette.color(QPalette::Active, QPalette::Highlight), width, Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin));
    painter.drawRect(rect.adjusted(width / 2, width / 2, -width / 2, -width / 2));
    painter.restore();
}

} // namespace granota::ui
