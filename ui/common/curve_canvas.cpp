#include "ui/common/curve_canvas.h"
#include "core/exact/round_step.h"
#include "ui/common/focus_frame.h"
#include "ui/common/number_text.h"

#include <QFocusEvent>
#include <QFontMetricsF>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace granota::ui {

namespace {

/// A round grid step (1, 2 or 5 × 10^k model units) giving at least `targetPx` pixels.
double niceStep(double scale, double targetPx)
{
    const double raw = targetPx / scale;
    if (!(raw > 0) || !std::isfinite(raw))
        return raw;
    return roundStepAtLeast(raw).value();
}

QString axisLabel(double v, double step)
{
    if (std::fabs(v) < step * 1e-6)
        v = 0.0;
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step))));
    if (std::fabs(v) >= 1e6 || (v != 0.0 && std::fabs(v) < 1e-4))
        return displaySignificant(v, 4);
    return displayFixed(v, std::min(decimals, 9));
}

} // namespace

CurveCanvas::CurveCanvas(QWidget* parent) : QWidget(parent)
{
    setFocusPolicy(Qt::StrongFocus);
    setDrawsOwnFocusFrame(this);
    setMouseTracking(true);
    setAttribute(Qt::WA_OpaquePaintEvent);
    m_view.setViewport(rect());
}

void CurveCanvas::addLayer(Layer layer) { m_layers.push_back(std::move(layer)); }
void CurveCanvas::addOverlay(Layer overlay) { m_overlays.push_back(std::move(overlay)); }

void CurveCanvas::setStyleScale(double scale)
{
    m_style.scale = scale;
    update();
}

namespace {

bool drawable(const QRectF& r, double maxSpan)
{
    const double w = r.width(), h = r.height(), x = r.center().x(), y = r.center().y();
    return std::isfinite(w) && std::isfinite(h) && std::isfinite(x) && std::isfinite(y) && w <= maxSpan && h <= maxSpan &&
           std::fabs(x) <= maxSpan && std::fabs(y) <= maxSpan;
}

} // namespace

bool CurveCanvas::contentDrawable() const
{
    return drawable(m_content, kMaxDrawableSpan) && drawable(m_dataExtent, kMaxDrawableSpan);
}

void CurveCanvas::setDataExtent(const QRectF& modelBounds)
{
    m_dataExtent = modelBounds;
    update();
}

QString CurveCanvas::notice() const
{
    if (contentDrawable())
        return QString();
    return tr("These points are too large to draw: the canvas shows coordinates up to about ±%1. "
              "Their values are in the table; bring them closer to the origin to see the curve.")
        .arg(displaySignificant(kMaxDrawableSpan, 2));
}

void CurveCanvas::setContentBounds(const QRectF& modelBounds)
{
    m_content = modelBounds;
    m_dataExtent = modelBounds;
    if (!contentDrawable()) { // keep the last view: fitting it to infinities would lose it
        update();
        return;
    }
    if (!m_userMoved)
        m_view.fit(m_content, 40.0 * m_style.scale);
    update();
}

void CurveCanvas::fitToContent()
{
    m_userMoved = false;
    if (contentDrawable())
        m_view.fit(m_content, 40.0 * m_style.scale);
    update();
}

void CurveCanvas::zoom(double factor)
{
    m_userMoved = true;
    m_view.zoomAt(rect().center(), factor);
    update();
}

void CurveCanvas::setGridVisible(bool on)
{
    m_gridVisible = on;
    update();
}

