#include "ui/frog/frog_canvas.h"
#include "ui/common/focus_frame.h"
#include "ui/common/number_text.h"
#include "ui/common/presentation_scale.h"

#include "core/softbody/polygon_geometry.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QCursor>
#include <QEnterEvent>
#include <QFontMetricsF>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

/// How often the text overlays and the averaged timings refresh.
constexpr qint64 kTextRefreshNs = 250'000'000;
const QColor kLetterbox(0x26, 0x30, 0x36);
const QColor kSkyTop(0xb9, 0xdc, 0xee);                  // FrogArt's sky, top
const QColor kMudBottom(0x86, 0x6a, 0x44);               // FrogArt's bank, bottom
const QColor kFrameCaptionColour(0x26, 0x30, 0x36, 190); // the frame's caption, over the sky

} // namespace

FrogCanvas::FrogCanvas(FrogRun* run, QWidget* parent) : QWidget(parent), m_run(run)
{
    setMouseTracking(true); // Processing's mouseX/mouseY are always current (§4.1, §4.13)
    setFocusPolicy(Qt::StrongFocus);
    setDrawsOwnFocusFrame(this);
    setAttribute(Qt::WA_OpaquePaintEvent);
    m_clock.start();
    m_textClock.start();
    buildPens();
    observe();
}

FrogCanvas::FrogCanvas(QWidget* parent) : FrogCanvas(new FrogRun, parent) { m_run->setParent(this); }

void FrogCanvas::observe()
{
    connect(m_run, &FrogRun::stepped, this, [this] {
        refreshTexts();
        update();
    });
    connect(m_run, &FrogRun::frameRan, this, [this] {
        if (m_textClock.nsecsElapsed() >= kTextRefreshNs)
            refreshTexts();
        update();
    });
    connect(m_run, &FrogRun::changed, this, [this] {
        refreshTexts();
        update();
    });
    connect(m_run, &FrogRun::runShown, this, &FrogCanvas::runShown);
    connect(m_run, &FrogRun::grabLost, this, &FrogCanvas::letGo);
}

FrogCanvas::~FrogCanvas() = default;

void FrogCanvas::runShown(bool fresh)
{
    m_scenePainter.restart();
    m_pressed = false;
    m_keyboardHeld = false;
    m_spawnHeld = false;
    // Processing's mouseX/mouseY hold from the first frame (§4.1, §4.13); a run brought back
    // is not sent one (recorded, it would cut off the run's recorded future).
    if (fresh && sim() && m_mouseKnown && underMouse())
        m_run->send(InputKind::Move, m_mouse);
    m_reportedRadius = -1;
    reportMouseRadius();
    unsetCursor();
    refreshTexts();
    update();
}

void FrogCanvas::letGo()
{
    m_pressed = false;
    m_keyboardHeld = false;
    m_spawnHeld = false;
    unsetCursor();
    reportMouseRadius();
}

void FrogCanvas::setOverlays(const Overlays& overlays)
{
    m_overlays = overlays;
    m_run->setGhostShown(overlays.ghost);
    m_run->setTrailShown(overlays.trail);
    m_run->setKeepsPrevious(overlays.velocities);
    refreshTexts();
    update();
}

void FrogCanvas::setBezierOutline(BezierOutline mode)
{
    m_scenePainter.setBezierOutline(mode);
    refreshTexts();
    update();
}

void FrogCanvas::setPresentation(bool on)
{
    m_style.scale = presentationScale(on);
    buildPens();
    refreshTexts();
    update();
}

void FrogCanvas::buildPens()
{
    m_scenePainter.setScale(m_style.scale);
    m_overlayPainter.setStyle(m_style.scale, m_style.labelFont(), font());
    m_framePen = QPen(QColor(0x26, 0x30, 0x36, 45), 1);
}

QStringList FrogCanvas::textLines() const { return m_overlayPainter.lines(); }

std::vector<LinkAngleReading> FrogCanvas::linkAngles(int chain) const
{
    std::vector<Point> joints;
    std::vector<LinkAngleReading> out;
    if (sim() && chain >= 0 && chain < sim()->chainCount())
        readLinkAngles(*sim(), chain, joints, out);
    return out;
}

