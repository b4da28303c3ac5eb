#include "ui/bsplines/homogeneous_view.h"

#include "core/curves/bsplines/de_boor.h"
#include "ui/bsplines/bspline_drawing.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

/// The oblique projection: the planes w = const face on (x to the right, y up), w into the
/// depth along 40° up and to the right, so that the plane w = 1 shows the curve as the canvas
/// does, the origin O sits below and to the left of it, and parallel projection keeps the rays
/// from O straight.
constexpr double kDepthCos = 0.766044443118978; // cos 40°
constexpr double kDepthSin = 0.642787609686539; // sin 40°

QPointF oblique(const HomogeneousPoint& h, double depth)
{
    return {h.x + depth * kDepthCos * h.w, h.y + depth * kDepthSin * h.w};
}

} // namespace

HomogeneousView homogeneousView(const BSplineCurve<double>& c, int samplesPerSpan)
{
    HomogeneousView v;
    samplesPerSpan = std::max(samplesPerSpan, 2);
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        const double w = c.rational() ? c.weights[i] : 1.0;
        v.controlPoints.push_back({w * c.points[i].x, w * c.points[i].y, w});
    }
    const int p = c.degree, count = c.pointCount();
    for (int span = p; span < count; ++span) {
        const double a = c.knots[static_cast<std::size_t>(span)], b = c.knots[static_cast<std::size_t>(span + 1)];
        if (!(a < b))
            continue;
        for (int j = v.u.empty() ? 0 : 1; j < samplesPerSpan; ++j) {
            const double u = j + 1 == samplesPerSpan ? b : a + (b - a) * j / (samplesPerSpan - 1);
            // de Boor on (w x, w y, w): the table's last level is c(u) with its weight W(u).
            const DeBoorTable<double> t = deBoor(c, u);
            const double w = c.rational() ? t.weightLevels.back().front() : 1.0;
            v.u.push_back(u);
            v.curve.push_back({w * t.point().x, w * t.point().y, w});
            v.planeCurve.push_back(t.point());
        }
    }
    return v;
}

