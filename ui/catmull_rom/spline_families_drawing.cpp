#include "ui/catmull_rom/spline_families_drawing.h"

#include "core/base/aabb.h"

#include "ui/catmull_rom/catmull_rom_drawing.h"
#include "ui/catmull_rom/tension_colour.h"
#include "ui/common/canvas_style.h"
#include "ui/common/view_transform.h"

#include <QCoreApplication>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace granota::ui {

namespace {

const QColor kSplineFamilyErrorColor(0xc6, 0x28, 0x28);
const QColor kPlaneSplineColour(0x33, 0x33, 0x33);


} // namespace

void drawPlaneSpline(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const PlaneSplineScene& scene)
{
    p.setBrush(Qt::NoBrush);
    if (!scene.catmullRom.bezier.empty()) {
        p.setPen(QPen(tensionColour(0.5), style.lineWidth(), Qt::DashLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPath(bezierSegmentsPath(view, scene.catmullRom.bezier));
    }
    if (!scene.spline.bezier.empty()) {
        p.setPen(QPen(kPlaneSplineColour, style.lineWidth() * 1.25, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPath(bezierSegmentsPath(view, scene.spline.bezier));
    }
}

CanvasLegend planeSplineLegend(const PlaneSplineSettings& settings, const PlaneSplineScene& scene)
{
    CanvasLegend legend;
    legend.alertColor = kSplineFamilyErrorColor;
    legend.entries.push_back({kPlaneSplineColour, scene.spline.error.isEmpty() ? Qt::SolidLine : Qt::NoPen,
                              PlaneSplineCurves::tr("C² spline, %1").arg(planeSplineEndsLabel(settings.ends))});
    if (settings.catmullRomToo)
        legend.entries.push_back({tensionColour(0.5), scene.catmullRom.error.isEmpty() ? Qt::DashLine : Qt::NoPen,
                                  PlaneSplineCurves::tr("dashed: Catmull-Rom τ = 1/2 (C¹)")});
    legend.note = !scene.spline.error.isEmpty() ? scene.spline.error : scene.catmullRom.error;
    return legend;
}

void drawFunctionData(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const FunctionDataSettings& settings,
                      const FunctionDataScene& scene)
{
    if (settings.shadeOvershoot) {
        p.setPen(Qt::NoPen);
        for (const auto& shape : scene.curves) {
            QColor fill = functionDataCurveColour(shape.curve);
            fill.setAlpha(kOvershootFillAlpha);
            p.setBrush(fill);
            for (const auto& region : shape.overshootRegions) {
                QPolygonF polygon;
                polygon.reserve(static_cast<int>(region.size()));
                for (const Point& q : region)
                    if (isFinite(q))
                        polygon << view.toScreen(q);
                p.drawPolygon(polygon, Qt::WindingFill);
            }
        }
    }
    p.setBrush(Qt::NoBrush);
    for (const auto& shape : scene.curves) {
        p.setPen(QPen(functionDataCurveColour(shape.curve), style.lineWidth(), Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.drawPath(bezierSegmentsPath(view, shape.bezier));
    }
}

CanvasLegend functionDataLegend(const FunctionDataScene& scene)
{
    CanvasLegend legend;
    legend.alertColor = kSplineFamilyErrorColor;
    for (const auto& shape : scene.curves)
        legend.entries.push_back({functionDataCurveColour(shape.curve), Qt::SolidLine, functionDataCurveLabel(shape.curve)});
    legend.note = scene.error;
    return legend;
}

std::vector<std::vector<Point>> planeSplineSamples(const PlaneSplineScene& scene)
{
    return {scene.spline.samples, scene.catmullRom.samples};
}

std::vector<std::vector<Point>> functionDataSamples(const FunctionDataScene& scene)
{
    std::vector<std::vector<Point>> out;
    for (const auto& shape : scene.curves)
        out.push_back(shape.samples);
    return out;
}

CanvasLegendObstacles splineFamilyLegendObstacles(const ViewTransform& view, const std::vector<std::vector<Point>>& samples)
{
    CanvasLegendObstacles avoid;
    for (const auto& curve : samples)
        for (const Point& q : curve)
            if (isFinite(q))
                avoid.points.push_back(view.toScreen(q));
    return avoid;
}

QRectF splineFamilyContentBounds(const std::vector<Point>& points, const std::vector<std::vector<Point>>& samples)
{
    const std::optional<Aabb> box = finiteBox(points);
    if (!box)
        return {-1, -1, 2, 2};
    // One box size around the points (at least a unit): a wild overshoot does not shrink the view.
    const double w = std::max(box->width(), 1e-9), h = std::max(box->height(), 1e-9);
    const double size = std::max(w, h);
    const QRectF limit(box->minX - size, box->minY - size, w + 2 * size, h + 2 * size);
    double x0 = box->minX, x1 = box->maxX, y0 = box->minY, y1 = box->maxY;
    for (const auto& curve : samples)
        for (const Point& q : curve)
            if (isFinite(q) && limit.contains(QPointF(q.x, q.y))) {
                x0 = std::min(x0, q.x);
                x1 = std::max(x1, q.x);
                y0 = std::min(y0, q.y);
                y1 = std::max(y1, q.y);
            }
    return QRectF(QPointF(x0, y0), QPointF(x1, y1));
}

} // namespace granota::ui
