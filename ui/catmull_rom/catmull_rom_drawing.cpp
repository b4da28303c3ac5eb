#include "ui/catmull_rom/catmull_rom_drawing.h"

#include "core/base/aabb.h"

#include "ui/catmull_rom/catmull_rom_report.h"
#include "ui/catmull_rom/family_drawing.h"
#include "ui/catmull_rom/spline_families_drawing.h"
#include "ui/catmull_rom/tension_colour.h"
#include "ui/common/canvas_style.h"
#include "ui/common/view_transform.h"

#include <QCoreApplication>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

const QColor kErrorColor(0xc6, 0x28, 0x28);

void drawPolyline(QPainter& p, const ViewTransform& view, const std::vector<Point>& points)
{
    if (points.size() < 2)
        return;
    QPolygonF poly;
    poly.reserve(static_cast<int>(points.size()));
    for (const Point& q : points)
        if (isFinite(q))
            poly << view.toScreen(q);
    p.drawPolyline(poly);
}

/// The rectangle holding the points, never empty (one point or coincident points get a unit box).
QRectF pointBounds(const std::vector<Point>& points)
{
    const std::optional<Aabb> box = finiteBox(points);
    if (!box)
        return {-1, -1, 2, 2};
    const double x0 = box->minX, y0 = box->minY;
    double w = box->width(), h = box->height();
    const double size = std::max({w, h, 0.0});
    const double pad = size > 0 ? 0.0
                                : std::max(1e-9, std::max(std::fabs(x0), std::fabs(y0)) * 0.1 + (x0 == 0 && y0 == 0 ? 1.0 : 0.0));
    if (w < size * 0.05 || w == 0)
        w = std::max(size * 0.05, pad);
    if (h < size * 0.05 || h == 0)
        h = std::max(size * 0.05, pad);
    const QPointF c((box->minX + box->maxX) / 2, (box->minY + box->maxY) / 2);
    return QRectF(c.x() - w / 2, c.y() - h / 2, w, h);
}

} // namespace

QPainterPath bezierSegmentsPath(const ViewTransform& view, const std::vector<BezierSegment<double>>& segments)
{
    QPainterPath path;
    bool open = false; // the path ends at the previous segment's end
    for (const auto& b : segments) {
        if (!isFinite(b[0]) || !isFinite(b[1]) || !isFinite(b[2]) || !isFinite(b[3])) {
            open = false;
            continue;
        }
        const QPointF start = view.toScreen(b[0]);
        // A segment starts where the previous one ends (up to rounding): one path, with its joins.
        if (!open || QLineF(path.currentPosition(), start).length() > 1e-6)
            path.moveTo(start);
        path.cubicTo(view.toScreen(b[1]), view.toScreen(b[2]), view.toScreen(b[3]));
        open = true;
    }
    return path;
}

void drawBezierSegments(QPainter& p, const ViewTransform& view, const std::vector<BezierSegment<double>>& segments)
{
    p.setBrush(Qt::NoBrush);
    p.drawPath(bezierSegmentsPath(view, segments));
}

