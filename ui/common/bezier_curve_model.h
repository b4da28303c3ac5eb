#pragma once
/// \file bezier_curve_model.h
/// The one Bézier curve the De Casteljau and Bernstein tabs share (docs/tabs.md, thesis §2.1):
/// its control points (kept and edited by the point editor of the De Casteljau tab's canvas),
/// the parameter t ∈ [0, 1] and the undo history both tabs write to. Each tab moves t or loads
/// a curve through the model and follows its signals; neither drives the other.

#include "core/base/vec2.h"
#include "core/exact/rational.h"

#include <QObject>
#include <functional>
#include <QString>

#include <vector>

class QUndoStack;

namespace granota::ui {

class PointEditor;

class BezierCurveModel : public QObject {
    Q_OBJECT
public:
    BezierCurveModel(PointEditor* points, QUndoStack* undo, QObject* parent = nullptr);

    /// The control points P_0…P_n (the editor's); pointsChanged() when they change.
    const std::vector<Point>& points() const;
    PointEditor* pointEditor() const { return m_points; }
    /// The history of both tabs.
    QUndoStack* undoStack() const { return m_undo; }

    double t() const { return m_t; }
    /// Makes t current, clamped to [0, 1] (a value that is not finite is ignored), without an
    /// undo step; tChanged() when it changes.
    void setT(double t);
    /// One undo step from `before` to the current t (none when they are equal); steps with the
    /// same `mergeId` (≥ 0) merge, as a slider drag does. Undoing emits documentChanged().
    void pushT(double before, int mergeId, const QString& undoText);
    /// Loads a curve: its points and t = 1/2 as one undo step named `undoText`, between
    /// curveLoading() and curveLoaded() (Ex 2.2, 2.3, and Ex 2.5, 2.6 from the Bernstein tab).
    void loadCurve(const std::vector<Point>& points, const QString& undoText);
    /// The same for points known exactly (a worked example's fractions): the editor keeps them as they are.
    void loadCurve(const std::vector<RPoint>& points, const QString& undoText);

signals:
    void tChanged(double t);
    void pointsChanged();
    void curveLoading();
    void curveLoaded();
    /// t changed by undo or redo: the document changed.
    void documentChanged();

private:
    /// One undo step: the points (`setPoints`) and t = 1/2, between curveLoading() and curveLoaded().
    void loadPoints(const std::function<void()>& setPoints, const QString& undoText);

    PointEditor* m_points;
    QUndoStack* m_undo;
    double m_t = 0.5;
};

} // namespace granota::ui
