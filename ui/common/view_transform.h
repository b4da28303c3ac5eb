#pragma once
/// \file view_transform.h
/// Model coordinates (y up, the thesis's plane) ↔ widget pixels (y down), with pan and zoom.
/// The model never stores pixels: every point lives in model coordinates.

#include "core/base/vec2.h"

#include <QPointF>
#include <QRectF>

#include <algorithm>
#include <cmath>

namespace granota::ui {

class ViewTransform {
public:
    /// Pixels per model unit.
    double scale() const { return m_scale; }
    /// The model point at the centre of the viewport.
    Point center() const { return m_center; }
    QRectF viewport() const { return m_viewport; }

    void setViewport(const QRectF& viewport) { m_viewport = viewport; }
    void setCenter(Point c) { m_center = c; }
    void setScale(double s) { m_scale = std::clamp(s, kMinScale, kMaxScale); }

    QPointF toScreen(Point p) const
    {
        const QPointF c = m_viewport.center();
        return {c.x() + (p.x - m_center.x) * m_scale, c.y() - (p.y - m_center.y) * m_scale};
    }
    Point toModel(const QPointF& s) const
    {
        const QPointF c = m_viewport.center();
        return {m_center.x + (s.x() - c.x()) / m_scale, m_center.y - (s.y() - c.y()) / m_scale};
    }
    /// The model rectangle visible in the viewport (y up: top() is the smallest y).
    QRectF visibleModelRect() const
    {
        const Point a = toModel(m_viewport.bottomLeft()), b = toModel(m_viewport.topRight());
        return QRectF(QPointF(a.x, a.y), QPointF(b.x, b.y)).normalized();
    }

    /// Shows `model` (y up) whole, centred, with `marginPx` pixels to spare on each side.
    void fit(const QRectF& model, double marginPx = 40.0)
    {
        const double w = std::max(model.width(), 1e-9), h = std::max(model.height(), 1e-9);
        const double aw = std::max(m_viewport.width() - 2 * marginPx, 10.0);
        const double ah = std::max(m_viewport.height() - 2 * marginPx, 10.0);
        setScale(std::min(aw / w, ah / h));
        m_center = {model.center().x(), model.center().y()};
    }
    /// Zooms by `factor` keeping the model point under `screenAnchor` in place.
    void zoomAt(const QPointF& screenAnchor, double factor)
    {
        const Point before = toModel(screenAnchor);
        setScale(m_scale * factor);
        const Point after = toModel(screenAnchor);
        m_center = m_center + (before - after);
    }
    /// Moves the view with the mouse: the model follows a drag of `deltaPx` pixels.
    void pan(const QPointF& deltaPx) { m_center = {m_center.x - deltaPx.x() / m_scale, m_center.y + deltaPx.y() / m_scale}; }

    static constexpr double kMinScale = 1e-9; ///< px per unit: coordinates up to 1e9 still fit (docs/extreme-cases.md)
    static constexpr double kMaxScale = 1e12; ///< px per unit: coordinates down to 1e-9 still separate

private:
    QRectF m_viewport{0, 0, 640, 480};
    Point m_center{0, 0};
    double m_scale = 40.0;
};

} // namespace granota::ui
