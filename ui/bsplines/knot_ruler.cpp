#include "ui/bsplines/knot_ruler.h"

#include "ui/common/canvas_style.h"
#include "ui/common/focus_frame.h"
#include "ui/common/number_text.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {
constexpr double kMarginPx = 24;              ///< room left and right of the outermost knots (their badges)
constexpr double kPickPx = 9;                 ///< how near the mouse must be to a tick to take it
constexpr double kTickPx = 9;                 ///< the tick's half height
constexpr int kKeySteps = 100;                ///< Shift+arrow moves a knot by 1/kKeySteps of the knots' extent
const QColor kSpanColour(0xff, 0xe0, 0x8a);   ///< the span that holds u (as the polygon's highlighted points)
const QColor kDomainColour(0x2b, 0x2b, 0x2b); ///< the domain [u_p, u_{n+1}]
} // namespace

KnotRuler::KnotRuler(QWidget* parent) : QWidget(parent)
{
    setFocusPolicy(Qt::StrongFocus);
    setDrawsOwnFocusFrame(this);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setMouseTracking(false);
}

QSize KnotRuler::sizeHint() const { return {400, minimumSizeHint().height()}; }

QSize KnotRuler::minimumSizeHint() const
{
    // A badge above the line, the ticks, a line of knot values under it.
    return {120, static_cast<int>(2 * kTickPx * m_scale + 2.6 * fontMetrics().height() + 8)};
}

void KnotRuler::setStyleScale(double scale)
{
    m_scale = scale;
    updateGeometry();
    update();
}

void KnotRuler::setKnots(const std::vector<double>& knots, int degree, const QStringList& texts)
{
    if (knots == m_knots && texts == m_texts && degree == m_degree)
        return; // a point dragged: nothing of the ruler's changed, no repaint (1000 knots cost a frame)
    m_knots = knots;
    m_texts = texts;
    m_degree = degree;
    if (m_selected >= static_cast<int>(m_knots.size()))
        m_selected = static_cast<int>(m_knots.size()) - 1;
    if (m_dragging < 0)
        updateRange();
    update();
}

void KnotRuler::setParameter(double u, int span)
{
    if (u == m_u && span == m_span)
        return;
    m_u = u;
    m_span = span;
    update();
}

void KnotRuler::setSelected(int index)
{
    index = std::clamp(index, -1, static_cast<int>(m_knots.size()) - 1);
    if (index == m_selected)
        return;
    m_selected = index;
    update();
    emit selectionChanged(index);
}

void KnotRuler::updateRange()
{
    if (m_knots.empty()) {
        m_lo = 0;
        m_hi = 1;
        return;
    }
    m_lo = m_knots.front();
    m_hi = m_knots.back();
    if (!(m_hi > m_lo))
        m_hi = m_lo + 1;
}

double KnotRuler::toX(double v) const
{
    const double w = std::max(1.0, width() - 2 * kMarginPx * m_scale);
    return kMarginPx * m_scale + (v - m_lo) / (m_hi - m_lo) * w;
}

double KnotRuler::toValue(double x) const
{
    const double w = std::max(1.0, width() - 2 * kMarginPx * m_scale);
    return m_lo + (x - kMarginPx * m_scale) / w * (m_hi - m_lo);
}

double KnotRuler::lowerBound(int index) const
{
    if (index <= 0)
        return index == 0 && !m_knots.empty() ? m_lo - (m_hi - m_lo) : 0;
    return m_knots[static_cast<std::size_t>(index - 1)];
}

double KnotRuler::upperBound(int index) const
{
    const int last = static_cast<int>(m_knots.size()) - 1;
    if (index >= last)
        return index == last && last >= 0 ? m_hi + (m_hi - m_lo) : 0;
    return m_knots[static_cast<std::size_t>(index + 1)];
}

double KnotRuler::lineY() const { return height() - 1.4 * fontMetrics().height() - kTickPx * m_scale; }

double KnotRuler::keyStep() const { return (m_hi - m_lo) / kKeySteps; }

std::pair<int, int> KnotRuler::pickStack(double x) const
{
    int best = -1;
    double bestDistance = kPickPx * m_scale;
    for (int i = 0; i < static_cast<int>(m_knots.size()); ++i) {
        const double d = std::abs(toX(m_knots[static_cast<std::size_t>(i)]) - x);
        if (d <= bestDistance) {
            bestDistance = d;
            best = i;
        }
    }
    if (best < 0)
        return {-1, -1};
    const double v = m_knots[static_cast<std::size_t>(best)];
    int first = best, last = best + 1;
    while (first > 0 && m_knots[static_cast<std::size_t>(first - 1)] == v)
        --first;
    while (last < static_cast<int>(m_knots.size()) && m_knots[static_cast<std::size_t>(last)] == v)
        ++last;
    return {first, last};
}