void CurveCanvas::render(QPainter& painter, const QRectF& target)
{
    // Map the model rectangle visible on screen onto `target`: exports show what is seen.
    ViewTransform view = m_view;
    if (target != QRectF(rect())) {
        const QRectF visible = m_view.visibleModelRect();
        view.setViewport(target);
        view.fit(visible, 0.0);
    }
    painter.save();
    painter.setClipRect(target);
    painter.fillRect(target, m_style.background);
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setRenderHint(QPainter::TextAntialiasing, true);
    if (const QString text = notice(); !text.isEmpty()) {
        QFont font = painter.font();
        font.setPointSizeF(font.pointSizeF() * m_style.scale);
        painter.setFont(font);
        painter.setPen(palette().color(QPalette::WindowText));
        const QRectF box = target.adjusted(target.width() * 0.1, 0, -target.width() * 0.1, 0);
        painter.drawText(box, Qt::AlignCenter | Qt::TextWordWrap, text);
        painter.restore();
        return;
    }
    if (m_gridVisible)
        drawGrid(painter, view);
    for (const auto* layers : {&m_layers, &m_overlays})
        for (const auto& layer : *layers) {
            painter.save();
            layer(painter, view, m_style);
            painter.restore();
        }
    painter.restore();
}

namespace {

/// The grid lines of a view: x = (i0 + k) step for k = 0…nx, y = (j0 + k) step for k = 0…ny.
struct GridSpan {
    double step = 0, i0 = 0, j0 = 0;
    int nx = -1, ny = -1; ///< −1: no grid
    double x(int k) const { return (i0 + k) * step; }
    double y(int k) const { return (j0 + k) * step; }
};

GridSpan gridSpan(const ViewTransform& view, const CanvasStyle& style)
{
    GridSpan g;
    const QRectF model = view.visibleModelRect();
    g.step = niceStep(view.scale(), 60.0 * style.scale);
    if (!std::isfinite(g.step) || g.step <= 0)
        return g;
    // The lines are counted from the first multiple of the step, never stepped with x += step:
    // far from the origin at a deep zoom the step is below the coordinates' resolution, and
    // x += step would leave x where it is for ever. At most a few hundred lines, whatever the
    // zoom; none when the multiples of the step cannot be told apart at these coordinates.
    g.i0 = std::floor(model.left() / g.step);
    g.j0 = std::floor(model.top() / g.step);
    const double columns = std::floor(model.right() / g.step) - g.i0, rows = std::floor(model.bottom() / g.step) - g.j0;
    constexpr double kMaxLines = 400, kExactIntegers = 9007199254740992.0; // 2^53
    if (!(columns <= kMaxLines && rows <= kMaxLines) || !(std::fabs(g.i0) + columns < kExactIntegers) ||
        !(std::fabs(g.j0) + rows < kExactIntegers))
        return g;
    g.nx = static_cast<int>(columns);
    g.ny = static_cast<int>(rows);
    return g;
}

/// The font of the grid's labels.
QFont gridLabelFont(const CanvasStyle& style)
{
    QFont font = style.labelFont();
    font.setPointSizeF(font.pointSizeF() * 0.8);
    return font;
}

} // namespace

std::vector<CurveCanvas::GridLabel> CurveCanvas::gridLabels(const ViewTransform& view, const QFontMetricsF& metrics) const
{
    std::vector<GridLabel> labels;
    const GridSpan g = gridSpan(view, m_style);
    const QRectF area = view.viewport();
    const QPointF origin = view.toScreen({0, 0});
    const double ax = std::clamp(origin.x(), area.left(), area.right());
    const double ay = std::clamp(origin.y(), area.top(), area.bottom());
    // Only a label wholly inside the viewport: the label of a line just off the left edge
    // starts off it too, and cut there "−0,5" read "0,5".
    const auto add = [&](const QString& text, const QPointF& baseline) {
        const QRectF box(baseline.x(), baseline.y() - metrics.ascent(), metrics.horizontalAdvance(text), metrics.height());
        if (area.contains(box))
            labels.push_back({text, baseline, box});
    };
    const double labelY = std::min(ay + 4 * m_style.scale, area.bottom() - metrics.height());
    for (int k = 0; k <= g.nx; ++k) {
        const double x = g.x(k);
        if (std::fabs(x) < g.step * 1e-6)
            continue;
        add(axisLabel(x, g.step), QPointF(view.toScreen({x, 0}).x() + 3 * m_style.scale, labelY + metrics.ascent()));
    }
    const double labelX = std::min(ax + 4 * m_style.scale, area.right() - metrics.horizontalAdvance(QStringLiteral("-00000")));
    for (int k = 0; k <= g.ny; ++k) {
        const double y = g.y(k);
        if (std::fabs(y) < g.step * 1e-6)
            continue;
        add(axisLabel(y, g.step), QPointF(labelX, view.toScreen({0, y}).y() - 3 * m_style.scale));
    }
    return labels;
}

