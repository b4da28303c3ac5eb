#include "ui/catmull_rom/family_drawing.h"

#include "ui/catmull_rom/catmull_rom_drawing.h"
#include "ui/catmull_rom/spline_families_drawing.h"
#include "ui/common/canvas_style.h"
#include "ui/common/view_transform.h"

#include <QLineF>
#include <QPainter>
#include <QPolygonF>

#include <cmath>

namespace granota::ui {

namespace {

/// An arrow from `from` to `to` (screen pixels) with its head at `to`; nothing when shorter
/// than a pixel (a zero tangent, T = 1, is drawn as no arrow).
void drawFamilyTangentArrow(QPainter& p, QPointF from, QPointF to, double headLength)
{
    const QLineF line(from, to);
    if (!(line.length() >= 1.0) || !std::isfinite(line.length()))
        return;
    p.drawLine(line);
    const QLineF back = QLineF(to, from).unitVector();
    const QPointF d = (back.p2() - back.p1()) * headLength;
    const QPointF n(-d.y() / 2, d.x() / 2);
    p.drawPolygon(QPolygonF{to, to + d + n, to + d - n});
}

} // namespace

void drawFamilyCurve(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const CatmullRomSettings& settings,
                     const CatmullRomScene& scene)
{
    const FamilyCurve& curve = scene.family;
    switch (settings.family) {
    case CurveFamily::CatmullRom: return; // drawCatmullRomCurves draws the τ curves
    case CurveFamily::Cardinal:
    case CurveFamily::KochanekBartels:
    case CurveFamily::Hermite: break;
    case CurveFamily::PlaneSpline: drawPlaneSpline(p, view, style, scene.planeSpline); return;
    case CurveFamily::FunctionData: drawFunctionData(p, view, style, settings.functionData, scene.functionData); return;
    }
    p.setPen(QPen(kFamilyCurveColor, style.lineWidth() * 1.25, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    drawBezierSegments(p, view, curve.bezier);
    if (!hasPointTangents(settings.family) || curve.tangents.size() != curve.points.size())
        return;
    // Def 2.8: the tangents the rule (or the student) chose, p′ in the local s, drawn from each
    // point: the outgoing one forwards, the incoming one ending at the point where it differs.
    const double head = 3.0 * style.lineWidth();
    for (std::size_t i = 0; i < curve.tangents.size(); ++i) {
        const Point q = curve.points[i];
        const KbTangents<double>& t = curve.tangents[i];
        const bool split = !(t.in == t.out);
        if (split) {
            p.setPen(QPen(kTangentInColor, style.thinLine() * 1.5));
            p.setBrush(kTangentInColor);
            drawFamilyTangentArrow(p, view.toScreen(q - t.in), view.toScreen(q), head);
        }
        p.setPen(QPen(kTangentOutColor, style.thinLine() * 1.5));
        p.setBrush(kTangentOutColor);
        drawFamilyTangentArrow(p, view.toScreen(q), view.toScreen(q + t.out), head);
    }
    p.setBrush(Qt::NoBrush);
}

} // namespace granota::ui