void drawHomogeneousView(QPainter& p, const QRectF& target, const HomogeneousView& view, const CanvasStyle& style,
                         const QString& title)
{
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(QPen(QColor(0x90, 0x90, 0x90), style.thinLine()));
    p.setBrush(QColor(255, 255, 255, 235));
    p.drawRect(target);
    p.setFont(style.labelFont());
    const QFontMetricsF fm(p.font());
    p.setPen(QColor(0x30, 0x30, 0x30));
    p.drawText(target.adjusted(6, 2, -6, 0), Qt::AlignTop | Qt::AlignLeft, title);
    if (view.empty()) {
        p.restore();
        return;
    }

    // The plane w = 1 over the points' extent, and the depth of w = 1 on the picture: about
    // that extent, so the rays fan out visibly.
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    const auto extend = [&](double x, double y) {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
    };
    for (const HomogeneousPoint& h : view.controlPoints)
        extend(h.x / h.w, h.y / h.w);
    for (const Point& q : view.planeCurve)
        extend(q.x, q.y);
    const double pad = 0.08 * std::max(x1 - x0, y1 - y0);
    x0 -= pad;
    x1 += pad;
    y0 -= pad;
    y1 += pad;
    const double depth = std::max({x1 - x0, y1 - y0, 1e-9}) * 0.8;
    const HomogeneousPoint corners[] = {{x0, y0, 1}, {x1, y0, 1}, {x1, y1, 1}, {x0, y1, 1}};

    // Fit everything drawn into the panel below the title.
    std::vector<QPointF> all = {oblique({0, 0, 0}, depth)};
    for (const auto& c : corners)
        all.push_back(oblique(c, depth));
    for (const auto& h : view.controlPoints)
        all.push_back(oblique(h, depth));
    for (const auto& h : view.curve)
        all.push_back(oblique(h, depth));
    double a0 = INFINITY, a1 = -INFINITY, b0 = INFINITY, b1 = -INFINITY;
    for (const QPointF& q : all)
        if (std::isfinite(q.x()) && std::isfinite(q.y())) {
            a0 = std::min(a0, q.x());
            a1 = std::max(a1, q.x());
            b0 = std::min(b0, q.y());
            b1 = std::max(b1, q.y());
        }
    const QRectF area = target.adjusted(10, fm.height() + 8, -10, -10);
    if (!(a1 > a0) || !(b1 > b0) || area.width() < 10 || area.height() < 10) {
        p.restore();
        return;
    }
    const double scale = std::min(area.width() / (a1 - a0), area.height() / (b1 - b0));
    const QPointF offset(area.center().x() - scale * (a0 + a1) / 2, area.center().y() + scale * (b0 + b1) / 2);
    const auto screen = [&](const HomogeneousPoint& h) {
        const QPointF q = oblique(h, depth);
        return QPointF(offset.x() + scale * q.x(), offset.y() - scale * q.y());
    };
    const auto path = [&](const std::vector<HomogeneousPoint>& points) {
        QPainterPath out;
        for (std::size_t i = 0; i < points.size(); ++i)
            i == 0 ? out.moveTo(screen(points[i])) : out.lineTo(screen(points[i]));
        return out;
    };

    // The plane w = 1.
    QPainterPath plane;
    plane.moveTo(screen(corners[0]));
    for (int i = 1; i < 4; ++i)
        plane.lineTo(screen(corners[i]));
    plane.closeSubpath();
    p.setPen(QPen(QColor(0x1f, 0x5f, 0xa8, 90), style.thinLine()));
    p.setBrush(QColor(0x1f, 0x5f, 0xa8, 28));
    p.drawPath(plane);
    p.setBrush(Qt::NoBrush);
    p.setPen(QColor(0x1f, 0x5f, 0xa8));
    p.drawText(screen(corners[2]) + QPointF(-fm.horizontalAdvance(QStringLiteral("w = 1")) - 4, fm.ascent() + 2),
               QStringLiteral("w = 1"));

    // The rays from the origin through Hᵢ and Pᵢ (whichever is farther ends the ray).
    const HomogeneousPoint origin{0, 0, 0};
    p.setPen(QPen(QColor(0x80, 0x80, 0x80), style.thinLine() * 0.8, Qt::DashLine));
    for (const HomogeneousPoint& h : view.controlPoints) {
        const HomogeneousPoint end = h.w >= 1 ? h : HomogeneousPoint{h.x / h.w, h.y / h.w, 1};
        p.drawLine(screen(origin), screen(end));
    }
    // The curve and its polygon on the plane.
    std::vector<HomogeneousPoint> polygon, curve;
    for (const HomogeneousPoint& h : view.controlPoints)
        polygon.push_back({h.x / h.w, h.y / h.w, 1});
    for (const Point& q : view.planeCurve)
        curve.push_back({q.x, q.y, 1});
    p.setPen(QPen(QColor(0x70, 0x70, 0x70), style.thinLine()));
    p.drawPath(path(polygon));
    p.setPen(QPen(style.curve, style.lineWidth() * 0.8));
    p.drawPath(path(curve));
    // The homogeneous polygon and the polynomial curve through it.
    p.setPen(QPen(kBSplineWeightColour, style.thinLine(), Qt::DashLine));
    p.drawPath(path(view.controlPoints));
    p.setPen(QPen(kBSplineWeightColour, style.lineWidth() * 0.8));
    p.drawPath(path(view.curve));
    const double r = style.handleRadius() * 0.45;
    p.setPen(Qt::NoPen);
    for (std::size_t i = 0; i < view.controlPoints.size(); ++i) {
        p.setBrush(kBSplineWeightColour);
        p.drawEllipse(screen(view.controlPoints[i]), r, r);
        p.setBrush(QColor(0x50, 0x50, 0x50));
        p.drawEllipse(screen(polygon[i]), r * 0.8, r * 0.8);
    }
    p.setBrush(Qt::black);
    p.drawEllipse(screen(origin), r, r);
    p.setPen(QColor(0x30, 0x30, 0x30));
    p.drawText(screen(origin) + QPointF(r + 2, -r), QStringLiteral("O"));
    p.restore();
}

} // namespace granota::ui