std::vector<CurveCanvas::GridLabel> CurveCanvas::gridLabels() const
{
    return gridLabels(m_view, QFontMetricsF(gridLabelFont(m_style), this));
}

void CurveCanvas::drawGrid(QPainter& painter, const ViewTransform& view) const
{
    const QRectF area = view.viewport();
    const GridSpan g = gridSpan(view, m_style);
    if (g.nx < 0)
        return;
    painter.setPen(QPen(m_style.gridMinor, m_style.thinLine()));
    for (int k = 0; k <= g.nx; ++k) {
        const double sx = view.toScreen({g.x(k), 0}).x();
        painter.drawLine(QPointF(sx, area.top()), QPointF(sx, area.bottom()));
    }
    for (int k = 0; k <= g.ny; ++k) {
        const double sy = view.toScreen({0, g.y(k)}).y();
        painter.drawLine(QPointF(area.left(), sy), QPointF(area.right(), sy));
    }
    // Axes through the origin when visible, labels along them (or along the edges).
    const QPointF origin = view.toScreen({0, 0});
    const double ax = std::clamp(origin.x(), area.left(), area.right());
    const double ay = std::clamp(origin.y(), area.top(), area.bottom());
    painter.setPen(QPen(m_style.axis, m_style.thinLine() * 1.5));
    painter.drawLine(QPointF(area.left(), ay), QPointF(area.right(), ay));
    painter.drawLine(QPointF(ax, area.top()), QPointF(ax, area.bottom()));
    painter.setFont(gridLabelFont(m_style));
    painter.setPen(m_style.axis);
    for (const GridLabel& label : gridLabels(view, QFontMetricsF(painter.font(), painter.device())))
        painter.drawText(label.baseline, label.text);
}

void CurveCanvas::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    render(painter, rect());
    if (hasFocus())
        drawFocusFrame(painter, rect(), palette(), m_style.scale); // on screen only, never exported
}

void CurveCanvas::resizeEvent(QResizeEvent* event)
{
    m_view.setViewport(rect());
    if (!m_userMoved && contentDrawable())
        m_view.fit(m_content, 40.0 * m_style.scale);
    QWidget::resizeEvent(event);
}

// Point editors filter the events first; what reaches the canvas is panning.
void CurveCanvas::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton || event->button() == Qt::MiddleButton) {
        m_panning = true;
        m_lastMouse = event->position();
        setCursor(Qt::ClosedHandCursor);
    }
}

void CurveCanvas::mouseMoveEvent(QMouseEvent* event)
{
    const Point p = m_view.toModel(event->position());
    emit cursorMoved(p.x, p.y);
    if (m_panning) {
        m_userMoved = true;
        m_view.pan(event->position() - m_lastMouse);
        m_lastMouse = event->position();
        update();
    }
}

void CurveCanvas::mouseReleaseEvent(QMouseEvent*)
{
    if (m_panning) {
        m_panning = false;
        unsetCursor();
    }
}

void CurveCanvas::focusInEvent(QFocusEvent* event)
{
    update(); // the focus frame
    QWidget::focusInEvent(event);
}

void CurveCanvas::focusOutEvent(QFocusEvent* event)
{
    update();
    QWidget::focusOutEvent(event);
}

void CurveCanvas::wheelEvent(QWheelEvent* event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0)
        return;
    m_userMoved = true;
    m_view.zoomAt(event->position(), std::pow(1.15, steps));
    update();
}

} // namespace granota::ui
