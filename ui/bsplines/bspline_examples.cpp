#include "ui/bsplines/bspline_examples.h"

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

} // namespace

std::vector<BSplineExampleId> bsplineExampleIds()
{
    return {BSplineExampleId::Ex22Bezier, BSplineExampleId::ClosedUniformCubic, BSplineExampleId::Circle};
}

QString bsplineExampleTitle(BSplineExampleId id)
{
    switch (id) {
    case BSplineExampleId::Ex22Bezier:
        return QCoreApplication::translate("granota::ui::BSplineTab", "Ex 2.2 as a B-spline (no interior knot)");
    case BSplineExampleId::ClosedUniformCubic:
        return QCoreApplication::translate("granota::ui::BSplineTab", "Uniform cubic, closed on Ex 2.13's points");
    case BSplineExampleId::Circle: return QCoreApplication::translate("granota::ui::BSplineTab", "The circle, exactly (NURBS)");
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
