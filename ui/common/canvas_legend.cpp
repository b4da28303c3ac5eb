#include "ui/common/canvas_legend.h"

#include <QFont>
#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>

namespace granota::ui {

QRectF drawCanvasLegend(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const CanvasLegend& legend)
{
    if (legend.entries.empty() && legend.note.isEmpty())
        return {};
    // The application font (already larger in presentation mode), a little smaller: the
    // legend must not hide the points.
    QFont font;
    font.setPointSizeF(font.pointSizeF() * 0.9);
    p.setFont(font);
    const QFontMetricsF fm(font);
    const double line = fm.height() * 1.15, swatch = 26 * style.scale, pad = 6 * style.scale;
    double width = 0;
    for (const auto& e : legend.entries)
        width = std::max(width, fm.horizontalAdvance(e.text));
    const double maxNoteWidth = std::max(120.0, view.viewport().width() * 0.6);
    QRectF noteRect;
    if (!legend.note.isEmpty())
        noteRect = fm.boundingRect(QRectF(0, 0, maxNoteWidth, 1000), Qt::TextWordWrap, legend.note);
    const double boxW = std::max(swatch + pad + width, noteRect.width()) + 2 * pad;
    const double boxH = static_cast<double>(legend.entries.size()) * line + (legend.note.isEmpty() ? 0 : noteRect.height() + pad)
                        + 2 * pad;
    const QRectF box(view.viewport().left() + 8 * style.scale, view.viewport().top() + 8 * style.scale, boxW, boxH);
    p.setPen(QPen(style.gridMajor, style.thinLine()));
    p.setBrush(QColor(255, 255, 255, 180));
    p.drawRoundedRect(box, 4, 4);
    double y = box.top() + pad;
    for (const auto& e : legend.entries) {
        const double mid = y + line / 2;
        if (e.pen != Qt::NoPen) {
            p.setPen(QPen(e.color, style.lineWidth(), e.pen));
            p.drawLine(QPointF(box.left() + pad, mid), QPointF(box.left() + pad + swatch, mid));
        }
        p.setPen(e.pen == Qt::NoPen ? legend.alertColor : style.text);
        p.drawText(QRectF(box.left() + 2 * pad + swatch, y, width + pad, line), Qt::AlignVCenter | Qt::AlignLeft, e.text);
        y += line;
    }
    if (!legend.note.isEmpty()) {
        p.setPen(legend.alertColor);
        p.drawText(QRectF(box.left() + pad, y + pad / 2, noteRect.width() + 1, noteRect.height() + 1), Qt::TextWordWrap,
                   legend.note);
    }
    return box;
}

} // namespace granota::ui
