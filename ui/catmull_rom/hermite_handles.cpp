#include "ui/catmull_rom/hermite_handles.h"

#include "ui/common/canvas_style.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/point_editor.h"
#include "ui/common/view_transform.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>

#include <cmath>

namespace granota::ui {

HermiteHandles::HermiteHandles(CurveCanvas* canvas, PointEditor* editor, QObject* parent)
    : QObject(parent), m_canvas(canvas), m_editor(editor)
{
    m_canvas->installEventFilter(this); // after the point editor's: this one sees events first
}

void HermiteHandles::setState(bool active, const std::vector<Point>& points, const std::vector<Point>& tangents)
{
    m_active = active && points.size() == tangents.size();
    m_points = points;
    m_tangents = tangents;
    if (!m_active)
        m_dragging = -1;
}

Point HermiteHandles::handlePosition(int i) const
{
    const auto k = static_cast<std::size_t>(i);
    return m_points[k] + m_tangents[k];
}

int HermiteHandles::pick(QPointF screen) const
{
    // The nearest handle within the pick radius (the same as the points').
    const double radius = m_canvas->style().pickRadius();
    int best = -1;
    double bestDistance = radius;
    for (int i = 0; i < static_cast<int>(m_points.size()); ++i) {
        const double d = QLineF(m_canvas->view().toScreen(handlePosition(i)), screen).length();
        if (d <= bestDistance) {
            best = i;
            bestDistance = d;
        }
    }
    return best;
}

void HermiteHandles::draw(QPainter& p, const ViewTransform& view, const CanvasStyle& style) const
{
    if (!m_active)
        return;
    const double r = style.handleRadius() * 0.75;
    p.setPen(QPen(QColor(0x55, 0x2a, 0x00), style.thinLine()));
    p.setBrush(QColor(0xff, 0xd0, 0x80));
    for (int i = 0; i < static_cast<int>(m_points.size()); ++i) {
        const QPointF c = view.toScreen(handlePosition(i));
        p.drawRect(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r));
    }
    p.setBrush(Qt::NoBrush);
}

bool HermiteHandles::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != m_canvas || !m_active)
        return QObject::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::MouseButtonPress: {
        auto* e = static_cast<QMouseEvent*>(event);
        if (e->button() != Qt::LeftButton)
            return false;
        const int hit = pick(e->position());
        if (hit < 0)
            return false; // a point or the paper: the point editor and the canvas take it
        m_dragging = hit;
        m_dragStartTangent = m_tangents[static_cast<std::size_t>(hit)];
        m_dragStartModel = m_canvas->view().toModel(e->position());
        return true;
    }
    case QEvent::MouseMove: {
        if (m_dragging < 0)
            return false;
        auto* e = static_cast<QMouseEvent*>(event);
        // The tangent moves by exactly the pointer's move in model units (no snapping).
        const Point now = m_canvas->view().toModel(e->position());
        const Point t = m_dragStartTangent + (now - m_dragStartModel);
        if (isFinite(t)) {
            m_tangents[static_cast<std::size_t>(m_dragging)] = t;
            emit tangentDragged(m_dragging, t);
        }
        return true;
    }
    case QEvent::MouseButtonRelease: {
        auto* e = static_cast<QMouseEvent*>(event);
        if (e->button() != Qt::LeftButton || m_dragging < 0)
            return false;
        const int index = m_dragging;
        m_dragging = -1;
        emit dragFinished(index, m_dragStartTangent); // one undo step for the whole drag
        return true;
    }
    case QEvent::KeyPress: {
        auto* e = static_cast<QKeyEvent*>(event);
        const int i = m_editor->selected();
        if (!(e->modifiers() & Qt::AltModifier) || i < 0 || i >= static_cast<int>(m_tangents.size()))
            return false;
        const double step = kKeyStep * ((e->modifiers() & Qt::ShiftModifier) ? 10.0 : 1.0);
        Point d{0, 0};
        switch (e->key()) {
        case Qt::Key_Left: d.x = -step; break;
        case Qt::Key_Right: d.x = step; break;
        case Qt::Key_Up: d.y = step; break;
        case Qt::Key_Down: d.y = -step; break;
        default: return false;
        }
        emit tangentNudged(i, m_tangents[static_cast<std::size_t>(i)] + d);
        return true;
    }
    default: return QObject::eventFilter(watched, event);
    }
}

} // namespace granota::ui
