#include "ui/common/bezier_curve_model.h"

#include "ui/common/point_editor.h"
#include "core/exact/exact_point.h"
#include "ui/common/value_command.h"

#include <QUndoStack>

#include <algorithm>
#include <cmath>

namespace granota::ui {

BezierCurveModel::BezierCurveModel(PointEditor* points, QUndoStack* undo, QObject* parent)
    : QObject(parent), m_points(points), m_undo(undo)
{
    connect(m_points, &PointEditor::pointsChanged, this, &BezierCurveModel::pointsChanged);
}

const std::vector<Point>& BezierCurveModel::points() const { return m_points->points(); }

void BezierCurveModel::setT(double t)
{
    if (!std::isfinite(t))
        return;
    t = std::clamp(t, 0.0, 1.0);
    if (t == m_t)
        return;
    m_t = t;
    emit tChanged(m_t);
}

void BezierCurveModel::pushT(double before, int mergeId, const QString& undoText)
{
    if (before == m_t)
        return;
    auto apply = [this](double v) {
        setT(v);
        emit documentChanged();
    };
    m_undo->push(
        new ValueCommand<double>(apply, before, m_t, undoText, mergeId, {/*dropWhenUnchanged=*/true, /*appliedAlready=*/true}));
}

void BezierCurveModel::loadCurve(const std::vector<Point>& points, const QString& undoText)
{
    loadPoints([&] { m_points->setPoints(points, undoText); }, undoText);
}

void BezierCurveModel::loadCurve(const std::vector<RPoint>& points, const QString& undoText)
{
    loadPoints([&] { m_points->setPoints(toDouble(points), exactForms(points), undoText); }, undoText);
}

void BezierCurveModel::loadPoints(const std::function<void()>& setPoints, const QString& undoText)
{
    emit curveLoading();
    m_undo->beginMacro(undoText);
    setPoints();
    const double before = m_t;
    setT(0.5);
    pushT(before, -1, undoText);
    m_undo->endMacro();
    emit curveLoaded();
}

} // namespace granota::ui