void FrogCanvas::setRuler(const std::optional<std::pair<Point, Point>>& ruler)
{
    m_ruler = ruler;
    m_rulerDragging = m_rulerPlacing = false;
    update();
}

QString FrogCanvas::rulerText() const
{
    if (!m_ruler)
        return {};
    const Point d = m_ruler->second - m_ruler->first;
    return tr("%1 px (Δx %2, Δy %3)")
        .arg(displayFixed(std::sqrt(d.x * d.x + d.y * d.y), 1), displayFixed(d.x, 1), displayFixed(d.y, 1));
}

void FrogCanvas::setSceneSummary(const QString& summary)
{
    m_sceneSummary = summary;
    updateAccessibleDescription();
}

void FrogCanvas::updateAccessibleDescription()
{
    if (!sim() || sim()->bodyCount() == 0) {
        setAccessibleDescription(m_sceneSummary);
        return;
    }
    setAccessibleDescription(tr("%1; area error %2 %.").arg(m_sceneSummary, displayFixed(sim()->readouts().areaErrorPercent, 1)));
}

void FrogCanvas::refreshTexts()
{
    m_textClock.restart();
    updateAccessibleDescription();
    m_run->averageTimings();
    if (m_draws > 0) {
        m_drawShownMs = m_drawNsSum / m_draws / 1e6;
        m_drawNsSum = 0;
        m_draws = 0;
    }
    m_scenePainter.averageFitCost();
    emit fitCostChanged(fitMicroseconds());
    const bool blownUpLine = sim() && m_run->blownUp(); // lines[0], wrapped to the canvas: it must be read whole
    m_overlayPainter.setLines(composeTexts(blownUpLine), std::max(120.0, textPanelRoom()), blownUpLine);
}

double FrogCanvas::textPanelRoom() const
{
    // What the text panel's margins and padding leave of the scene's width.
    return sceneRectIn(QRectF(rect())).width() -
           2 * (FrogOverlayPainter::kPanelMargin + FrogOverlayPainter::kPanelPad) * m_style.scale;
}

double FrogCanvas::textPanelWidth() const { return m_overlayPainter.linesWidth(); }

// ---------------------------------------------------------------- coordinates

QRectF FrogCanvas::sceneRectIn(const QRectF& target) const
{
    const double W = sim() ? sim()->scene().params.width : 1280, H = sim() ? sim()->scene().params.height : 720;
    const double s = std::min(target.width() / W, target.height() / H);
    if (!(s > 0) || !std::isfinite(s))
        return {};
    return QRectF(target.center().x() - W * s / 2, target.center().y() - H * s / 2, W * s, H * s);
}

QPointF FrogCanvas::toWidget(const Point& p) const
{
    const QRectF r = sceneRectIn(QRectF(rect()));
    const double W = sim() ? sim()->scene().params.width : 1280;
    const double s = r.width() / W;
    return QPointF(r.left() + p.x * s, r.top() + p.y * s);
}

Point FrogCanvas::toScene(const QPointF& w) const
{
    const QRectF r = sceneRectIn(QRectF(rect()));
    const double W = sim() ? sim()->scene().params.width : 1280;
    const double s = r.width() / W;
    if (!(s > 0))
        return Point(0, 0);
    return Point((w.x() - r.left()) / s, (w.y() - r.top()) / s);
}

// ---------------------------------------------------------------- drawing

void FrogCanvas::paintEvent(QPaintEvent*)
{
    const qint64 t0 = m_clock.nsecsElapsed();
    QPainter p(this);
    render(p, QRectF(rect()));
    if (hasFocus()) { // on screen only: the keyboard cursor and the focus frame
        drawKeyboardCursor(p);
        drawFocusFrame(p, QRectF(rect()), palette(), m_style.scale);
    }
    m_drawNsSum += double(m_clock.nsecsElapsed() - t0);
    ++m_draws;
}

