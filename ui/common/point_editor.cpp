#include "ui/common/point_editor.h"

#include "ui/common/curve_canvas.h"
#include "ui/common/point_commands.h"
#include "ui/common/value_command.h"

#include "core/exact/rational_approximation.h"
#include "core/exact/round_step.h"

#include <QContextMenuEvent>
#include <QFontMetricsF>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <limits>

namespace granota::ui {

namespace {
/// Above this many points, coincident labels are not looked for (the check is quadratic).
constexpr std::size_t kStackLabelsUpTo = 300;
} // namespace

PointEditor::PointEditor(CurveCanvas* canvas, QUndoStack* undoStack, QObject* parent)
    : QObject(parent), m_canvas(canvas), m_undo(undoStack), m_color(CanvasStyle().handle)
{
    m_canvas->installEventFilter(this);
    m_canvas->addLayer([this](QPainter& p, const ViewTransform& view, const CanvasStyle& style) {
        if (m_edited.points.empty() || !m_handlesVisible)
            return;
        if (m_polygonVisible && m_edited.points.size() > 1) {
            QPen pen(style.polygon, style.thinLine(), Qt::DashLine);
            p.setPen(pen);
            QPainterPath path(view.toScreen(m_edited.points[0]));
            for (std::size_t i = 1; i < m_edited.points.size(); ++i)
                path.lineTo(view.toScreen(m_edited.points[i]));
            p.drawPath(path);
        }
        p.setFont(style.labelFont());
        for (const Mark& mark : marks(view, style)) {
            const bool sel = static_cast<int>(mark.index) == m_selected;
            p.setPen(QPen(Qt::white, style.thinLine()));
            p.setBrush(sel ? style.handleSelected : m_color);
            p.drawEllipse(mark.handle);
            if (!mark.label.isEmpty()) {
                p.setPen(style.text);
                p.drawText(mark.labelBaseline, m_prefix + QString::number(mark.index));
            }
        }
    });
}

std::vector<PointEditor::Mark> PointEditor::marks(const ViewTransform& view, const CanvasStyle& style) const
{
    std::vector<Mark> out;
    if (m_edited.points.empty() || !m_handlesVisible)
        return out;
    const QFontMetricsF fm(style.labelFont());
    // Past kLabelledPointsUpTo points (unless the user asks for labels) the handles are small
    // and unlabelled, so that the curve stays visible; the selected one keeps both.
    const bool labels = labelsShown() && !m_prefix.isEmpty();
    const double r = style.handleRadius();
    const double small = m_edited.points.size() > kLabelledPointsUpTo && !m_labelChoice.value_or(false) ? r * 0.5 : r;
    // Huge data sets (up to kMaxDataPoints in the fitting tab, docs/extreme-cases.md): draw every stride-th
    // handle and no labels, so that painting stays fast; the selected one always.
    constexpr std::size_t kMaxDrawnHandles = 5000;
    const std::size_t stride = (m_edited.points.size() + kMaxDrawnHandles - 1) / kMaxDrawnHandles;
    for (std::size_t i = 0; i < m_edited.points.size(); ++i) {
        const bool sel = static_cast<int>(i) == m_selected;
        if (stride > 1 && i % stride != 0 && !sel)
            continue;
        const QPointF s = view.toScreen(m_edited.points[i]);
        const double radius = sel ? r * 1.3 : small;
        Mark mark{i, QRectF(s - QPointF(radius, radius), QSizeF(2 * radius, 2 * radius)), {}, {}};
        const bool named = sel || static_cast<int>(i) == m_hovered; // labelled even when labels step aside
        if (stride <= 1 && (labels || (named && !m_prefix.isEmpty()))) {
            // Coincident points (Ex 2.3 closes its curve: P4 = P0) stack their labels.
            int below = 0;
            for (std::size_t j = 0; j < i && labels && m_edited.points.size() <= kStackLabelsUpTo; ++j) {
                const QPointF d = view.toScreen(m_edited.points[j]) - s;
                below += d.x() * d.x() + d.y() * d.y() < r * r;
            }
            mark.labelBaseline = s + QPointF(r + 3 * style.scale, -r + below * fm.height());
            const QString text = m_prefix + QString::number(i);
            mark.label = QRectF(mark.labelBaseline.x(), mark.labelBaseline.y() - fm.ascent(), fm.horizontalAdvance(text),
                                fm.height());
        }
        out.push_back(mark);
    }
    return out;
}

void PointEditor::setHandlesVisible(bool on)
{
    if (on == m_handlesVisible)
        return;
    m_handlesVisible = on;
    if (!on) {
        setHovered(-1);
        m_canvas->unsetCursor();
    }
    m_canvas->update();
}

void PointEditor::setHovered(int index)
{
    if (index == m_hovered)
        return;
    m_hovered = index;
    if (!labelsShown())
        m_canvas->update(); // its label comes and goes
}

bool PointEditor::labelsShown() const { return m_labelChoice.value_or(m_edited.points.size() <= kLabelledPointsUpTo); }

bool PointEditor::labelsHiddenAutomatically() const { return !m_labelChoice && m_edited.points.size() > kLabelledPointsUpTo; }

QString PointEditor::labelsHiddenNote() const
{
    if (!labelsHiddenAutomatically())
        return QString();
    return tr("%n points: their labels are hidden and their handles small, so that the curve shows; "
              "right-click the canvas ▸ Show point labels to see them.",
              nullptr, static_cast<int>(std::min<std::size_t>(m_edited.points.size(), std::numeric_limits<int>::max())));
}

void PointEditor::setLabelChoice(std::optional<bool> choice)
{
    if (choice == m_labelChoice)
        return;
    m_labelChoice = choice;
    m_canvas->update();
    emit labelChoiceChanged();
}

void PointEditor::chooseLabels(bool shown)
{
    if (shown == labelsShown() && m_labelChoice)
        return;
    const auto apply = [this](const std::optional<bool>& choice) { setLabelChoice(choice); };
    m_undo->push(new ValueCommand<std::optional<bool>>(apply, m_labelChoice, shown,
                                                       shown ? tr("Show point labels") : tr("Hide point labels")));
}

void PointEditor::applyPoints(const std::vector<Point>& points, const std::vector<ExactPoint>& exact)
{
    // Undo, redo or a document in the middle of a drag: the points are no longer the drag's,
    // and its index may be past their end. The drag ends here (the release finds none).
    m_dragging = -1;
    const bool hiddenBefore = labelsHiddenAutomatically();
    m_edited.points = points;
    m_edited.exact = exact.size() == points.size() ? exact : std::vector<ExactPoint>(); // else none has one
    if (!hiddenBefore && labelsHiddenAutomatically())
        emit message(labelsHiddenNote());
    if (m_selected >= static_cast<int>(m_edited.points.size()))
        setSelected(static_cast<int>(m_edited.points.size()) - 1);
    m_canvas->update();
    emit pointsChanged();
}

void PointEditor::setPoints(const std::vector<Point>& points, const QString& undoText)
{
    setPoints(points, writtenExact(points), undoText);
}

void PointEditor::setPoints(const std::vector<Point>& points, const std::vector<ExactPoint>& exact, const QString& undoText)
{
    for (const Point& p : points)
        if (!isFinite(p)) {
            emit message(tr("Refused: a point is not a finite number."));
            return;
        }
    finishDrag();
    m_undo->push(
        new PointsCommand(this, edited(), {points, exact.size() == points.size() ? exact : std::vector<ExactPoint>()}, undoText));
}

void PointEditor::movePoint(int index, Point to, const ExactPoint& exact)
{
    if (index < 0 || index >= static_cast<int>(m_edited.points.size()))
        return;
    if (!isFinite(to)) {
        emit message(tr("Refused: a coordinate must be a finite number."));
        return;
    }
    finishDrag();
    EditedPoints after = edited();
    after.set(static_cast<std::size_t>(index), to, exact);
    m_undo->push(new PointsCommand(this, edited(), after, tr("Move point %1").arg(index)));
}

void PointEditor::insertPoint(int index, Point p, const ExactPoint& exact)
{
    if (static_cast<int>(m_edited.points.size()) >= m_max) {
        emit message(tr("At most %n points here.", nullptr, m_max));
        return;
    }
    if (!isFinite(p))
        return;
    finishDrag();
    index = std::clamp(index, 0, static_cast<int>(m_edited.points.size()));
    EditedPoints after = edited();
    after.insert(static_cast<std::size_t>(index), p, exact);
    const QString text = tr("Add point");
    m_undo->beginMacro(text); // with the values a tab keeps per point (pointInserted)
    m_undo->push(new PointsCommand(this, edited(), after, text));
    emit pointInserted(index);
    m_undo->endMacro();
    setSelected(index);
}

void PointEditor::removePoint(int index)
{
    if (index < 0 || index >= static_cast<int>(m_edited.points.size()))
        return;
    if (static_cast<int>(m_edited.points.size()) <= m_min) {
        emit message(tr("At least %n points are needed here.", nullptr, m_min));
        return;
    }
    finishDrag();
    EditedPoints after = edited();
    after.erase(static_cast<std::size_t>(index));
    const QString text = tr("Delete point %1").arg(index);
    m_undo->beginMacro(text); // with the values a tab keeps per point (pointRemoved)
    m_undo->push(new PointsCommand(this, edited(), after, text));
    emit pointRemoved(index);
    m_undo->endMacro();
}

void PointEditor::finishDrag()
{
    if (m_dragging < 0)
        return;
    const int index = m_dragging;
    m_dragging = -1;
    const auto i = static_cast<std::size_t>(index);
    if (m_dragStart.points[i].x != m_edited.points[i].x || m_dragStart.points[i].y != m_edited.points[i].y ||
        m_dragStart.exactAt(i) != m_edited.exactAt(i))
        m_undo->push(new PointsCommand(this, m_dragStart, edited(), tr("Move point %1").arg(index)));
}

void PointEditor::setSelected(int index)
{
    if (index < -1 || index >= static_cast<int>(m_edited.points.size()))
        index = -1;
    if (index == m_selected)
        return;
    m_selected = index;
    m_canvas->update();
    emit selectionChanged(index);
}

std::pair<Point, ExactPoint> PointEditor::snappedExactly(Point p) const
{
    // Where the pointer puts a point: on the grid when snapping, else on the round step of one
    // pixel (1, 2 or 5 × 10^k). Exactly, as a nudge: the table then reads 2.34 rather than
    // 2.3456789012345678, and 7 grid steps of 0.1 are 0.7, not 0.7000000000000001.
    const double scale = m_canvas->view().scale();
    if (!isFinite(p) || !(scale > 0))
        return {p, ExactPoint{}};
    const Rational step = m_snap ? meantRational(m_gridStep) : roundStepAtMost(1.0 / scale).exact();
    const ExactPoint exact{nearestMultiple(meantRational(p.x), step), nearestMultiple(meantRational(p.y), step)};
    return {Point(toDouble(*exact.x), toDouble(*exact.y)), exact};
}

void PointEditor::setCountLimits(int minimum, int maximum)
{
    m_min = std::max(0, minimum);
    m_max = std::max(m_min, maximum);
}

int PointEditor::pick(const QPointF& screen) const
{
    if (!m_handlesVisible)
        return -1; // nothing to pick where nothing is drawn
    const ViewTransform& view = m_canvas->view();
    const double r = m_canvas->style().pickRadius();
    int best = -1;
    double bestD = r * r;
    for (std::size_t i = 0; i < m_edited.points.size(); ++i) {
        const QPointF d = view.toScreen(m_edited.points[i]) - screen;
        const double dd = d.x() * d.x() + d.y() * d.y();
        if (dd <= bestD) { // later points win ties: they are drawn on top
            bestD = dd;
            best = static_cast<int>(i);
        }
    }
    return best;
}

int PointEditor::insertionIndex(Point p) const
{
    const int n = static_cast<int>(m_edited.points.size());
    if (n < 2)
        return n;
    // Nearest edge of the polygon; beyond either end of it, the new point becomes the end.
    double best = std::numeric_limits<double>::infinity();
    int index = n;
    for (int i = 0; i + 1 < n; ++i) {
        const Point a = m_edited.points[i], b = m_edited.points[i + 1];
        const Point ab = b - a;
        const double len2 = dot(ab, ab);
        double s = len2 > 0 ? dot(p - a, ab) / len2 : 0.0;
        int candidate = i + 1;
        if (s < 0 && i == 0)
            candidate = 0;
        else if (s > 1 && i + 2 == n)
            candidate = n;
        s = std::clamp(s, 0.0, 1.0);
        const double d = distance(p, a + s * ab);
        if (d < best) {
            best = d;
            index = candidate;
        }
    }
    return index;
}

Rational PointEditor::nudgeStep(bool tenTimes) const
{
    const Rational step = m_snap ? meantRational(m_gridStep) : roundStepAtMost(kNudgePixels / m_canvas->view().scale()).exact();
    return tenTimes ? Rational(step * 10) : step;
}

void PointEditor::nudge(int dx, int dy, bool tenTimes)
{
    if (m_selected < 0 || m_selected >= static_cast<int>(m_edited.points.size()))
        return;
    finishDrag();
    const Rational step = nudgeStep(tenTimes);
    const auto i = static_cast<std::size_t>(m_selected);
    const Point from = m_edited.points[i];
    // The moved coordinate goes to the next multiple of the step; with snapping the other one
    // to the nearest, as a dragged point would. Exactly, from the coordinate's exact form (else
    // its double's value): -9/5 + 1/10 is -17/10, not -1.7000000000000002, and it stays -17/10.
    ExactPoint exact = m_edited.exactAt(i);
    const auto moved = [&](double v, ExactCoordinate& q, int sign) {
        if (sign == 0 && !m_snap)
            return v;
        const Rational meant = exactOr(q, v);
        q = sign == 0 ? nearestMultiple(meant, step) : nextMultiple(meant, step, sign);
        return toDouble(*q);
    };
    const Point to(moved(from.x, exact.x, dx), moved(from.y, exact.y, dy));
    if (!isFinite(to)) {
        emit message(tr("Refused: a coordinate must be a finite number."));
        return;
    }
    if (to == from)
        return; // too far from the origin for this step to change the double
    EditedPoints after = edited();
    after.set(i, to, exact);
    m_undo->push(new PointsCommand(this, edited(), after, tr("Move point %1").arg(m_selected), m_selected));
}

void PointEditor::showContextMenu(const QPointF& screen, const QPoint& global)
{
    QMenu menu(m_canvas);
    menu.setToolTipsVisible(true);
    const int hit = pick(screen);
    const auto [at, atExact] = snappedExactly(m_canvas->view().toModel(screen));
    if (hit >= 0) {
        menu.addAction(tr("Delete %1%2").arg(m_prefix).arg(hit), this, [this, hit] { removePoint(hit); });
    } else {
        menu.addAction(tr("Add a point here"), this,
                       [this, at = at, exact = atExact] { insertPoint(insertionIndex(at), at, exact); });
    }
    menu.addSeparator();
    QAction* snap = menu.addAction(tr("Snap to grid"));
    snap->setCheckable(true);
    snap->setChecked(m_snap);
    connect(snap, &QAction::toggled, this, [this](bool on) { setSnapEnabled(on); });
    QAction* labels = menu.addAction(tr("Show point labels"));
    labels->setCheckable(true);
    labels->setChecked(labelsShown());
    labels->setToolTip(
        tr("Past %1 points the labels are hidden and the handles small, unless this is on.").arg(kLabelledPointsUpTo));
    connect(labels, &QAction::toggled, this, [this](bool on) { chooseLabels(on); });
    menu.addAction(tr("Fit view"), m_canvas, &CurveCanvas::fitToContent);
    menu.exec(global);
}

bool PointEditor::eventFilter(QObject* watched, QEvent* event)
{
    // Hidden handles take no new gesture; a drag under way (hidden by an undo) ends as usual.
    if (watched != m_canvas || !m_enabled || (!m_handlesVisible && m_dragging < 0))
        return QObject::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::MouseButtonPress: {
        auto* e = static_cast<QMouseEvent*>(event);
        if (e->button() != Qt::LeftButton)
            return false;
        const int hit = pick(e->position());
        setSelected(hit);
        if (hit < 0)
            return false; // empty paper: the canvas pans
        m_dragging = hit;
        m_dragStart = edited();
        return true;
    }
    case QEvent::MouseMove: {
        auto* e = static_cast<QMouseEvent*>(event);
        if (m_dragging < 0) {
            const int hit = pick(e->position());
            m_canvas->setCursor(hit >= 0 ? Qt::OpenHandCursor : Qt::ArrowCursor);
            setHovered(hit);
            return false;
        }
        const auto [p, exact] = snappedExactly(m_canvas->view().toModel(e->position()));
        if (isFinite(p)) {
            m_edited.set(static_cast<std::size_t>(m_dragging), p, exact);
            m_canvas->update();
            emit pointsChanged();
        }
        return false; // the canvas still reports the cursor position
    }
    case QEvent::MouseButtonRelease: {
        auto* e = static_cast<QMouseEvent*>(event);
        if (e->button() != Qt::LeftButton || m_dragging < 0)
            return false;
        finishDrag(); // one undo step for the whole drag
        return true;
    }
    case QEvent::MouseButtonDblClick: {
        auto* e = static_cast<QMouseEvent*>(event);
        if (e->button() != Qt::LeftButton || pick(e->position()) >= 0)
            return false;
        const auto [p, exact] = snappedExactly(m_canvas->view().toModel(e->position()));
        insertPoint(insertionIndex(p), p, exact);
        return true;
    }
    case QEvent::Leave: setHovered(-1); return false;
    case QEvent::ContextMenu: {
        auto* e = static_cast<QContextMenuEvent*>(event);
        showContextMenu(e->pos(), e->globalPos());
        return true;
    }
    case QEvent::KeyPress: {
        auto* e = static_cast<QKeyEvent*>(event);
        const bool tenTimes = e->modifiers() & Qt::ShiftModifier;
        switch (e->key()) {
        case Qt::Key_Delete:
        case Qt::Key_Backspace: removePoint(m_selected); return true;
        case Qt::Key_Left: nudge(-1, 0, tenTimes); return m_selected >= 0;
        case Qt::Key_Right: nudge(1, 0, tenTimes); return m_selected >= 0;
        case Qt::Key_Up: nudge(0, 1, tenTimes); return m_selected >= 0;
        case Qt::Key_Down: nudge(0, -1, tenTimes); return m_selected >= 0;
        // ] and [ select the next and the previous point; Tab is left to move the focus on.
        case Qt::Key_BracketRight:
        case Qt::Key_BracketLeft:
            if (!m_edited.points.empty()) {
                const int n = static_cast<int>(m_edited.points.size());
                const int step = e->key() == Qt::Key_BracketRight ? 1 : n - 1;
                setSelected(m_selected < 0 ? (step == 1 ? 0 : n - 1) : (m_selected + step) % n);
                return true;
            }
            return false;
        default: return false;
        }
    }
    default: return QObject::eventFilter(watched, event);
    }
}

} // namespace granota::ui
