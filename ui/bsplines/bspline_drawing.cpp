#include "ui/bsplines/bspline_drawing.h"

#include "ui/common/number_text.h"
#include "ui/files/tikz_writer.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <array>
#include <cmath>

namespace granota::ui {

namespace {

QPainterPath pathOf(const std::vector<Point>& points, const ViewTransform& view)
{
    QPainterPath path;
    bool first = true;
    for (const Point& q : points) {
        if (!isFinite(q))
            continue;
        if (first)
            path.moveTo(view.toScreen(q));
        else
            path.lineTo(view.toScreen(q));
        first = false;
    }
    return path;
}

void drawDots(QPainter& p, const std::vector<Point>& points, const ViewTransform& view, const QColor& colour, double radius,
              double outline)
{
    QPainterPath dots;
    for (const Point& q : points)
        if (isFinite(q))
            dots.addEllipse(view.toScreen(q), radius, radius);
    p.setPen(QPen(Qt::white, outline));
    p.setBrush(colour);
    p.drawPath(dots);
    p.setBrush(Qt::NoBrush);
}

} // namespace

void drawBSpline(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const BSplineModel& model,
                 const BSplineScene& scene, const std::vector<Point>& previousPolygon)
{
    p.setRenderHint(QPainter::Antialiasing);
    if (!previousPolygon.empty()) {
        p.setPen(QPen(kBSplineOldPolygonColour, style.thinLine() * 1.4, Qt::DashLine));
        p.drawPath(pathOf(previousPolygon, view));
        drawDots(p, previousPolygon, view, kBSplineOldPolygonColour, style.handleRadius() * 0.45, style.thinLine());
    }
    if (scene.cubicCircle.size() == 4) {
        const auto& b = scene.cubicCircle;
        QPainterPath path(view.toScreen(b[0]));
        path.cubicTo(view.toScreen(b[1]), view.toScreen(b[2]), view.toScreen(b[3]));
        p.setPen(QPen(kBSplineCubicCircleColour, style.lineWidth(), Qt::DashLine));
        p.drawPath(path);
    }
    if (!scene.valid())
        return;
    if (model.bezierSegments)
        for (std::size_t i = 0; i < scene.bezier.size(); ++i) {
            const QColor c = bsplineSegmentColour(static_cast<int>(i));
            p.setPen(QPen(c, style.thinLine() * 1.2, Qt::DashDotLine));
            p.drawPath(pathOf(scene.bezier[i], view));
            drawDots(p, scene.bezier[i], view, c, style.handleRadius() * 0.5, style.thinLine());
        }

    // Local support: the span's p + 1 points, ringed, and the polygon between them.
    const int p0 = scene.span() - scene.degree();
    if (model.net && p0 >= 0 && !scene.net.levels.empty()) {
        const std::vector<Point>& support = scene.net.levels.front();
        p.setPen(QPen(kBSplineSpanColour, style.lineWidth() * 2.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPath(pathOf(support, view));
        p.setPen(QPen(kBSplineSpanColour, style.lineWidth()));
        for (const Point& q : support)
            if (isFinite(q))
                p.drawEllipse(view.toScreen(q), style.handleRadius() * 1.7, style.handleRadius() * 1.7);
    }

    p.setPen(QPen(style.curve, style.lineWidth(), Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    if (!scene.cubics.empty()) {
        // The curve itself as cubic paths (SVG's C, PDF's curveto), not a polyline.
        QPainterPath path;
        for (const auto& b : scene.cubics) {
            if (path.isEmpty() || path.currentPosition() != view.toScreen(b[0]))
                path.moveTo(view.toScreen(b[0]));
            path.cubicTo(view.toScreen(b[1]), view.toScreen(b[2]), view.toScreen(b[3]));
        }
        p.drawPath(path);
    } else {
        p.drawPath(pathOf(scene.samples, view));
    }

    if (!model.net || scene.net.levels.empty())
        return;
    const int degree = scene.net.degree();
    for (int r = 1; r < degree; ++r) {
        const auto& level = scene.net.levels[static_cast<std::size_t>(r)];
        const QColor c = CanvasStyle::series(r);
        p.setPen(QPen(c, style.thinLine() * 1.4));
        p.drawPath(pathOf(level, view));
        drawDots(p, level, view, c, style.handleRadius() * 0.6, style.thinLine());
    }
    drawDots(p, {scene.net.point()}, view, CanvasStyle::series(degree), style.handleRadius() * 0.9, style.thinLine() * 1.5);
}

void drawBSplineWeights(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const std::vector<Point>& points,
                        const std::vector<Rational>& weights, int selected)
{
    if (weights.size() != points.size())
        return;
    p.setRenderHint(QPainter::Antialiasing);
    const double r0 = style.handleRadius();
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!isFinite(points[i]))
            continue;
        // w = 1 at 2.2 handle radii, ± 0.6 a doubling, kept between the handle and 6 radii.
        const double r = r0 * std::clamp(2.2 + 0.6 * std::log2(toDouble(weights[i])), 1.2, 6.0);
        p.setPen(QPen(kBSplineWeightColour, style.thinLine() * (static_cast<int>(i) == selected ? 1.8 : 1.0), Qt::DotLine));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(view.toScreen(points[i]), r, r);
    }
    if (selected < 0 || selected >= static_cast<int>(points.size()) || !isFinite(points[static_cast<std::size_t>(selected)]))
        return;
    const QPointF at = view.toScreen(points[static_cast<std::size_t>(selected)]);
    const QString text = QStringLiteral("w = %1").arg(rationalText(weights[static_cast<std::size_t>(selected)]));
    p.setFont(style.labelFont());
    const QFontMetricsF fm(p.font());
    const QRectF box(at + QPointF(r0 * 1.6, r0 * 1.6), QSizeF(fm.horizontalAdvance(text) + 6, fm.height() + 2));
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(255, 255, 255, 210));
    p.drawRoundedRect(box, 3, 3);
    p.setPen(kBSplineWeightColour);
    p.drawText(box, Qt::AlignCenter, text);
    p.setBrush(Qt::NoBrush);
}

void writeBSplineTikz(TikzWriter& w, const std::vector<Point>& points, const BSplineModel& model, const BSplineScene& scene)
{
    w.comment(QStringLiteral("B-spline of degree %1, knots %2").arg(scene.degree()).arg(scene.curve.knots.size()));
    w.polyline(points, CanvasStyle().polygon, 0.6);
    if (scene.valid()) {
        if (model.bezierSegments)
            for (std::size_t i = 0; i < scene.bezier.size(); ++i)
                w.polyline(scene.bezier[i], bsplineSegmentColour(static_cast<int>(i)), 0.6, Qt::DashDotLine);
        // Up to degree 3 each Bézier segment of a polynomial curve is a cubic exactly
        // (scene.cubics): TikZ's `.. controls ..` draws the curve itself.
        if (!scene.cubics.empty()) {
            w.bezierSegments(scene.cubics, CanvasStyle().curve, 1.2);
        } else {
            w.polyline(scene.samples, CanvasStyle().curve, 1.2);
        }
        if (model.net && !scene.net.levels.empty()) {
            const int degree = scene.net.degree();
            w.comment(QStringLiteral("de Boor's net at u = %1").arg(QString::fromStdString(toString(scene.u))));
            for (int r = 1; r < degree; ++r)
                w.polyline(scene.net.levels[static_cast<std::size_t>(r)], CanvasStyle::series(r), 0.8);
            w.point(scene.net.point(), CanvasStyle::series(degree), QStringLiteral("c(u)"));
        }
    }
    if (scene.cubicCircle.size() == 4)
        w.bezierSegments({{scene.cubicCircle[0], scene.cubicCircle[1], scene.cubicCircle[2], scene.cubicCircle[3]}},
                         kBSplineCubicCircleColour, 1.0, true);
    for (std::size_t i = 0; i < points.size(); ++i)
        w.point(points[i], CanvasStyle().handle, QStringLiteral("P_{%1}").arg(i));
}

} // namespace granota::ui