void FrogCanvas::render(QPainter& p, const QRectF& target) { renderScene(p, target, true); }

void FrogCanvas::renderFrame(QPainter& p, const QRectF& target) { renderScene(p, target, false); }

void FrogCanvas::renderScene(QPainter& p, const QRectF& target, bool textPanel)
{
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setRenderHint(QPainter::SmoothPixmapTransform, true);
    p.fillRect(target, kLetterbox);
    const QRectF r = sceneRectIn(target);
    if (!sim() || r.width() < 1 || r.height() < 1) {
        p.restore();
        return;
    }
    // Bars above and below continue the sky and the mud; the frame's edge stays visible.
    if (r.top() > target.top() + 0.5) {
        p.fillRect(QRectF(target.left(), target.top(), target.width(), r.top() - target.top()), kSkyTop);
        p.fillRect(QRectF(target.left(), r.bottom(), target.width(), target.bottom() - r.bottom()), kMudBottom);
    }
    p.save();
    p.setPen(m_framePen);
    p.setBrush(Qt::NoBrush);
    p.drawRect(r.adjusted(-0.5, -0.5, 0.5, 0.5));
    // The frame's top edge, a thin line across the sky: say what it is.
    p.setPen(kFrameCaptionColour);
    p.setFont(m_overlayPainter.numberFont());
    const QRectF caption = frameCaptionRect(target);
    p.drawText(caption, Qt::AlignRight | Qt::AlignVCenter,
               QFontMetricsF(m_overlayPainter.numberFont()).elidedText(frameCaption(), Qt::ElideRight, caption.width()));
    p.restore();
    p.setClipRect(r, Qt::IntersectClip);
    // One path for the screen and every export: the scene, then what is drawn over it. The
    // pond is a pixmap on screen only (a vector drawing in an export).
    const std::optional<Point> look = m_mouseKnown ? std::optional<Point>(m_mouse) : std::nullopt;
    m_scenePainter.draw(p, *sim(), r, p.device() == this ? devicePixelRatioF() : 0.0, look);
    const FrogOverlayPainter::Frame frame{*m_run,         m_overlays, m_scenePainter.art(),
                                          m_markedBody,   m_ruler,    m_ruler ? rulerText() : QString(),
                                          QSizeF(size()), textPanel};
    m_overlayPainter.draw(p, frame, r, target);
    p.restore();
}

QString FrogCanvas::frameCaption() const { return tr("Top of the frame: the scene's upper wall (y = 0)"); }

QRectF FrogCanvas::frameCaptionRect(const QRectF& target) const
{
    // Just above the line when the sky bar over the frame has room for it, else just below.
    const QRectF r = sceneRectIn(target);
    const double h = QFontMetricsF(m_overlayPainter.numberFont()).height() + 2, margin = 6 * m_style.scale;
    const double top = r.top() - target.top() >= h + 2 ? r.top() - h - 1 : r.top() + 1;
    return QRectF(r.left() + margin, top, r.width() - 2 * margin, h);
}

void FrogCanvas::setMarkedBody(int body)
{
    m_run->setSeriesBodiesAsked(body >= 0); // a scene of many bodies keeps them only while asked
    if (body == m_markedBody)
        return;
    m_markedBody = body;
    update();
}

void FrogCanvas::paintHeadOf(QPainter& p, int index)
{
    if (sim())
        m_scenePainter.paintHead(p, *sim(), index, m_mouseKnown ? std::optional<Point>(m_mouse) : std::nullopt);
}

// ---------------------------------------------------------------- mouse and keys

