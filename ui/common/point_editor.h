#pragma once
/// \file point_editor.h
/// The reusable control-point editor of the four curve tabs — Qt's HoverPoints idea, in
/// model coordinates behind the canvas's view transform. It owns the points, draws their
/// handles as a canvas layer and emits one signal, pointsChanged(), after every change.
///
/// Mouse: drag a handle (one undo step per drag); double-click empty paper to add a point
/// on the nearest edge of the polygon (or at an end); right-click for a menu.
/// Keys: Delete removes the selected point, arrows nudge it to the next multiple of a round
/// step (the grid step when snapping, else 1, 2 or 5 × 10^k worth at most kNudgePixels on
/// screen; Shift ×10), exactly (round_step.h), ] and [ select the next and the previous point (Tab moves the
/// focus on, as everywhere). Beside each double the editor keeps the coordinate's exact form
/// (exact_point.h): typed in the table (1/3, 0.1), loaded, or where a nudge, a snap or a drag
/// step put it; nullopt where a value has none. Every edit goes
/// through the QUndoStack given to the constructor; successive nudges of one point are one step.
///
/// Past kLabelledPointsUpTo points the handles are drawn small and unlabelled (the selected one
/// keeps its size and label, the one under the mouse its label) unless the user chooses "Show point labels" (the canvas's menu).

#include "core/base/vec2.h"
#include "core/exact/exact_point.h"
#include "core/exact/rational.h"
#include "ui/common/canvas_style.h"
#include "ui/common/point_commands.h"
#include "ui/common/view_transform.h"

#include <QColor>
#include <QObject>
#include <QPointF>
#include <QRectF>
#include <QString>

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

class QUndoStack;

namespace granota::ui {

class CurveCanvas;

class PointEditor : public QObject {
    Q_OBJECT
public:
    PointEditor(CurveCanvas* canvas, QUndoStack* undoStack, QObject* parent = nullptr);

    const std::vector<Point>& points() const { return m_edited.points; }
    /// The exact form of each point, index by index (nullopt coordinates have none), or empty
    /// when none has one (beyond kExactFormsUpTo points).
    const std::vector<ExactPoint>& exactPoints() const { return m_edited.exact; }
    /// Point i's exact form.
    const ExactPoint& exactAt(std::size_t i) const { return m_edited.exactAt(i); }
    /// Every point exactly, or nullopt when a coordinate has no exact form.
    std::optional<std::vector<RPoint>> allExactPoints() const { return allExact(m_edited.exact, m_edited.points.size()); }
    const EditedPoints& edited() const { return m_edited; }
    QUndoStack* undoStack() const { return m_undo; }
    CurveCanvas* canvas() const { return m_canvas; }

    /// Undoable edits (each one step; `undoText` names it in Edit ▸ Undo). Points given as
    /// doubles alone keep the small fractions they were written as (writtenExact()).
    void setPoints(const std::vector<Point>& points, const QString& undoText);
    void setPoints(const std::vector<Point>& points, const std::vector<ExactPoint>& exact, const QString& undoText);
    void movePoint(int index, Point to) { movePoint(index, to, writtenExact(to)); }
    void movePoint(int index, Point to, const ExactPoint& exact);
    void insertPoint(int index, Point p) { insertPoint(index, p, writtenExact(p)); }
    void insertPoint(int index, Point p, const ExactPoint& exact);
    void removePoint(int index);

    /// Replaces the points without an undo step (used by the undo commands themselves, and by
    /// loading a document). A drag in progress is dropped: its point may be gone.
    void applyPoints(const std::vector<Point>& points) { applyPoints(points, writtenExact(points)); }
    void applyPoints(const std::vector<Point>& points, const std::vector<ExactPoint>& exact);

    int selected() const { return m_selected; }
    /// A point is being dragged: views may defer costly refreshes until it is dropped.
    bool dragging() const { return m_dragging >= 0; }
    void setSelected(int index);

    bool snapEnabled() const { return m_snap; }
    void setSnapEnabled(bool on) { m_snap = on; }
    double gridStep() const { return m_gridStep; }
    void setGridStep(double step) { m_gridStep = step > 0 ? step : m_gridStep; }
    /// Rounds to the grid when snapping is on, else to the round step of one pixel.
    Point snapped(Point p) const { return snappedExactly(p).first; }
    /// The same with the exact multiple it is (nullopt coordinates for a point not finite).
    std::pair<Point, ExactPoint> snappedExactly(Point p) const;

