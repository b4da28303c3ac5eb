#pragma once
/// \file bspline_examples.h
/// The B-spline tab's examples, as data (points, knots, weights) and without a widget: the
/// curve it opens on, Ex 2.2's Bézier curve as the B-spline with no interior knot, the uniform
/// cubic closed on Ex 2.13's points, the exact circle as a NURBS, and the conic presets: the
/// exact quarter circle (with the cubic Bézier approximation beside it), an ellipse, a parabola
/// and a hyperbola on one triangle, by their middle weight (conic_section.h). Their texts keep the
/// tab's translation context (granota::ui::BSplineTab).

#include "core/curves/bsplines/bspline_curve.h"
#include "ui/bsplines/bspline_model.h"

#include <QString>

#include <optional>
#include <vector>

namespace granota::ui {

struct BSplineExample {
    BSplineCurve<Rational> curve; ///< the points, degree, knots and weights, exactly
    BSplineModel model;           ///< the tab's model that shows it
};

enum class BSplineExampleId { Ex22Bezier, ClosedUniformCubic, Circle, QuarterCircle, Ellipse, Parabola, Hyperbola };

std::vector<BSplineExampleId> bsplineExampleIds();
QString bsplineExampleTitle(BSplineExampleId id);
/// nullopt only when chapter2.json lacks the example it reads (a build without resources).
std::optional<BSplineExample> bsplineExample(BSplineExampleId id);
/// The curve the tab opens on: a clamped cubic on six points (two interior knots, three spans), u = 1/2.
BSplineExample openingBSpline();

} // namespace granota::ui
