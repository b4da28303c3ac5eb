#include "ui/decasteljau/decasteljau_curve_drag.h"

#include "core/base/number_format.h"
#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/bezier/molding.h"
#include "core/exact/exact_cost.h"
#include "core/exact/rational_approximation.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/number_text.h"
#include "ui/common/point_commands.h"
#include "ui/common/point_editor.h"

#include <QEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QUndoStack>

#include <cmath>

namespace granota::ui {

DeCasteljauCurveDrag::DeCasteljauCurveDrag(CurveCanvas* canvas, PointEditor* editor, QUndoStack* undoStack, QObject* parent)
    : QObject(parent), m_canvas(canvas), m_editor(editor), m_undo(undoStack)
{
    // Installed after the editor's filter: Qt asks the last one installed first.
    m_canvas->installEventFilter(this);
    // Undo, redo or a document in the middle of a mold: the points are no longer the mold's,
    // and the mold ends there (the release then finds none), as a point drag does.
    connect(m_undo, &QUndoStack::indexChanged, this, [this] { m_molding = false; });
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (!m_hover || !isFinite(m_hover->point))
            return;
        const QPointF s = view.toScreen(m_hover->point);
        const double r = style.handleRadius() * 0.8;
        const QColor colour(0xe0, 0x7b, 0x00);
        p.setPen(QPen(colour, style.thinLine() * 2));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(s, r, r);
        p.setFont(style.labelFont());
        const QString label = QStringLiteral("t = %1").arg(displaySignificant(m_hover->t, 4));
        const QFontMetricsF fm(p.font());
        // A white halo under the label: it stays readable over the construction.
        const QRectF box(s + QPointF(r + 3 * style.scale, -r - fm.height()),
                         QSizeF(fm.horizontalAdvance(label) + 4, fm.height()));
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(255, 255, 255, 200));
        p.drawRect(box);
        p.setPen(colour);
        p.drawText(box, Qt::AlignCenter, label);
    });
}

void DeCasteljauCurveDrag::updateHover(const QPointF& screen)
{
    std::optional<ClosestPoint> next;
    const auto& points = m_editor->points();
    if (!points.empty() && m_editor->pick(screen) < 0) {
        const Point at = m_canvas->view().toModel(screen);
        if (isFinite(at)) {
            const ClosestPoint c = closestPoint(points, at);
            const QPointF d = m_canvas->view().toScreen(c.point) - screen;
            if (std::hypot(d.x(), d.y()) <= kHoverPixels * m_canvas->style().scale)
                next = c;
        }
    }
    const bool changed = next.has_value() != m_hover.has_value() ||
                         (next && (next->t != m_hover->t || next->point != m_hover->point));
    m_hover = next;
    if (changed) {
        m_canvas->update();
        emit hoverChanged();
    }
}

void DeCasteljauCurveDrag::finishMold()
{
    if (!m_molding)
        return;
    m_molding = false;
    const EditedPoints now = m_editor->edited();
    if (now != m_moldStart)
        m_undo->push(
            new PointsCommand(m_editor, m_moldStart, now, tr("Mold the curve at t = %1").arg(displaySignificant(m_moldT, 4))));
    else
        m_editor->applyPoints(now.points, now.exact); // the tab refreshes what it deferred while molding
}

namespace {

/// The control points after moving c(t) by `step` × (dx, dy). Exactly, on the points' exact
/// forms (else their doubles' values) and the fraction t stands for (meantRational), when that
/// costs no more than an exact panel may (exact_cost.h): at t = 0, P_0 at 0.2 moved by a step of
/// 1/10 is 3/10, not the double sum 0.30000000000000004, and the editor keeps the fractions —
/// what the table, the CSV and the panels then show. In doubles beyond, without exact forms.
EditedPoints moldedByStep(const EditedPoints& points, double t, const Rational& step, int dx, int dy)
{
    std::vector<RPoint> exact;
    exact.reserve(points.points.size());
    for (std::size_t i = 0; i < points.points.size(); ++i)
        exact.emplace_back(exactOr(points.exactAt(i).x, points.points[i].x), exactOr(points.exactAt(i).y, points.points[i].y));
    const Rational exactT = meantRational(t);
    const int degree = static_cast<int>(exact.size()) - 1;
    if (!exactWorkAllowed(deCasteljauExactWork(degree, maxBitLength(exact), bitLength(exactT)))) {
        const Point target = deCasteljauPoint(points.points, t) + toDouble(step) * Point(dx, dy);
        return {moldCurve(points.points, t, target), std::vector<ExactPoint>()}; // none has an exact form
    }
    const RPoint target = deCasteljauPoint(exact, exactT) + RPoint(Rational(step * dx), Rational(step * dy));
    const std::vector<RPoint> molded = moldCurve(exact, exactT, target);
    return {toDouble(molded), exactForms(molded)};
}

} // namespace