void FrogCanvas::mousePressEvent(QMouseEvent* event)
{
    if (!sim())
        return;
    setFocus(Qt::MouseFocusReason);
    m_mouse = toScene(event->position());
    m_mouseKnown = true;
    const bool measure = event->button() == Qt::RightButton ||
                         (event->button() == Qt::LeftButton && (event->modifiers() & Qt::ControlModifier));
    if (measure) { // the ruler: measuring grabs nothing and records nothing
        m_ruler = std::pair{m_mouse, m_mouse};
        m_rulerDragging = true;
        m_rulerPlacing = false;
        update();
        return;
    }
    if (event->button() != Qt::LeftButton)
        return;
    if (m_overlays.trail && (event->modifiers() & Qt::ShiftModifier)) { // choose the trail's point, grab nothing
        if (!m_run->chooseTrailPoint(m_mouse))
            emit statusMessage(tr("Shift+click on a vertex or a joint to follow it with the trail."));
        return;
    }
    // Annex II, mousePressed: grab when the cursor is inside the body. Going back in a run
    // (docs/rewind.md), a press that grabs nothing leaves the recorded future alone.
    if (m_run->playingBack() && !m_run->wouldGrab(m_mouse)) {
        emit statusMessage(
            tr("Playing the recorded run back: press inside a body to take over from step %1.").arg(sim()->stepCount()));
        return;
    }
    m_run->send(InputKind::Move, m_mouse);
    reportMouseRadius();
    m_pressed = true;
    const bool held = m_run->send(InputKind::Press, m_mouse);
    if (held && sim()->grabbing())
        setCursor(Qt::ClosedHandCursor);
    else if (!held && sim()->scene().has(SceneComponent::Grab))
        emit statusMessage(tr("Press inside the body to grab it."));
    update();
}

void FrogCanvas::mouseMoveEvent(QMouseEvent* event)
{
    if (!sim())
        return;
    m_mouse = toScene(event->position());
    m_mouseKnown = true;
    if ((m_rulerDragging || m_rulerPlacing) && m_ruler) {
        m_ruler->second = m_mouse;
        update();
    }
    if (m_pressed || !m_run->playingBack()) // hovering over a run played back changes nothing
        m_run->send(InputKind::Move, m_mouse);
    reportMouseRadius();
    if (!m_pressed && sim()->scene().has(SceneComponent::Grab)) {
        if (insideABody(m_mouse))
            setCursor(Qt::OpenHandCursor);
        else
            unsetCursor();
    }
    if (!m_run->running())
        update(); // the eyes follow the mouse even when paused
}

void FrogCanvas::reportMouseRadius()
{
    const std::optional<double> r = sim() ? sim()->mouseRadius() : std::nullopt;
    if (r && *r != m_reportedRadius) {
        m_reportedRadius = *r;
        emit mouseRadiusChanged(*r);
    }
}

void FrogCanvas::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_rulerDragging && (event->button() == Qt::RightButton || event->button() == Qt::LeftButton)) {
        m_rulerDragging = false;
        const QPointF from = toWidget(m_ruler->first), to = toWidget(m_ruler->second);
        if ((from - to).manhattanLength() < 3) // a click, not a drag: clears the ruler
            m_ruler.reset();
        else
            emit statusMessage(tr("Ruler: %1. Esc or a right click clears it.").arg(rulerText()));
        update();
        return;
    }
    if (!sim() || event->button() != Qt::LeftButton || !m_pressed)
        return;
    m_keyboardHeld = false;
    m_run->send(InputKind::Release); // Annex II, mouseReleased
    m_pressed = false;
    unsetCursor();
    update();
}

void FrogCanvas::drawKeyboardCursor(QPainter& p) const
{
    if (!sim())
        return;
    const QPointF c = toWidget(m_mouse);
    const double k = m_style.scale, r = 9 * k;
    p.save();
    p.setRenderHint(QPainter::Antialiasing, true);
    p.setBrush(Qt::NoBrush);
    for (const auto& [colour, width] :
         {std::pair{QColor(Qt::white), 4.0 * k}, std::pair{palette().color(QPalette::Highlight), 2.0 * k}}) {
        p.setPen(QPen(colour, width));
        p.drawEllipse(c, r, r);
        p.drawLine(c - QPointF(2 * r, 0), c - QPointF(r, 0));
        p.drawLine(c + QPointF(r, 0), c + QPointF(2 * r, 0));
        p.drawLine(c - QPointF(0, 2 * r), c - QPointF(0, r));
        p.drawLine(c + QPointF(0, r), c + QPointF(0, 2 * r));
    }
    p.restore();
}

