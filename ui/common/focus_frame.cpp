#include "ui/common/focus_frame.h"

#include <QApplication>
#include <QEvent>
#include <QPainter>
#include <QPalette>
#include <QPen>

#include <cmath>
#include <utility>

namespace granota::ui {

namespace {
const char* const kOwnFrame = "granotaDrawsOwnFocusFrame";
} // namespace

void drawFocusFrame(QPainter& painter, const QRectF& rect, const QPalette& palette, double scale)
{
    (void)palette;
    const double width = kFocusRingWidth * scale;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(kFocusRingColour, width, Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin));
    painter.drawRect(rect.adjusted(width / 2, width / 2, -width / 2, -width / 2));
    painter.restore();
}

void setDrawsOwnFocusFrame(QWidget* widget) { widget->setProperty(kOwnFrame, true); }

bool drawsOwnFocusFrame(const QWidget* widget) { return widget->property(kOwnFrame).toBool(); }

FocusRing::FocusRing(QWidget* window) : QWidget(window), m_window(window)
{
    setObjectName(QStringLiteral("focusRing"));
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setFocusPolicy(Qt::NoFocus);
    hide();
    connect(qApp, &QApplication::focusChanged, this, [this](QWidget*, QWidget* now) { follow(now); });
}

void FocusRing::setScale(double scale)
{
    m_scale = scale;
    place();
}

int FocusRing::ringWidth() const { return static_cast<int>(std::lround(kFocusRingWidth * m_scale)); }

void FocusRing::follow(QWidget* focus)
{
    // Only this window's controls; a popup (a combo box's list, a menu) has its own look.
    if (focus && (focus->window() != m_window || focus->isWindow() || drawsOwnFocusFrame(focus)))
        focus = nullptr;
    if (focus == m_target)
        return;
    watch(false);
    m_target = focus;
    watch(true);
    place();
}

void FocusRing::watch(bool on)
{
    if (!on) {
        for (const QPointer<QWidget>& w : std::as_const(m_watched))
            if (w)
                w->removeEventFilter(this);
        m_watched.clear();
        return;
    }
    for (QWidget* w = m_target; w && w != m_window; w = w->parentWidget()) {
        w->installEventFilter(this);
        m_watched.push_back(w);
    }
}

void FocusRing::place()
{
    if (!m_target || !m_window || !m_target->isVisible() || !m_target->hasFocus()) {
        hide();
        return;
    }
    const int w = ringWidth();
    const QRect target(m_target->mapTo(m_window, QPoint()), m_target->size());
    const QRect ring = target.adjusted(-w, -w, w, w);
    // What holds the control cuts the ring where it cuts the control (a panel scrolled), and
    // the window's edge cuts it too.
    QRect clip = ring & m_window->rect();
    for (QWidget* a = m_target->parentWidget(); a && a != m_window; a = a->parentWidget())
        clip &= QRect(a->mapTo(m_window, QPoint()), a->size());
    if (!clip.intersects(target)) {
        hide();
        return;
    }
    const QRect shown = ring & m_window->rect();
    m_ring = ring;
    m_clip = clip.translated(-shown.topLeft());
    setGeometry(shown);
    show();
    raise();
    update();
}

bool FocusRing::eventFilter(QObject* watched, QEvent* event)
{
    switch (event->type()) {
    case QEvent::Move:
    case QEvent::Resize:
    case QEvent::Show:
    case QEvent::Hide:
    case QEvent::FocusOut: place(); break;
    case QEvent::ParentChange: // what holds the control changed: watch the new chain
        watch(false);
        watch(true);
        place();
        break;
    default: break;
    }
    return QWidget::eventFilter(watched, event);
}

void FocusRing::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    painter.setClipRect(m_clip);
    const int w = ringWidth();
    const QRect r = m_ring.translated(-pos());
    painter.setPen(Qt::NoPen);
    painter.setBrush(kFocusRingColour);
    // Four bars round the control: the control itself shows through the middle.
    painter.drawRect(r.left(), r.top(), r.width(), w);
    painter.drawRect(r.left(), r.bottom() - w + 1, r.width(), w);
    painter.drawRect(r.left(), r.top() + w, w, r.height() - 2 * w);
    painter.drawRect(r.right() - w + 1, r.top() + w, w, r.height() - 2 * w);
}

} // namespace granota::ui
