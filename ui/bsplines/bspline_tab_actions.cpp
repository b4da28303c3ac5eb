// The B-spline tab's undoable edits: the degree, the knot preset, a knot moved, inserted or
// removed, the degree elevated, the weights, u and what is shown. Each is one undo step; the
// algorithms are the core's (core/curves/bsplines/), exact on the points' exact values.

#include "ui/bsplines/bspline_tab.h"

#include "core/curves/bsplines/bspline_degree_elevation.h"
#include "core/curves/bsplines/knot_insertion.h"
#include "core/curves/bsplines/knot_removal.h"
#include "core/exact/round_step.h"
#include "ui/bsplines/knot_ruler.h"
#include "ui/bsplines/weight_gesture.h"
#include "ui/common/curve_canvas.h"
#include "ui/common/number_text.h"
#include "ui/common/point_editor.h"
#include "ui/common/value_command.h"

#include <QUndoStack>

namespace granota::ui {

namespace {
constexpr int kWeightMergeIdBase = 0x42570000; ///< "BW" + the point's index: its weight's changes merge
constexpr int kRulerSteps = 200; ///< a dragged knot lands on a round step of at most 1/kRulerSteps of the knots' extent
} // namespace

std::vector<Rational> BSplineTab::knots() const { return m_model.knotsFor(static_cast<int>(m_editor->points().size())); }

Rational BSplineTab::rulerValue(double value) const
{
    const std::vector<Rational> k = knots();
    const double extent = k.empty() ? 1.0 : toDouble(k.back() - k.front());
    const Rational step = roundStepAtMost(extent > 0 ? extent / kRulerSteps : 1.0).exact();
    return nearestMultiple(exactRational(value), step);
}

void BSplineTab::changeModel(const BSplineModel& after, const QString& undoText, int mergeId)
{
    if (after == m_model)
        return;
    auto apply = [this](const BSplineModel& m) {
        applyModel(m);
        emit documentChanged();
    };
    m_undo->push(new ValueCommand<BSplineModel>(apply, m_model, after, undoText, mergeId, {/*dropWhenUnchanged=*/true}));
}

void BSplineTab::changeCurve(const BSplineCurve<Rational>& curve, const BSplineModel& after, const QString& undoText)
{
    setPlaying(false);
    std::vector<ExactPoint> exact;
    exact.reserve(curve.points.size());
    for (const RPoint& q : curve.points)
        exact.push_back({q.x, q.y});
    m_undo->beginMacro(undoText);
    if (toDouble(curve.points) != m_editor->points() || exact != m_editor->exactPoints())
        m_editor->setPoints(toDouble(curve.points), exact, undoText);
    changeModel(after, undoText);
    m_undo->endMacro();
}

bool BSplineTab::setDegree(int degree)
{
    const int count = static_cast<int>(m_editor->points().size());
    if (degree == m_model.degreeFor(count) && degree == m_model.degree)
        return true;
    if (degree < 1 || degree > kMaxBSplineDegree || degree > count - 1) {
        refuse(
            tr("A B-spline of degree %1 needs at least %2 control points; there are %3.").arg(degree).arg(degree + 1).arg(count));
        return false;
    }
    BSplineModel after = m_model;
    after.degree = degree;
    after.knots.clear(); // edited knots belong to the old degree: the preset's again
    if (after.preset == KnotPreset::Bezier && degree != count - 1)
        after.preset = KnotPreset::Clamped;
    changeModel(after, tr("Degree %1").arg(degree));
    return true;
}

bool BSplineTab::setPreset(KnotPreset preset)
{
    const int count = static_cast<int>(m_editor->points().size());
    BSplineModel after = m_model;
    after.preset = preset;
    after.knots.clear();
    if (preset == KnotPreset::Bezier) {
        // No interior knot: one piece of degree n, the Bézier curve of the points.
        if (count - 1 > kMaxBSplineDegree) {
            refuse(tr("The Bézier preset has degree n = number of points − 1, at most %1: remove points first.")
                       .arg(kMaxBSplineDegree));
            return false;
        }
        after.degree = count - 1;
    }
    changeModel(after, tr("Knots: %1").arg(presetKey(preset)));
    return true;
}

void BSplineTab::setU(const Rational& u, int mergeId)
{
    BSplineModel after = m_model;
    after.u = u;
    changeModel(after, tr("Move u"), mergeId);
}

bool BSplineTab::moveKnot(int index, const Rational& value, int mergeId)
{
    std::vector<Rational> k = knots();
    if (index < 0 || index >= static_cast<int>(k.size()))
        return false;
    // Bounded by its neighbours: it may meet them, never pass them.
    Rational v = value;
    if (index > 0 && v < k[static_cast<std::size_t>(index - 1)])
        v = k[static_cast<std::size_t>(index - 1)];
    if (index + 1 < static_cast<int>(k.size()) && v > k[static_cast<std::size_t>(index + 1)])
        v = k[static_cast<std::size_t>(index + 1)];
    if (v == k[static_cast<std::size_t>(index)])
        return true;
    k[static_cast<std::size_t>(index)] = v;
    BSplineModel after = m_model;
    after.knots = k;
    if (const Expected<void> ok = checkBSpline(after.curve(exactValues())); !ok) {
        refuse(tr("A knot can be repeated at most p = %1 times inside the domain and p + 1 times at an end, and the "
                  "domain [uₚ, uₙ₊₁] cannot be empty.")
                   .arg(m_scene.degree()));
        return false;
    }
    changeModel(after, tr("Move knot u%1").arg(subscriptDigits(index)), mergeId);
    return true;
}

bool BSplineTab::insertKnot(const Rational& value)
{
    if (!m_scene.valid())
        return false;
    const BSplineCurve<Rational>& c = m_scene.exact;
    const int p = c.degree;
    if (value < c.domainStart() || value > c.domainEnd()) {
        refuse(
            tr("A knot is inserted inside the domain [%1, %2].").arg(rationalText(c.domainStart()), rationalText(c.domainEnd())));
        return false;
    }
    if (!checkKnotInsertion(c, value, 1)) { // inside the domain, so the multiplicity is the fault
        const int m = knotMultiplicity(c.knots, value);
        refuse(tr("u = %1 is a knot of multiplicity %2 already: once more would break the curve (at most p = %3 times).")
                   .arg(rationalText(value))
                   .arg(m)
                   .arg(p));
        return false;
    }
    if (c.pointCount() + 1 > BSplineModel::kMaxPoints) {
        refuse(tr("A B-spline here has at most %1 control points.").arg(BSplineModel::kMaxPoints));
        return false;
    }
    const BSplineCurve<Rational> inserted = granota::insertKnot(c, value, 1);
    BSplineModel after = m_model;
    after.knots = inserted.knots;
    after.weights = inserted.weights;
    const std::vector<Point> before = m_editor->points();
    changeCurve(inserted, after, tr("Insert knot %1").arg(rationalText(value)));
    m_previousPolygon = before; // drawn under the new polygon until the next edit
    m_canvas->update();
    refuse(tr("Knot %1 inserted: %2 control points now, the same curve.").arg(rationalText(value)).arg(inserted.pointCount()));
    return true;
}

bool BSplineTab::removeKnot(int index)
{
    if (!m_scene.valid())
        return false;
    const BSplineCurve<Rational>& c = m_scene.exact;
    if (index < 0 || index >= static_cast<int>(c.knots.size()))
        return false;
    const Rational value = c.knots[static_cast<std::size_t>(index)];
    if (!(value > c.domainStart() && value < c.domainEnd())) {
        refuse(tr("Only a knot inside the domain can be removed; %1 is at its end or outside it.").arg(rationalText(value)));
        return false;
    }
    if (c.pointCount() - 1 < c.degree + 1) {
        refuse(tr("Removing a knot would leave fewer than p + 1 = %1 points.").arg(c.degree + 1));
        return false;
    }
    const KnotRemoval<Rational> r = granota::removeKnot(c, value, 1, 0.0);
    if (r.removed == 0) {
        refuse(tr("The curve needs the knot %1: removing it would change the curve.").arg(rationalText(value)));
        return false;
    }
    BSplineModel after = m_model;
    after.knots = r.curve.knots;
    after.weights = r.curve.weights;
    changeCurve(r.curve, after, tr("Remove knot %1").arg(rationalText(value)));
    refuse(tr("Knot %1 removed: the curve is exactly the same.").arg(rationalText(value)));
    return true;
}

bool BSplineTab::elevateDegree()
{
    if (!m_scene.valid())
        return false;
    const BSplineCurve<Rational>& c = m_scene.exact;
    if (c.degree >= kMaxBSplineDegree) {
        refuse(tr("The degree is at most %1.").arg(kMaxBSplineDegree));
        return false;
    }
    const BSplineCurve<Rational> raised = granota::elevateDegree(c);
    if (raised.pointCount() > BSplineModel::kMaxPoints) {
        refuse(tr("A B-spline here has at most %1 control points.").arg(BSplineModel::kMaxPoints));
        return false;
    }
    BSplineModel after = m_model;
    after.degree = raised.degree;
    after.knots = raised.knots;
    after.weights = raised.weights;
    if (after.preset == KnotPreset::Bezier && raised.degree != raised.pointCount() - 1)
        after.preset = KnotPreset::Clamped;
    changeCurve(raised, after, tr("Elevate the degree to %1").arg(raised.degree));
    return true;
}

bool BSplineTab::setWeights(const std::vector<Rational>& weights)
{
    const int count = static_cast<int>(m_editor->points().size());
    if (!weights.empty() && static_cast<int>(weights.size()) != count) {
        refuse(
            tr("%n weight(s) for %1 points: give one per point, or none.", nullptr, static_cast<int>(weights.size())).arg(count));
        return false;
    }
    for (const Rational& w : weights)
        if (!(w > 0)) {
            refuse(tr("A weight must be positive, not %1.").arg(rationalText(w)));
            return false;
        }
    // Weights all equal give the polynomial curve: kept as typed, the document says what was meant.
    BSplineModel after = m_model;
    after.weights = weights;
    changeModel(after, weights.empty() ? tr("No weights") : tr("Change the weights"));
    return true;
}

Rational BSplineTab::weightOf(int index) const
{
    const auto i = static_cast<std::size_t>(index);
    return m_model.weights.size() == m_editor->points().size() && i < m_model.weights.size() ? m_model.weights[i] : Rational(1);
}

bool BSplineTab::setWeight(int index, const Rational& weight)
{
    const int count = static_cast<int>(m_editor->points().size());
    if (index < 0 || index >= count)
        return false;
    if (!(weight > 0)) {
        refuse(tr("A weight must be positive, not %1.").arg(rationalText(weight)));
        return false;
    }
    if (weight == weightOf(index))
        return true; // as it is: a polynomial curve stays polynomial for a typed 1
    // As stepWeight does: a polynomial curve becomes rational with 1 at every other point.
    std::vector<Rational> weights = m_model.weightsFor(count);
    if (weights.empty())
        weights.assign(static_cast<std::size_t>(count), Rational(1));
    weights[static_cast<std::size_t>(index)] = weight;
    BSplineModel after = m_model;
    after.weights = weights;
    changeModel(after, tr("Change the weight of P%1").arg(index)); // no merge id: each typed weight is one undo step
    return true;
}

bool BSplineTab::stepWeight(int index, int steps)
{
    const int count = static_cast<int>(m_editor->points().size());
    if (index < 0 || index >= count || steps == 0)
        return false;
    std::vector<Rational> weights = m_model.weightsFor(count);
    if (weights.empty())
        weights.assign(static_cast<std::size_t>(count), Rational(1));
    Rational& w = weights[static_cast<std::size_t>(index)];
    const Rational stepped = steppedWeight(w, steps);
    if (stepped == w) {
        refuse((steps > 0 ? tr("The weight of P%1 is already %2, the largest the canvas reaches.")
                          : tr("The weight of P%1 is already %2, the smallest the canvas reaches."))
                   .arg(index)
                   .arg(rationalText(w)));
        return false;
    }
    w = stepped;
    BSplineModel after = m_model;
    after.weights = weights;
    changeModel(after, tr("Change the weight of P%1").arg(index), kWeightMergeIdBase + index % 0x10000);
    return true;
}

void BSplineTab::setNetVisible(bool on)
{
    BSplineModel after = m_model;
    after.net = on;
    changeModel(after, on ? tr("Show de Boor's net") : tr("Hide de Boor's net"));
}

void BSplineTab::setBezierSegmentsVisible(bool on)
{
    BSplineModel after = m_model;
    after.bezierSegments = on;
    changeModel(after, on ? tr("Show the Bézier segments") : tr("Hide the Bézier segments"));
}

void BSplineTab::setCubicCircleVisible(bool on)
{
    BSplineModel after = m_model;
    after.cubicCircle = on;
    changeModel(after, on ? tr("Show the cubic circle") : tr("Hide the cubic circle"));
}

void BSplineTab::setCurvaturePlot(bool on)
{
    BSplineModel after = m_model;
    after.curvaturePlot = on;
    changeModel(after, on ? tr("Plot the curvature") : tr("Plot the basis functions"));
}

void BSplineTab::setHomogeneousCurveVisible(bool on)
{
    BSplineModel after = m_model;
    after.homogeneousCurve = on;
    changeModel(after, on ? tr("Show the homogeneous curve") : tr("Hide the homogeneous curve"));
}

} // namespace granota::ui