bool FrogCanvas::insideABody(Point at)
{
    for (int i = 0; i < sim()->bodyCount(); ++i) {
        sim()->bodyVertices(i, m_vertices);
        if (pointInPolygon(at, m_vertices))
            return true;
    }
    return false;
}

Point FrogCanvas::bodyCentre(int body)
{
    sim()->bodyVertices(body, m_vertices);
    Point sum{0, 0};
    for (const Point& v : m_vertices)
        sum = {sum.x + v.x / double(m_vertices.size()), sum.y + v.y / double(m_vertices.size())};
    return sum;
}

Point FrogCanvas::keyboardCursorStart()
{
    // On the body nearest the middle of the view, where the keys can grab it at once (the
    // view's middle if the scene has none), never in a corner half out of sight.
    const Point middle = toScene(QPointF(rect().center()));
    if (const int body = nearestBody(middle); body >= 0)
        return bodyCentre(body);
    return middle;
}

void FrogCanvas::placeKeyboardCursor()
{
    if (m_mouseKnown || !sim())
        return;
    m_mouse = keyboardCursorStart();
    m_mouseKnown = true;
}

int FrogCanvas::nearestBody(Point at)
{
    int best = -1;
    double bestDistance = 0;
    for (int i = 0; i < sim()->bodyCount(); ++i) {
        sim()->bodyVertices(i, m_vertices);
        for (const Point& v : m_vertices) {
            const double d = std::hypot(v.x - at.x, v.y - at.y);
            if (best < 0 || d < bestDistance) {
                best = i;
                bestDistance = d;
            }
        }
    }
    return best;
}

bool FrogCanvas::keyboardGrab()
{
    if (!sim() || m_pressed)
        return false;
    placeKeyboardCursor();
    // Outside every body, the cursor first jumps to the centre of the nearest one.
    if (const int body = insideABody(m_mouse) ? -1 : nearestBody(m_mouse); body >= 0)
        m_mouse = bodyCentre(body);
    if (m_run->playingBack() && !m_run->wouldGrab(m_mouse)) {
        emit statusMessage(tr("Playing the recorded run back: move the cursor inside a body to take over from step %1.")
                               .arg(sim()->stepCount()));
        update();
        return false;
    }
    m_run->send(InputKind::Move, m_mouse);
    reportMouseRadius();
    m_pressed = m_run->send(InputKind::Press, m_mouse);
    m_keyboardHeld = m_pressed;
    if (!m_pressed && sim()->scene().has(SceneComponent::Grab))
        emit statusMessage(tr("Nothing to grab here: move the cursor inside the body with the arrows."));
    update();
    return m_pressed;
}

void FrogCanvas::keyboardRelease()
{
    if (!sim() || !m_keyboardHeld)
        return;
    m_run->send(InputKind::Release);
    m_pressed = false;
    m_keyboardHeld = false;
    update();
}

void FrogCanvas::moveKeyboardCursor(double dx, double dy)
{
    if (!sim())
        return;
    placeKeyboardCursor();
    const double W = sim()->scene().params.width, H = sim()->scene().params.height;
    m_mouse = {std::clamp(m_mouse.x + dx, 0.0, W - 1), std::clamp(m_mouse.y + dy, 0.0, H - 1)};
    if (m_rulerPlacing && m_ruler)
        m_ruler->second = m_mouse;
    if (m_pressed || !m_run->playingBack())
        m_run->send(InputKind::Move, m_mouse);
    reportMouseRadius();
    update();
}

