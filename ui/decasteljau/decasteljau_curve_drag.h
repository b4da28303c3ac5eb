#pragma once
/// \file decasteljau_curve_drag.h
/// Dragging the curve itself in the De Casteljau tab (beyond the thesis; docs/tabs.md):
/// hovering near the curve shows its closest point and that point's t (closest_point.h, the
/// global minimum over [0, 1]); pressing there and dragging molds the curve — the point at
/// that t follows the mouse by the smallest change of the control points (molding.h) — as
/// one undo step per drag. A control point under the mouse keeps priority: the point editor
/// drags it, as before. Empty paper away from the curve still pans.
/// The keyboard equivalent, on the canvas: Alt+arrows mold the curve's point at the tab's
/// current t by one nudge step (PointEditor::nudgeStep(), Shift ten times), a run of them one
/// undo step, as the arrows nudge the selected control point.

#include "core/base/vec2.h"
#include "core/curves/bezier/closest_point.h"
#include "ui/common/point_commands.h"

#include <QObject>
#include <QPointF>

#include <functional>
#include <optional>
#include <vector>

class QUndoStack;

namespace granota::ui {

class CurveCanvas;
class PointEditor;

class DeCasteljauCurveDrag : public QObject {
    Q_OBJECT
public:
    /// Installs itself on `canvas` after `editor` (so that it sees the mouse first and can
    /// leave the control points to the editor) and adds the hover marker as a layer.
    DeCasteljauCurveDrag(CurveCanvas* canvas, PointEditor* editor, QUndoStack* undoStack, QObject* parent = nullptr);

    /// The curve's closest point to the mouse, while the mouse is within kHoverPixels of the
    /// curve and not on a control point (or while molding: the point being dragged).
    const std::optional<ClosestPoint>& hover() const { return m_hover; }
    bool molding() const { return m_molding; }
    /// The t of the point being molded (valid while molding()).
    double moldT() const { return m_moldT; }

    /// Where the keyboard molds: the tab's current t.
    void setParameterSource(std::function<double()> t) { m_parameter = std::move(t); }
    /// Alt+arrow: moves c(t) by (dx, dy) nudge steps (each −1, 0 or 1; Shift: ten steps) by
    /// the least change of the control points (molding.h); successive ones are one undo step.
    void moldByKey(int dx, int dy, bool tenTimes);

    /// How near the curve (in pixels, × the presentation scale) the mouse must be.
    static constexpr double kHoverPixels = 9.0;

signals:
    /// A mold step changed the points (the tab recomputes lazily while molding()).
    void hoverChanged();
    /// What a keyboard mold did, or why it was refused (for the status bar).
    void message(const QString& text);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void updateHover(const QPointF& screen);
    void finishMold();

    CurveCanvas* m_canvas;
    PointEditor* m_editor;
    QUndoStack* m_undo;
    std::optional<ClosestPoint> m_hover;
    bool m_molding = false;
    double m_moldT = 0;
    EditedPoints m_moldStart; ///< the points when the mold began: one undo step per drag
    std::function<double()> m_parameter;
};

} // namespace granota::ui
