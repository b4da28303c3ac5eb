#pragma once
/// \file hermite_handles.h
/// The Hermite family's tangent handles (issue 37): Def 2.8 with the student choosing every
/// tangent. The end of each point's tangent, q_i + m_i (m_i = p′ in the local s), is a
/// handle on the canvas; dragging it moves m_i by exactly the dragged amount in model units,
/// and the keyboard moves the selected point's tangent with Alt + arrows (Shift: ten times
/// more). It sits on the canvas in front of the point editor (an event filter installed after
/// it) and only reports: the tab makes each finished drag and each key one undo step.

#include "core/base/vec2.h"

#include <QObject>

#include <vector>

class QPainter;

namespace granota::ui {

class CurveCanvas;
class PointEditor;
class ViewTransform;
struct CanvasStyle;

class HermiteHandles : public QObject {
    Q_OBJECT
public:
    static constexpr double kKeyStep = 0.1; ///< model units per Alt + arrow (Shift: ×10)

    HermiteHandles(CurveCanvas* canvas, PointEditor* editor, QObject* parent = nullptr);

    /// Active only in the Hermite family; the points and their tangents as drawn.
    void setState(bool active, const std::vector<Point>& points, const std::vector<Point>& tangents);
    bool active() const { return m_active; }
    /// Where handle i is drawn, in model coordinates: q_i + m_i.
    Point handlePosition(int i) const;
    /// The handle squares (the arrows are drawn by family_drawing.h).
    void draw(QPainter& p, const ViewTransform& view, const CanvasStyle& style) const;

signals:
    /// During a drag: the tangent of point `index` is now `tangent` (no undo step yet).
    void tangentDragged(int index, granota::Point tangent);
    /// The drag ended; it started from `startTangent`.
    void dragFinished(int index, granota::Point startTangent);
    /// Alt + arrow: the selected point's tangent moved to `tangent`.
    void tangentNudged(int index, granota::Point tangent);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    int pick(QPointF screen) const;

    CurveCanvas* m_canvas = nullptr;
    PointEditor* m_editor = nullptr;
    bool m_active = false;
    std::vector<Point> m_points;
    std::vector<Point> m_tangents;
    int m_dragging = -1;
    Point m_dragStartTangent{0, 0};
    Point m_dragStartModel{0, 0};
};

} // namespace granota::ui