void drawCatmullRomCurves(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const CatmullRomSettings& settings,
                          const CatmullRomScene& scene)
{
    if (!scene.bezier.empty()) {
        p.setPen(QPen(kCatmullRomBezierColor, style.lineWidth(), Qt::DashDotLine, Qt::RoundCap, Qt::RoundJoin));
        drawPolyline(p, view, scene.bezier);
    }
    if (!scene.splineBezier.empty()) {
        p.setPen(QPen(kCatmullRomSplineColor, style.lineWidth(), Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        drawBezierSegments(p, view, scene.splineBezier);
    }
    if (settings.family != CurveFamily::CatmullRom) {
        drawFamilyCurve(p, view, style, settings, scene); // the family selector's switch point (family_drawing.h)
        return;
    }
    if (!settings.catmullRom)
        return;
    for (std::size_t i = 0; i < scene.otherEnds.size(); ++i) {
        p.setPen(QPen(tensionColour(scene.otherEnds[i].tau), style.lineWidth() * 0.75, Qt::DashLine));
        drawBezierSegments(p, view, scene.otherEnds[i].bezier);
    }
    for (std::size_t i = 0; i < scene.curves.size(); ++i) {
        const bool selected = static_cast<int>(i) == settings.selectedTau;
        p.setPen(QPen(tensionColour(scene.curves[i].tau), style.lineWidth() * (selected ? 1.5 : 1.0), Qt::SolidLine, Qt::RoundCap,
                      Qt::RoundJoin));
        drawBezierSegments(p, view, scene.curves[i].bezier);
    }
}

CanvasLegend catmullRomLegend(const CatmullRomSettings& settings, const CatmullRomScene& scene)
{
    if (settings.family == CurveFamily::PlaneSpline)
        return planeSplineLegend(settings.planeSpline, scene.planeSpline);
    if (settings.family == CurveFamily::FunctionData)
        return functionDataLegend(scene.functionData);
    CanvasLegend legend;
    legend.alertColor = kErrorColor;
    const bool catmullRom = settings.catmullRom && settings.family == CurveFamily::CatmullRom;
    if (settings.family != CurveFamily::CatmullRom) {
        legend.entries.push_back(
            {kFamilyCurveColor, scene.family.error.isEmpty() ? Qt::SolidLine : Qt::NoPen, curveFamilyName(settings.family)});
        if (hasPointTangents(settings.family))
            legend.entries.push_back({kTangentOutColor, Qt::SolidLine,
                                      QCoreApplication::translate("granota::ui::CatmullRomTab", "tangent out (p′(0))")});
        if (settings.family == CurveFamily::KochanekBartels)
            legend.entries.push_back(
                {kTangentInColor, Qt::SolidLine,
                 QCoreApplication::translate("granota::ui::CatmullRomTab", "tangent in (p′(1)), where it differs")});
        if (!scene.family.error.isEmpty())
            legend.note = scene.family.error;
    }
    for (std::size_t i = 0; catmullRom && i < scene.curves.size(); ++i) {
        const auto& c = scene.curves[i];
        legend.entries.push_back({tensionColour(c.tau), c.error.isEmpty() ? Qt::SolidLine : Qt::NoPen,
                                  QStringLiteral("τ = %1").arg(tensionText(c.tau))});
    }
    if (catmullRom && !scene.otherEnds.empty())
        legend.entries.push_back({QColor(0x77, 0x77, 0x77), Qt::DashLine,
                                  QCoreApplication::translate("granota::ui::CatmullRomTab", "dashed: %1 ends")
                                      .arg(CatmullRomReport::endsName(comparedEnds(settings.ends)))});
    if (!scene.bezier.empty())
        legend.entries.push_back({kCatmullRomBezierColor, Qt::DashDotLine,
                                  QCoreApplication::translate("granota::ui::CatmullRomTab", "Bézier curve of the same points")});
    if (settings.spline)
        legend.entries.push_back(
            {kCatmullRomSplineColor, scene.spline.empty() ? Qt::NoPen : Qt::SolidLine,
             scene.spline.empty() ? QCoreApplication::translate("granota::ui::CatmullRomTab", "no cubic spline: x must increase")
                                  : QCoreApplication::translate("granota::ui::CatmullRomTab", "cubic spline C²")});
    for (const auto& c : scene.curves)
        if (catmullRom && !c.error.isEmpty())
            legend.note = c.error;
    return legend;
}

CanvasLegendObstacles catmullRomLegendObstacles(const ViewTransform& view, const CatmullRomSettings& settings,
                                                const CatmullRomScene& scene)
{
    CanvasLegendObstacles avoid;
    const auto samples = [&](const std::vector<Point>& points) {
        for (const Point& q : points)
            avoid.points.push_back(view.toScreen(q));
    };
    const bool catmullRom = settings.catmullRom && settings.family == CurveFamily::CatmullRom;
    for (std::size_t i = 0; catmullRom && i < scene.curves.size(); ++i)
        samples(scene.curves[i].samples);
    for (std::size_t i = 0; catmullRom && i < scene.otherEnds.size(); ++i)
        samples(scene.otherEnds[i].samples);
    samples(scene.bezier);
    samples(scene.spline);
    samples(scene.family.samples);
    for (const auto& curve : planeSplineSamples(scene.planeSpline))
        samples(curve);
    for (const auto& curve : functionDataSamples(scene.functionData))
        samples(curve);
    return avoid;
}

QRectF catmullRomContentBounds(const std::vector<Point>& points, const CatmullRomSettings& settings, const CatmullRomScene& scene)
{
    const QRectF box = pointBounds(points);
    // The curves overshoot the points for large |τ|; include them, up to one box size around.
    const QRectF limit = box.adjusted(-box.width(), -box.height(), box.width(), box.height());
    double x0 = box.left(), x1 = box.right(), y0 = box.top(), y1 = box.bottom();
    auto include = [&](const std::vector<Point>& samples) {
        for (const Point& p : samples)
            if (isFinite(p) && limit.contains(QPointF(p.x, p.y))) {
                x0 = std::min(x0, p.x);
                x1 = std::max(x1, p.x);
                y0 = std::min(y0, p.y);
                y1 = std::max(y1, p.y);
            }
    };
    const bool catmullRom = settings.catmullRom && settings.family == CurveFamily::CatmullRom;
    for (const auto& c : scene.curves)
        if (catmullRom)
            include(c.samples);
    for (const auto& c : scene.otherEnds)
        if (catmullRom)
            include(c.samples);
    include(scene.spline);
    include(scene.bezier);
    include(scene.family.samples);
    // The tangents' ends (the Hermite handles, the arrows' heads).
    for (std::size_t i = 0; i < scene.family.tangents.size() && i < scene.family.points.size(); ++i)
        include({scene.family.points[i] + scene.family.tangents[i].out, scene.family.points[i] - scene.family.tangents[i].in});
    for (const auto& curve : planeSplineSamples(scene.planeSpline))
        include(curve);
    for (const auto& curve : functionDataSamples(scene.functionData))
        include(curve);
    return QRectF(QPointF(x0, y0), QPointF(x1, y1));
}

} // namespace granota::ui
