#include "ui/bsplines/bspline_examples.h"

#include "core/curves/bsplines/circle_arcs.h"
#include "core/curves/bsplines/conic_section.h"
#include "core/io/worked_examples.h"

#include <QCoreApplication>

namespace granota::ui {

namespace {

BSplineExample withModel(BSplineCurve<Rational> c, KnotPreset preset, bool editedKnots)
{
    BSplineExample e;
    e.model.degree = c.degree;
    e.model.preset = preset;
    if (editedKnots)
        e.model.knots = c.knots;
    e.model.weights = c.weights;
    e.model.u = (c.domainStart() + c.domainEnd()) / 2;
    e.curve = std::move(c);
    return e;
}

RPoint rp(long x, long y) { return RPoint(Rational(x), Rational(y)); }

/// One rational quadratic Bézier piece (no interior knot) as the tab shows it.
BSplineExample conicPiece(std::vector<RPoint> points, std::vector<Rational> weights, bool cubicCircle)
{
    BSplineCurve<Rational> c;
    c.degree = 2;
    c.points = std::move(points);
    c.weights = std::move(weights);
    c.knots = presetKnots<Rational>(KnotPreset::Bezier, 3, 2);
    BSplineExample e = withModel(std::move(c), KnotPreset::Bezier, false);
    e.model.cubicCircle = cubicCircle;
    return e;
}

/// The conic on the triangle (0, 0), (2, 3), (4, 0) with middle weight w: its kind is w's
/// (ConicSection: an ellipse below 1, a parabola at 1, a hyperbola above).
BSplineExample conicOfWeight(const Rational& w)
{
    ConicSection<Rational> conic;
    conic.points = {rp(0, 0), rp(2, 3), rp(4, 0)};
    conic.weight = w;
    return conicPiece({conic.points.begin(), conic.points.end()}, {Rational(1), conic.weight, Rational(1)}, false);
}


} // namespace

std::vector<BSplineExampleId> bsplineExampleIds()
{
    return {BSplineExampleId::Ex22Bezier, BSplineExampleId::ClosedUniformCubic,
            BSplineExampleId::Circle,     BSplineExampleId::QuarterCircle,
            BSplineExampleId::Ellipse,    BSplineExampleId::Parabola,
            BSplineExampleId::Hyperbola};
}

QString bsplineExampleTitle(BSplineExampleId id)
{
    switch (id) {
    case BSplineExampleId::Ex22Bezier:
        return QCoreApplication::translate("granota::ui::BSplineTab", "Ex 2.2 as a B-spline (no interior knot)");
    case BSplineExampleId::ClosedUniformCubic:
        return QCoreApplication::translate("granota::ui::BSplineTab", "Closed uniform cubic (Ex 2.13)");
    case BSplineExampleId::Circle: return QCoreApplication::translate("granota::ui::BSplineTab", "The circle, exactly (NURBS)");
    case BSplineExampleId::QuarterCircle:
        return QCoreApplication::translate("granota::ui::BSplineTab", "Quarter circle: exact and cubic");
    case BSplineExampleId::Ellipse: return QCoreApplication::translate("granota::ui::BSplineTab", "Conic: an ellipse (w = 1/2)");
    case BSplineExampleId::Parabola: return QCoreApplication::translate("granota::ui::BSplineTab", "Conic: a parabola (w = 1)");
    case BSplineExampleId::Hyperbola: return QCoreApplication::translate("granota::ui::BSplineTab", "Conic: a hyperbola (w = 2)");
    }
    return {};
}

std::optional<BSplineExample> bsplineExample(BSplineExampleId id)
{
    BSplineCurve<Rational> c;
    switch (id) {
    case BSplineExampleId::Ex22Bezier: {
        // Degree n = 4 on p + 1 zeros and p + 1 ones: the B-spline is Ex 2.2's Bézier curve exactly.
        const WorkedExample* ex = findWorkedExample("2.2");
        if (!ex)
            return std::nullopt;
        c.points = ex->points;
        c.degree = static_cast<int>(c.points.size()) - 1;
        c.knots = presetKnots<Rational>(KnotPreset::Bezier, c.pointCount(), c.degree);
        return withModel(std::move(c), KnotPreset::Bezier, false);
    }
    case BSplineExampleId::ClosedUniformCubic: {
        // Ex 2.13's points q0…q4 (the thesis closes them with a cyclic Catmull-Rom curve, the
        // frog's outline of §4.12) and the first three again: on uniform knots the cubic closes
        // with C² joins everywhere, where the Catmull-Rom curve is only C¹.
        const WorkedExample* ex = findWorkedExample("2.13");
        if (!ex)
            return std::nullopt;
        c.points = ex->points;
        for (std::size_t i = 0; i < 3; ++i)
            c.points.push_back(ex->points[i]);
        c.degree = 3;
        c.knots = presetKnots<Rational>(KnotPreset::Uniform, c.pointCount(), c.degree);
        return withModel(std::move(c), KnotPreset::Uniform, false);
    }
    case BSplineExampleId::Circle: {
        // Four quadratic arcs with double knots. Each arc b0, b1, b2 (a corner of the square
        // between two points of the unit circle) with weights w0, w1, w2 is the circle when
        // w1²/(w0 w2) = cos²45° = 1/2 (the conic's shape factor; Farin, "Curves and Surfaces for
        // CAGD", §12.7): (1, 1, 2) is such a triple and gives the rational point (3/5, 4/5) at
        // u = 1/8, and each next arc's weights are the last one's times 2, so that the shared end
        // points carry one weight. Every rational u gives a rational point with x² + y² = 1.
        c.degree = 2;
        c.points = {rp(1, 0), rp(1, 1), rp(0, 1), rp(-1, 1), rp(-1, 0), rp(-1, -1), rp(0, -1), rp(1, -1), rp(1, 0)};
        c.weights = {Rational(1), Rational(1), Rational(2), Rational(2), Rational(4),
                     Rational(4), Rational(8), Rational(8), Rational(16)};
        c.knots = {Rational(0), Rational(0), Rational(0), frac(1, 4),  frac(1, 4),  frac(1, 2),
                   frac(1, 2),  frac(3, 4),  frac(3, 4),  Rational(1), Rational(1), Rational(1)};
        return withModel(std::move(c), KnotPreset::Clamped, true);
    }
    case BSplineExampleId::QuarterCircle: {
        // The quarter circle (1, 0), (1, 1), (0, 1) with the weights (1, 1, 2), exact (circle_arcs.h).
        const RationalBezierSegment<Rational> q = rationalQuarterCircle<Rational>();
        return conicPiece(q.points, q.weights, true);
    }
    case BSplineExampleId::Ellipse: return conicOfWeight(frac(1, 2));
    case BSplineExampleId::Parabola: return conicOfWeight(Rational(1));
    case BSplineExampleId::Hyperbola: return conicOfWeight(Rational(2));
    }
    return std::nullopt;
}

BSplineExample openingBSpline()
{
    BSplineCurve<Rational> c;
    c.degree = 3;
    c.points = {rp(0, 0), rp(1, 3), rp(3, 4), rp(5, 1), rp(7, 3), rp(8, 0)};
    c.knots = presetKnots<Rational>(KnotPreset::Clamped, c.pointCount(), c.degree);
    return withModel(std::move(c), KnotPreset::Clamped, false);
}

} // namespace granota::ui