    /// What one arrow key press moves a coordinate by: the grid step when snapping, else the
    /// largest round step (1, 2 or 5 × 10^k) of at most kNudgePixels at the current zoom;
    /// ten times that with `tenTimes` (Shift).
    Rational nudgeStep(bool tenTimes) const;
    static constexpr double kNudgePixels = 4.0;
    /// The arrow keys: moves the selected point's coordinate along (dx, dy), each −1, 0 or 1, to
    /// the next multiple of nudgeStep() in that direction, computed exactly from the fraction the
    /// coordinate stands for (meantRational), so that an exact point stays exact.
    void nudge(int dx, int dy, bool tenTimes);

    /// Past this many points, labels and full-size handles step aside unless chosen (see above).
    static constexpr std::size_t kLabelledPointsUpTo = 40;
    /// The user's choice of labels: nullopt for automatic (shown up to kLabelledPointsUpTo points).
    std::optional<bool> labelChoice() const { return m_labelChoice; }
    /// Makes a choice current, without an undo step (documents, the undo step itself).
    void setLabelChoice(std::optional<bool> choice);
    /// The user's "Show point labels": one undo step.
    void chooseLabels(bool shown);
    bool labelsShown() const;
    /// The labels are hidden because there are many points and the user chose nothing.
    bool labelsHiddenAutomatically() const;
    /// What the status bar says then ("200 points: labels hidden …"); empty otherwise.
    QString labelsHiddenNote() const;

    /// Deleting below `minimum` or adding above `maximum` is refused with a message.
    void setCountLimits(int minimum, int maximum);
    int minimumCount() const { return m_min; }
    int maximumCount() const { return m_max; }

    /// Labels drawn beside the handles: prefix + index (P0, P1, … or Q0, Q1, …); empty for none.
    void setLabelPrefix(const QString& prefix) { m_prefix = prefix; }
    QString labelPrefix() const { return m_prefix; }
    void setHandleColor(const QColor& c) { m_color = c; }
    /// Whether the editor draws the polygon through the points (control polygon).
    void setPolygonVisible(bool on) { m_polygonVisible = on; }
    bool polygonVisible() const { return m_polygonVisible; }
    void setEnabled(bool on) { m_enabled = on; }
    /// Whether the handles, their labels and the polygon are drawn at all (the thesis's Matlab
    /// `puntsvis`): hidden, the points are neither drawn nor picked by the mouse (nothing
    /// invisible is dragged, added or deleted on the canvas); the table still edits them.
    void setHandlesVisible(bool on);
    bool handlesVisible() const { return m_handlesVisible; }

    /// A handle as drawn, in widget pixels: its disc and its label's box (empty when unlabelled).
    struct Mark {
        std::size_t index = 0;
        QRectF handle;
        QRectF label;
        QPointF labelBaseline; ///< where the label's text starts, on its baseline
    };
    /// Every handle drawn in `view` (none while the handles are hidden), as the canvas shows it:
    /// what a key or an inset placed over the canvas keeps clear of.
    std::vector<Mark> marks(const ViewTransform& view, const CanvasStyle& style) const;

    /// The index of the handle within pick distance of a widget position, or −1 (always −1 while
    /// the handles are hidden).
    int pick(const QPointF& screen) const;
    /// Where double-clicking at model point `p` inserts a point: nearest polygon edge, or an end.
    int insertionIndex(Point p) const;

signals:
    void pointsChanged();
    void selectionChanged(int index);
    /// A refused edit (too few points, not a number…): the tab shows it in the status bar.
    void message(const QString& text);
    /// The labels were chosen on or off, or back to automatic (for the tab's document).
    void labelChoiceChanged();
    /// A point was inserted at `index` (or removed from there) by insertPoint()/removePoint().
    /// Emitted inside that edit's undo macro, after the points changed: a tab that keeps values
    /// per point pushes their change here, and it becomes part of the same undo step.
    void pointInserted(int index);
    void pointRemoved(int index);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// Before an edit of the editor's own (Delete, a nudge, an example, the table) while a
    /// point is dragged: the drag so far becomes its undo step, and the drag ends.
    void finishDrag();
    void showContextMenu(const QPointF& screen, const QPoint& global);
    /// The handle under the mouse (−1: none): labelled when the labels step aside.
    void setHovered(int index);

    CurveCanvas* m_canvas;
    QUndoStack* m_undo;
    EditedPoints m_edited;    ///< the points and their exact forms
    EditedPoints m_dragStart; ///< the points when a drag began: one undo step per drag
    int m_selected = -1;
    int m_dragging = -1;
    int m_hovered = -1;
    bool m_snap = false;
    double m_gridStep = 0.5;
    int m_min = 1;
    int m_max = 200;
    QString m_prefix = QStringLiteral("P");
    QColor m_color;
    bool m_polygonVisible = true;
    bool m_enabled = true;
    bool m_handlesVisible = true;
    std::optional<bool> m_labelChoice;
};

} // namespace granota::ui
