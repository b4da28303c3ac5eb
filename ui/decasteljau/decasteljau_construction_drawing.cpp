#include "ui/decasteljau/decasteljau_construction_drawing.h"

#include <QPainter>

namespace granota::ui {

QPainterPath polylinePath(const std::vector<Point>& points, const ViewTransform& view)
{
    QPainterPath path;
    bool first = true;
    for (const Point& q : points) {
        if (!isFinite(q))
            continue;
        const QPointF s = view.toScreen(q);
        if (first)
            path.moveTo(s);
        else
            path.lineTo(s);
        first = false;
    }
    return path;
}

void drawDeCasteljauConstruction(QPainter& p, const ViewTransform& view, const CanvasStyle& style,
                                 const DeCasteljauTable<double>& table, double dotScale)
{
    const int n = table.degree();
    for (int r = 1; r < n; ++r) {
        const auto& level = table.levels[static_cast<std::size_t>(r)];
        const QColor c = CanvasStyle::series(r);
        // Beyond degree 10 the levels crowd each other: hairlines keep them apart, and a
        // one-pixel line is drawn by Qt's fast stroker — a 1.4 px one costs the outline
        // of every segment, three quarters of a frame at degree 30.
        p.setPen(QPen(c, style.thinLine() * (n > 10 ? 1.0 : 1.4)));
        p.setBrush(Qt::NoBrush);
        p.drawPath(polylinePath(level, view));
        if (dotScale <= 0)
            continue; // lines only (a small view of a high degree)
        // All the level's points as one path: one fill and one stroke instead of one per
        // point keeps a drag at degree 30 (465 points) within a frame.
        const double rad = style.handleRadius() * dotScale;
        QPainterPath dots;
        for (const Point& q : level)
            if (isFinite(q))
                dots.addEllipse(view.toScreen(q), rad, rad);
        p.setPen(QPen(Qt::white, style.thinLine()));
        p.setBrush(c);
        p.drawPath(dots);
    }
}

} // namespace granota::ui
