#pragma once
/// \file bspline_model.h
/// Everything the B-spline tab keeps besides its points (which the CurveTab's PointEditor
/// owns): the degree p, the knots (a preset, or the knots as edited), the weights, the
/// parameter u of de Boor's construction and what is shown. A plain value, so that an undo
/// step holds it before and after (ValueCommand) and the document saves it.
///
/// The knots and the weights belong to a number of points: the knots as edited are used while
/// there are n + p + 2 of them for the n + 1 points, the weights while there are n + 1. Adding or
/// removing a point (the editor's own undo step) makes the preset's knots and no weights current
/// again, and undoing it brings the edited ones back: nothing is lost and nothing is stale.

#include "core/curves/bsplines/bspline_curve.h"
#include "core/curves/bsplines/knot_vector.h"
#include "core/exact/rational.h"

#include <QJsonObject>
#include <QString>

#include <optional>
#include <vector>

namespace granota::ui {

struct BSplineModel {
    static constexpr int kMaxPoints = 1000; ///< docs/extreme-cases.md: a drag at 1000 points fits a 60 Hz frame (bench_gui.cpp)

    int degree = 3;                          ///< p, 1..kMaxBSplineDegree (less while there are fewer than p + 1 points)
    KnotPreset preset = KnotPreset::Clamped; ///< the knots unless edited ones fit
    std::vector<Rational> knots;             ///< the knots as edited (dragged, inserted); empty: the preset's
    std::vector<Rational> weights;           ///< w_i > 0 (NURBS); empty: polynomial
    Rational u{1, 2};                        ///< de Boor's construction at u (kept inside the domain)
    bool net = true;                         ///< de Boor's net at u, level by level
    bool bezierSegments = false;             ///< the curve's Bézier segments (the extraction) drawn
    bool cubicCircle = false;                ///< the cubic Bézier quarter circle drawn beside (its radial error)
    bool curvaturePlot = false;              ///< the plot under the canvas shows κ(s) instead of the basis functions
    bool homogeneousCurve = false;           ///< the inset of the curve in (wx, wy, w) (homogeneous_view.h)

    bool operator==(const BSplineModel& o) const;
    bool operator!=(const BSplineModel& o) const { return !(*this == o); }

    /// The degree in force for `pointCount` points: p, or n when there are fewer than p + 1.
    int degreeFor(int pointCount) const;
    /// The knots in force for `pointCount` points (see the file comment): the edited ones if
    /// they fit, else the preset's (clamped when the preset does not exist for the count:
    /// Bézier needs n = p).
    std::vector<Rational> knotsFor(int pointCount) const;
    /// The weights in force: the model's if there are `pointCount` of them, else none.
    std::vector<Rational> weightsFor(int pointCount) const;
    /// The curve of these points with the knots and weights in force (not checked).
    template <class S> BSplineCurve<S> curve(const std::vector<Vec2<S>>& points) const;
    /// u inside the domain of the knots in force.
    Rational uFor(int pointCount) const;
};

/// "clamped", "uniform", "bezier".
QString presetKey(KnotPreset preset);
std::optional<KnotPreset> presetFromKey(const QString& key);

/// The model as JSON ("degree", "knot_preset", "knots" and "weights" as exact texts "1/3", "u",
/// "net", "bezier_segments", "cubic_circle", "curvature_plot", "homogeneous_curve") and back. readModel checks the types and the ranges it can check
/// alone (the degree, the preset, each number); the tab checks the knots and the weights
/// against the points (checkBSpline). nullopt with `problem` (English, the key at fault) on bad data.
void writeModel(const BSplineModel& m, QJsonObject& json);
std::optional<BSplineModel> readModel(const QJsonObject& json, QString* problem);

template <class S> BSplineCurve<S> BSplineModel::curve(const std::vector<Vec2<S>>& points) const
{
    const int count = static_cast<int>(points.size());
    BSplineCurve<S> c;
    c.degree = degreeFor(count);
    c.points = points;
    for (const Rational& k : knotsFor(count)) {
        if constexpr (std::is_same_v<S, Rational>)
            c.knots.push_back(k);
        else
            c.knots.push_back(static_cast<S>(toDouble(k)));
    }
    for (const Rational& w : weightsFor(count)) {
        if constexpr (std::is_same_v<S, Rational>)
            c.weights.push_back(w);
        else
            c.weights.push_back(static_cast<S>(toDouble(w)));
    }
    return c;
}

} // namespace granota::ui