void DeCasteljauCurveDrag::moldByKey(int dx, int dy, bool tenTimes)
{
    const EditedPoints points = m_editor->edited();
    if (points.points.empty() || !m_parameter || m_molding)
        return;
    const double t = m_parameter();
    const Rational exactStep = m_editor->nudgeStep(tenTimes);
    const double step = toDouble(exactStep);
    const auto molded = moldedByStep(points, t, exactStep, dx, dy);
    for (const Point& q : molded.points)
        if (!isFinite(q)) {
            emit message(tr("Refused: a coordinate must be a finite number."));
            return;
        }
    if (molded.points == points.points)
        return; // too far from the origin for this step to change the doubles
    // Merged with the next key of the run, as the nudges of a control point are.
    m_undo->push(new PointsCommand(m_editor, points, molded, tr("Mold the curve at t = %1").arg(displaySignificant(t, 4)),
                                   PointsCommand::kCurveNudge));
    emit message(
        tr("c(t) at t = %1 moved by %2: the control points changed the least that does it.")
            .arg(displaySignificant(t, 4), displayPair(displaySignificant(step * dx, 6), displaySignificant(step * dy, 6))));
}

bool DeCasteljauCurveDrag::eventFilter(QObject* watched, QEvent* event)
{
    if (watched != m_canvas)
        return QObject::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::MouseButtonPress: {
        auto* e = static_cast<QMouseEvent*>(event);
        if (e->button() != Qt::LeftButton || m_editor->pick(e->position()) >= 0)
            return false; // a control point: the editor drags it
        updateHover(e->position());
        if (!m_hover)
            return false; // empty paper: the canvas pans
        m_editor->setSelected(-1);
        m_molding = true;
        m_moldT = m_hover->t;
        m_moldStart = m_editor->edited();
        return true;
    }
    case QEvent::MouseMove: {
        auto* e = static_cast<QMouseEvent*>(event);
        if (!m_molding) {
            if (!e->buttons()) {
                updateHover(e->position());
            } else if (m_hover) { // a control point dragged, or the paper panned: no hover meanwhile
                m_hover.reset();
                m_canvas->update();
                emit hoverChanged();
            }
            return false;
        }
        const Point target = m_canvas->view().toModel(e->position());
        if (!isFinite(target))
            return false;
        // From the points the drag began with: the point at t is exactly where the mouse is.
        // Where the mouse happens to be: the molded points have no exact form.
        const auto molded = moldCurve(m_moldStart.points, m_moldT, target);
        bool finite = true;
        for (const Point& q : molded)
            finite = finite && isFinite(q);
        if (finite && molded.size() == m_moldStart.points.size()) {
            m_hover = ClosestPoint{m_moldT, target, 0.0};
            m_editor->applyPoints(molded, std::vector<ExactPoint>()); // none exact; undone at the release, as one step
            m_molding = true;                                         // applyPoints ends the editor's drags, not this one
        }
        return false; // the canvas still reports the cursor position
    }
    case QEvent::MouseButtonRelease: {
        auto* e = static_cast<QMouseEvent*>(event);
        if (e->button() != Qt::LeftButton || !m_molding)
            return false;
        finishMold();
        updateHover(e->position());
        return true;
    }
    case QEvent::KeyPress: {
        auto* e = static_cast<QKeyEvent*>(event);
        if (!(e->modifiers() & Qt::AltModifier))
            return false; // plain arrows: the editor nudges the selected control point
        const bool tenTimes = e->modifiers() & Qt::ShiftModifier;
        switch (e->key()) {
        case Qt::Key_Left: moldByKey(-1, 0, tenTimes); return true;
        case Qt::Key_Right: moldByKey(1, 0, tenTimes); return true;
        case Qt::Key_Up: moldByKey(0, 1, tenTimes); return true;
        case Qt::Key_Down: moldByKey(0, -1, tenTimes); return true;
        default: return false;
        }
    }
    case QEvent::Leave:
        if (!m_molding && m_hover) {
            m_hover.reset();
            m_canvas->update();
            emit hoverChanged();
        }
        return false;
    default: return QObject::eventFilter(watched, event);
    }
}

} // namespace granota::ui