void KnotRuler::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(rect(), CanvasStyle().background);
    if (m_knots.empty())
        return;
    const double y = lineY();
    const double tick = kTickPx * m_scale;
    const int n = static_cast<int>(m_knots.size()) - m_degree - 2; // n + 1 points
    const auto at = [this](int i) { return m_knots[static_cast<std::size_t>(i)]; };

    // The span of u, then the whole line, then the domain bold.
    if (m_span >= 0 && m_span + 1 < static_cast<int>(m_knots.size())) {
        const double a = toX(at(m_span)), b = toX(at(m_span + 1));
        p.fillRect(QRectF(a, y - tick, std::max(2.0, b - a), 2 * tick), kSpanColour);
    }
    p.setPen(QPen(CanvasStyle().axis, m_scale));
    p.drawLine(QPointF(toX(m_knots.front()), y), QPointF(toX(m_knots.back()), y));
    if (n >= 0 && m_degree <= n + 1) {
        p.setPen(QPen(kDomainColour, 3 * m_scale, Qt::SolidLine, Qt::FlatCap));
        p.drawLine(QPointF(toX(at(m_degree)), y), QPointF(toX(at(n + 1)), y));
    }

    // u.
    p.setPen(QPen(CanvasStyle().curve, 2 * m_scale));
    p.drawLine(QPointF(toX(m_u), y - 1.6 * tick), QPointF(toX(m_u), y + tick));

    // Each distinct knot: a tick, its value under it where there is room, its multiplicity over it.
    QFont small = font();
    const QFontMetricsF fm(small);
    double labelsEnd = -1e9;
    for (int i = 0; i < static_cast<int>(m_knots.size());) {
        int j = i + 1;
        while (j < static_cast<int>(m_knots.size()) && at(j) == at(i))
            ++j;
        const double x = toX(at(i));
        const bool selected = m_selected >= i && m_selected < j;
        p.setPen(QPen(selected ? CanvasStyle().handleSelected : CanvasStyle().handle, (selected ? 3 : 2) * m_scale));
        p.drawLine(QPointF(x, y - tick), QPointF(x, y + tick));
        if (x > labelsEnd + 4) { // else no label fits: skip measuring it (1000 knots)
            const QString value = i < m_texts.size() ? m_texts[i] : displayNumber(at(i));
            const double w = fm.horizontalAdvance(value);
            if (x - w / 2 > labelsEnd + 4) {
                p.setPen(CanvasStyle().text);
                p.drawText(QPointF(x - w / 2, y + tick + fm.ascent() + 2), value);
                labelsEnd = x + w / 2;
            }
        }
        if (j - i > 1) {
            const double r = 0.5 * fm.height() + m_scale;
            const QPointF c(x, y - tick - r - 1);
            p.setPen(QPen(Qt::white, m_scale));
            p.setBrush(selected ? CanvasStyle().handleSelected : CanvasStyle().handle);
            p.drawEllipse(c, r, r);
            p.setPen(Qt::white);
            p.drawText(QRectF(c.x() - r, c.y() - r, 2 * r, 2 * r), Qt::AlignCenter, QString::number(j - i));
            p.setBrush(Qt::NoBrush);
        }
        i = j;
    }
    if (hasFocus())
        drawFocusFrame(p, rect(), palette(), m_scale);
}

void KnotRuler::mousePressEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton)
        return QWidget::mousePressEvent(event);
    m_pressedStack = pickStack(event->position().x());
    m_pressX = event->position().x();
    m_moved = false;
    m_dragging = -1;
    if (m_pressedStack.first >= 0)
        setSelected(m_pressedStack.second - 1);
}

void KnotRuler::mouseMoveEvent(QMouseEvent* event)
{
    if (m_pressedStack.first < 0 || !(event->buttons() & Qt::LeftButton))
        return;
    const double x = event->position().x();
    if (m_dragging < 0) {
        if (x == m_pressX)
            return;
        // From a stack, the knot on the side of the move leaves it: the others stay.
        m_dragging = x > m_pressX ? m_pressedStack.second - 1 : m_pressedStack.first;
        setSelected(m_dragging);
    }
    const double v = std::clamp(toValue(x), lowerBound(m_dragging), upperBound(m_dragging));
    m_moved = true;
    emit knotMoved(m_dragging, v);
}

void KnotRuler::mouseReleaseEvent(QMouseEvent* event)
{
    const bool moved = m_moved;
    m_pressedStack = {-1, -1};
    m_dragging = -1;
    m_moved = false;
    if (moved) {
        emit dragFinished();
        updateRange();
        update();
    }
    QWidget::mouseReleaseEvent(event);
}

void KnotRuler::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton)
        emit insertRequested(toValue(event->position().x()));
}

void KnotRuler::keyPressEvent(QKeyEvent* event)
{
    const int count = static_cast<int>(m_knots.size());
    const bool shift = event->modifiers() & Qt::ShiftModifier;
    switch (event->key()) {
    case Qt::Key_Left:
    case Qt::Key_Right: {
        const int dir = event->key() == Qt::Key_Right ? 1 : -1;
        if (!shift) {
            setSelected(m_selected < 0 ? (dir > 0 ? 0 : count - 1) : std::clamp(m_selected + dir, 0, count - 1));
        } else if (m_selected >= 0) {
            const double v = std::clamp(m_knots[static_cast<std::size_t>(m_selected)] + dir * keyStep(), lowerBound(m_selected),
                                        upperBound(m_selected));
            emit knotMoved(m_selected, v);
            emit dragFinished();
        }
        return;
    }
    case Qt::Key_Insert: emit insertAtParameterRequested(); return;
    case Qt::Key_Delete:
    case Qt::Key_Backspace:
        if (m_selected >= 0)
            emit removeRequested(m_selected);
        return;
    default: QWidget::keyPressEvent(event);
    }
}

void KnotRuler::focusInEvent(QFocusEvent* event)
{
    QWidget::focusInEvent(event);
    update();
}

void KnotRuler::focusOutEvent(QFocusEvent* event)
{
    QWidget::focusOutEvent(event);
    update();
}

} // namespace granota::ui
