#include "ui/common/canvas_legend.h"

#include <QFont>
#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <limits>
#include <vector>

namespace granota::ui {

namespace {

/// The labels' font (the application font, larger in presentation mode, × the style's scale,
/// as the points' names are), a little smaller: the legend must not hide the points. The
/// compact form, for a canvas without room, keeps to the application font.
QFont legendFont(const CanvasStyle& style, bool compact)
{
    QFont font = compact ? QFont() : style.labelFont();
    font.setPointSizeF(font.pointSizeF() * (compact ? CanvasLegendBox::kCompactFont : 0.9));
    return font;
}

struct LegendMetrics {
    double line = 0, swatch = 0, pad = 0, textWidth = 0;
    QRectF noteRect;
    QSizeF size;
};

LegendMetrics legendMetrics(const ViewTransform& view, const CanvasStyle& style, const CanvasLegend& legend, bool compact)
{
    LegendMetrics m;
    const QFontMetricsF fm(legendFont(style, compact));
    m.line = fm.height() * (compact ? 1.0 : 1.15);
    m.swatch = (compact ? 16 : 26) * style.scale;
    m.pad = (compact ? 3 : 6) * style.scale;
    for (const auto& e : legend.entries)
        m.textWidth = std::max(m.textWidth, fm.horizontalAdvance(e.text));
    const double maxNoteWidth = std::max(120.0, view.viewport().width() * 0.6);
    if (!legend.note.isEmpty())
        m.noteRect = fm.boundingRect(QRectF(0, 0, maxNoteWidth, 1000), Qt::TextWordWrap, legend.note);
    const double w = std::max(m.swatch + m.pad + m.textWidth, m.noteRect.width()) + 2 * m.pad;
    const double h = static_cast<double>(legend.entries.size()) * m.line +
                     (legend.note.isEmpty() ? 0 : m.noteRect.height() + m.pad) + 2 * m.pad;
    m.size = QSizeF(w, h);
    return m;
}

} // namespace

QSizeF canvasLegendSize(const ViewTransform& view, const CanvasStyle& style, const CanvasLegend& legend, bool compact)
{
    if (legend.entries.empty() && legend.note.isEmpty())
        return {};
    return legendMetrics(view, style, legend, compact).size;
}

double canvasCoverCost(const QRectF& box, const CanvasLegendObstacles& obstacles)
{
    double c = 0;
    for (const QRectF& r : obstacles.keepClear)
        c += box.intersects(r) ? CanvasLegendObstacles::kKeepClearCost : 0.0;
    for (const QPointF& q : obstacles.points)
        c += box.contains(q) ? 1.0 : 0.0;
    return c;
}

CanvasLegendBox canvasLegendRect(const ViewTransform& view, const CanvasStyle& style, const CanvasLegend& legend,
                                 const CanvasLegendObstacles& obstacles)
{
    const auto cost = [&obstacles](const QRectF& box) { return canvasCoverCost(box, obstacles); };
    const QRectF area = view.viewport().adjusted(8 * style.scale, 8 * style.scale, -8 * style.scale, -8 * style.scale);
    CanvasLegendBox best;
    double bestCost = std::numeric_limits<double>::infinity();
    // Full size first; the compact key only where the full one would cover a point or a label.
    for (const bool compact : {false, true}) {
        const QSizeF size = canvasLegendSize(view, style, legend, compact);
        if (size.isEmpty())
            return {};
        const double right = area.right() - size.width(), bottom = area.bottom() - size.height();
        // The corners (top left, top right, bottom left, bottom right), then along the edges.
        std::vector<QPointF> at = {area.topLeft(), {right, area.top()}, {area.left(), bottom}, {right, bottom}};
        for (int k = 1; k < kCanvasLegendEdgeSteps; ++k) {
            const double f = static_cast<double>(k) / kCanvasLegendEdgeSteps;
            const double x = area.left() + f * (right - area.left()), y = area.top() + f * (bottom - area.top());
            at.insert(at.end(), {{x, area.top()}, {x, bottom}, {area.left(), y}, {right, y}});
        }
        for (const QPointF& corner : at) {
            const QRectF box(corner, size);
            const double c = cost(box);
            if (c < bestCost) {
                bestCost = c;
                best = {box, compact};
            }
        }
        if (bestCost < CanvasLegendObstacles::kKeepClearCost)
            break;
    }
    return best;
}

QRectF drawCanvasLegend(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const CanvasLegend& legend)
{
    const QSizeF size = canvasLegendSize(view, style, legend, false);
    const QPointF corner = view.viewport().topLeft() + QPointF(8, 8) * style.scale;
    return drawCanvasLegend(p, view, style, legend, {QRectF(corner, size), false});
}

QRectF drawCanvasLegend(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const CanvasLegend& legend,
                        const CanvasLegendBox& where)
{
    const QRectF& box = where.box;
    if (box.isEmpty() || (legend.entries.empty() && legend.note.isEmpty()))
        return {};
    const LegendMetrics m = legendMetrics(view, style, legend, where.compact);
    p.setFont(legendFont(style, where.compact));
    p.setPen(QPen(style.gridMajor, style.thinLine()));
    p.setBrush(QColor(255, 255, 255, 215));
    p.drawRoundedRect(box, 4, 4);
    double y = box.top() + m.pad;
    for (const auto& e : legend.entries) {
        const double mid = y + m.line / 2;
        if (e.pen != Qt::NoPen) {
            p.setPen(QPen(e.color, style.lineWidth(), e.pen));
            p.drawLine(QPointF(box.left() + m.pad, mid), QPointF(box.left() + m.pad + m.swatch, mid));
        }
        p.setPen(e.pen == Qt::NoPen ? legend.alertColor : style.text);
        p.drawText(QRectF(box.left() + 2 * m.pad + m.swatch, y, m.textWidth + m.pad, m.line), Qt::AlignVCenter | Qt::AlignLeft,
                   e.text);
        y += m.line;
    }
    if (!legend.note.isEmpty()) {
        p.setPen(legend.alertColor);
        p.drawText(QRectF(box.left() + m.pad, y + m.pad / 2, m.noteRect.width() + 1, m.noteRect.height() + 1), Qt::TextWordWrap,
                   legend.note);
    }
    return box;
}

} // namespace granota::ui