void FrogCanvas::keyPressEvent(QKeyEvent* event)
{
    // The keyboard's grab (docs/classroom.md): the arrows move the cursor (Shift: five times
    // further), G or Enter grabs at it and lets go, Esc lets go.
    const double step = kKeyboardStep * (event->modifiers() & Qt::ShiftModifier ? 5 : 1);
    switch (event->key()) {
    case Qt::Key_Left: moveKeyboardCursor(-step, 0); return;
    case Qt::Key_Right: moveKeyboardCursor(step, 0); return;
    case Qt::Key_Up: moveKeyboardCursor(0, -step); return;
    case Qt::Key_Down: moveKeyboardCursor(0, step); return;
    case Qt::Key_G:
    case Qt::Key_Return:
    case Qt::Key_Enter:
        if (event->isAutoRepeat())
            return;
        if (m_keyboardHeld)
            keyboardRelease();
        else
            keyboardGrab();
        return;
    case Qt::Key_Escape:
        if (m_keyboardHeld) {
            keyboardRelease();
            return;
        }
        if (m_ruler) {
            m_ruler.reset();
            m_rulerPlacing = m_rulerDragging = false;
            update();
            return;
        }
        break;
    case Qt::Key_L: // the ruler from the keyboard: one end at the cursor, the arrows, L again
        if (event->isAutoRepeat() || !sim())
            return;
        placeKeyboardCursor();
        if (m_rulerPlacing) {
            m_rulerPlacing = false;
            emit statusMessage(tr("Ruler: %1. Esc or a right click clears it.").arg(rulerText()));
        } else {
            m_ruler = std::pair{m_mouse, m_mouse};
            m_rulerPlacing = true;
            emit statusMessage(tr("Ruler: move the cursor with the arrows to the other end, then L."));
        }
        update();
        return;
    default: break;
    }
    if (event->key() != Qt::Key_Space) {
        QWidget::keyPressEvent(event);
        return;
    }
    event->accept();
    if (event->isAutoRepeat() || !sim() || m_spawnHeld)
        return;
    // Annex II, keyPressed(' '): a new frog at the mouse, held until the key is released.
    if (!m_mouseKnown) {
        m_mouse = toScene(mapFromGlobal(QCursor::pos()));
        m_mouseKnown = true;
    }
    m_run->send(InputKind::Spawn, m_mouse); // a new body: more work a step
    m_spawnHeld = true;
    update();
}

void FrogCanvas::keyReleaseEvent(QKeyEvent* event)
{
    if (event->key() != Qt::Key_Space) {
        QWidget::keyReleaseEvent(event);
        return;
    }
    event->accept();
    if (event->isAutoRepeat() || !m_spawnHeld)
        return;
    m_spawnHeld = false;
    if (sim())
        m_run->send(InputKind::ReleaseSpawn); // Annex II, keyReleased(' ')
    update();
}

void FrogCanvas::enterEvent(QEnterEvent* event)
{
    // The space bar belongs to the canvas as soon as the mouse is over it (unless a number
    // is being typed in a field).
    if (!qobject_cast<QAbstractSpinBox*>(QApplication::focusWidget()))
        setFocus(Qt::MouseFocusReason);
    QWidget::enterEvent(event);
}

void FrogCanvas::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    m_run->setShown(isVisible());
}

void FrogCanvas::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    if (sim())
        refreshTexts();
}

void FrogCanvas::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event); // a hidden tab costs nothing
    m_run->setShown(isVisible());
}

void FrogCanvas::focusInEvent(QFocusEvent* event)
{
    // The cursor is drawn where the keys will start, but the scene is not told of a mouse
    // until a key moves or uses it (the §4.1 polygon's radius follows the mouse).
    if (!m_mouseKnown && sim())
        m_mouse = keyboardCursorStart();
    update(); // the focus frame and the keyboard cursor
    QWidget::focusInEvent(event);
}

void FrogCanvas::focusOutEvent(QFocusEvent* event)
{
    keyboardRelease();
    update();
    // The key release would go elsewhere: let go of a frog held by the space bar now.
    if (m_spawnHeld && sim())
        m_run->send(InputKind::ReleaseSpawn);
    m_spawnHeld = false;
    QWidget::focusOutEvent(event);
}

void FrogCanvas::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::FontChange)
        buildPens();
    if (event->type() == QEvent::LanguageChange || event->type() == QEvent::FontChange)
        refreshTexts();
    QWidget::changeEvent(event);
}

} // namespace granota::ui
