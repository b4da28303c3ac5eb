#include "ui/decasteljau/decasteljau_scene_painter.h"

#include "ui/common/number_text.h"
#include "ui/common/view_transform.h"
#include "ui/decasteljau/decasteljau_construction_drawing.h"

#include <QCoreApplication>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace granota::ui {

namespace {

/// At most this many lines of levels (or of step curves) in the legend; the rest is one line.
constexpr int kMaxLegendLines = 6;

/// Rep_Bezier with desglossar: the curves of the first 1, 2, …, n + 1 points.
void drawStepCurvesLayer(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s)
{
    if (!s.view.stepByStep)
        return;
    p.setBrush(Qt::NoBrush);
    for (std::size_t k = 0; k < s.stepCurves.size(); ++k) {
        QColor c = CanvasStyle::series(static_cast<int>(k));
        c.setAlpha(170);
        p.setPen(QPen(c, style.lineWidth() * 0.75));
        if (s.stepCurves[k].size() == 1) {
            p.setBrush(c);
            p.drawEllipse(view.toScreen(s.stepCurves[k][0]), style.handleRadius() * 0.5, style.handleRadius() * 0.5);
            p.setBrush(Qt::NoBrush);
        } else {
            p.drawPath(polylinePath(s.stepCurves[k], view));
        }
    }
}

/// The curve: all of it lighter, the part traced so far (0..t) bold.
void drawTracedCurveLayer(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s)
{
    if (s.curve.size() < 2)
        return;
    p.setBrush(Qt::NoBrush);
    QColor light = style.curve;
    light.setAlpha(110);
    p.setPen(QPen(light, style.lineWidth(), Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    p.drawPath(polylinePath(s.curve, view));
    std::vector<Point> traced;
    const double part = static_cast<double>(s.curve.size() - 1);
    for (std::size_t j = 0; j < s.curve.size() && static_cast<double>(j) / part <= s.t; ++j)
        traced.push_back(s.curve[j]);
    if (!s.levels.levels.empty())
        traced.push_back(s.levels.point());
    p.setPen(QPen(style.curve, style.lineWidth() * 1.8, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    p.drawPath(polylinePath(traced, view));
}

/// The curvature comb (beyond the thesis), under the construction.
void drawCombLayer(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s)
{
    if (s.view.comb)
        drawCurvatureComb(p, view, style, s.comb);
}

/// The tight bounding box and the extrema of x (◇ on its left and right sides) and y (on top and bottom).
void drawBoundingBoxLayer(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s)
{
    if (!s.view.boundingBox || s.points.empty())
        return;
    const Aabb& box = s.features.bbox;
    if (!isFinite(box.minCorner()) || !isFinite(box.maxCorner()))
        return;
    p.setPen(QPen(kDeCasteljauBox, style.thinLine() * 1.3, Qt::DashDotLine));
    p.setBrush(Qt::NoBrush);
    p.drawRect(QRectF(view.toScreen(box.minCorner()), view.toScreen(box.maxCorner())).normalized());
    // Large, with a dark edge of the canvas's line width: a white 1 px edge round a slate
    // diamond of 9 px was lost on a projector (issue 34).
    const double r = style.handleRadius();
    p.setPen(QPen(kDeCasteljauExtremumEdge, style.lineWidth(), Qt::SolidLine, Qt::SquareCap, Qt::MiterJoin));
    p.setBrush(kDeCasteljauBox);
    const auto& points = s.points;
    for (const auto* list : {&s.features.extremaX, &s.features.extremaY})
        for (double t : *list) {
            const QPointF c = view.toScreen(deCasteljauPoint(points, t));
            QPolygonF diamond;
            diamond << c + QPointF(0, -r) << c + QPointF(r, 0) << c + QPointF(0, r) << c + QPointF(-r, 0);
            p.drawPolygon(diamond);
        }
}

/// The construction of Def 2.4: every level r ≥ 1, points and segments, one colour each.
void drawConstructionLayer(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s)
{
    if (s.view.construction && s.levels.levels.size() >= 2)
        drawDeCasteljauConstruction(p, view, style, s.levels);
}

/// Split at t: the halves' control polygons are the triangle's two edges. Drawn over the
/// construction, on a white halo, with hollow squares larger than the level's dots: both
/// the halves and the construction under them stay visible.
void drawSplitLayer(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s)
{
    if (!s.view.split || s.levels.levels.size() < 2)
        return;
    const std::vector<Point> halves[2] = {s.levels.leftHalf(), s.levels.rightHalf()};
    p.setBrush(Qt::NoBrush);
    for (int h = 0; h < 2; ++h) {
        const QPainterPath path = polylinePath(halves[h], view);
        p.setPen(QPen(QColor(255, 255, 255, 200), style.lineWidth() * 2.6, Qt::SolidLine, Qt::RoundCap));
        p.drawPath(path);
        p.setPen(QPen(kDeCasteljauSplit[h], style.lineWidth() * 1.3, Qt::DashLine, Qt::RoundCap));
        p.drawPath(path);
        p.setPen(QPen(kDeCasteljauSplit[h], style.thinLine() * 2));
        const double side = deCasteljauSplitSquareSide(style);
        for (const Point& q : halves[h])
            p.drawRect(QRectF(view.toScreen(q) - QPointF(side, side) / 2, QSizeF(side, side)));
    }
}

/// Inflections (hollow circles) and cusps (crosses).
void drawFeaturesLayer(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s)
{
    if (!s.view.inflections || s.points.empty())
        return;
    const auto& points = s.points;
    const double r = style.handleRadius() * 1.1;
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(kDeCasteljauInflection, style.thinLine() * 2.2));
    for (double t : s.features.inflections)
        p.drawEllipse(view.toScreen(deCasteljauPoint(points, t)), r, r);
    p.setPen(QPen(kDeCasteljauCusp, style.thinLine() * 2.5, Qt::SolidLine, Qt::RoundCap));
    for (double t : s.features.cusps) {
        const QPointF c = view.toScreen(deCasteljauPoint(points, t));
        p.drawLine(c + QPointF(-r, -r), c + QPointF(r, r));
        p.drawLine(c + QPointF(-r, r), c + QPointF(r, -r));
    }
}

/// The osculating circle at t: centre c(t) + N/κ, radius 1/|κ| (none where κ is 0 or undefined).
void drawOsculatingCircleLayer(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s)
{
    if (!s.view.osculatingCircle || !s.curvature.center || !s.curvature.radius)
        return;
    const QPointF c = view.toScreen(*s.curvature.center);
    const double r = *s.curvature.radius * view.scale();
    if (!std::isfinite(r) || !std::isfinite(c.x()) || !std::isfinite(c.y()) || r > 1e7)
        return; // nearly straight: a circle larger than any screen
    p.setPen(QPen(kDeCasteljauCircle, style.lineWidth() * 0.8));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(c, r, r);
    p.setPen(QPen(kDeCasteljauCircle, style.thinLine(), Qt::DotLine));
    p.drawLine(c, view.toScreen(s.curvature.point));
    p.setPen(QPen(Qt::white, style.thinLine()));
    p.setBrush(kDeCasteljauCircle);
    p.drawEllipse(c, style.handleRadius() * 0.5, style.handleRadius() * 0.5);
}

/// The unit normal N(t), left of the tangent, drawn as long as the tangent's arrow c′(t)/n.
void drawNormalLayer(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s)
{
    if (!s.view.normal || !s.curvature.normal || s.levels.degree() < 1)
        return;
    const double length = std::hypot(s.curvature.tangent.x, s.curvature.tangent.y) / s.levels.degree();
    const Point c = s.curvature.point, d = length * *s.curvature.normal;
    if (!isFinite(c) || !isFinite(d))
        return;
    p.setPen(QPen(kDeCasteljauNormal, style.lineWidth()));
    const QPointF from = view.toScreen(c), to = view.toScreen(c + d);
    drawDeCasteljauArrow(p, from, to, 11.0 * style.scale);
    p.setFont(style.labelFont());
    p.setPen(kDeCasteljauNormal);
    const QFontMetricsF fm(p.font());
    const QPointF dir = to - from;
    const double len = std::hypot(dir.x(), dir.y());
    QPointF at = to + (len > 0 ? dir / len * (8.0 * style.scale) : QPointF()) + QPointF(0, fm.ascent() / 2);
    if (dir.x() < 0)
        at.rx() -= fm.horizontalAdvance(QStringLiteral("N(t)"));
    p.drawText(at, QStringLiteral("N(t)"));
}

/// The tangent c′(t), from the last level but one.
void drawTangentLayer(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s)
{
    if (!s.view.tangent || s.levels.degree() < 1)
        return;
    // Drawn as c′(t)/n = P_1^{n−1}(t) − P_0^{n−1}(t): the last segment of the construction,
    // so the arrow stays on screen (c′ itself is n times longer).
    const int n = s.levels.degree();
    const Point c = s.levels.point(), d = (1.0 / n) * s.levels.tangent();
    if (!isFinite(c) || !isFinite(d))
        return;
    const QColor colour = kDeCasteljauTangent;
    p.setPen(QPen(colour, style.lineWidth()));
    const QPointF from = view.toScreen(c), to = view.toScreen(c + d);
    drawDeCasteljauArrow(p, from, to, 11.0 * style.scale);
    p.setFont(style.labelFont());
    p.setPen(colour);
    // The label beyond the arrow's tip, on the side the arrow points to.
    const QString label = n == 1 ? QStringLiteral("c′(t)") : QStringLiteral("c′(t)/%1").arg(n);
    const QPointF dir = to - from;
    const double len = std::hypot(dir.x(), dir.y());
    const QPointF ahead = len > 0 ? dir / len * (8.0 * style.scale) : QPointF();
    const QFontMetricsF fm(p.font());
    QPointF at = to + ahead + QPointF(0, fm.ascent() / 2);
    if (dir.x() < 0)
        at.rx() -= fm.horizontalAdvance(label);
    p.drawText(at, label);
}

/// c(t) itself, prominent.
void drawCurvePointLayer(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s)
{
    if (s.levels.levels.empty() || !isFinite(s.levels.point()))
        return;
    const QPointF at = view.toScreen(s.levels.point());
    const double r = style.handleRadius() * 1.25;
    p.setPen(QPen(Qt::white, style.thinLine() * 2));
    p.setBrush(style.curve);
    p.drawEllipse(at, r, r);
    p.setPen(style.curve);
    QFont f = style.labelFont();
    f.setBold(true);
    p.setFont(f);
    p.drawText(at + QPointF(r + 4 * style.scale, r + 12 * style.scale), QStringLiteral("c(t)"));
}

} // namespace

void drawDeCasteljauArrow(QPainter& p, const QPointF& from, const QPointF& to, double head)
{
    p.drawLine(from, to);
    const QPointF d = to - from;
    const double len = std::hypot(d.x(), d.y());
    if (len < 1e-9)
        return;
    const QPointF u = d / len, n(-u.y(), u.x());
    QPolygonF tip;
    tip << to << to - head * u + 0.45 * head * n << to - head * u - 0.45 * head * n;
    p.setBrush(p.pen().color());
    p.drawPolygon(tip);
}


const std::vector<DeCasteljauLayer>& deCasteljauLayers()
{
    static const std::vector<DeCasteljauLayer> layers = {drawStepCurvesLayer,  drawTracedCurveLayer,      drawCombLayer,
                                                         drawBoundingBoxLayer, drawConstructionLayer,     drawSplitLayer,
                                                         drawFeaturesLayer,    drawOsculatingCircleLayer, drawNormalLayer,
                                                         drawTangentLayer,     drawCurvePointLayer};
    return layers;
}

double deCasteljauSplitSquareSide(const CanvasStyle& style) { return style.handleRadius() * 1.2 + 6 * style.scale; }

CanvasLegend deCasteljauLegend(const DeCasteljauScene& s)
{
    CanvasLegend legend;
    const int n = s.levels.degree();
    const auto lines = [&legend](int first, int last, const std::function<QString(int)>& text) {
        for (int r = first; r <= last; ++r) {
            if (r - first == kMaxLegendLines - 1 && r < last) {
                legend.entries.push_back(
                    {CanvasStyle::series(r), Qt::DotLine,
                     QCoreApplication::translate("granota::ui::DeCasteljauTab", "… %1 more, one colour each").arg(last - r + 1)});
                return;
            }
            legend.entries.push_back({CanvasStyle::series(r), Qt::SolidLine, text(r)});
        }
    };
    if (s.view.construction && n >= 2)
        lines(1, n - 1, [](int r) {
            return QCoreApplication::translate("granota::ui::DeCasteljauTab", "level %1: the points %2(t)")
                .arg(r)
                .arg(QStringLiteral("Pᵢ") + superscriptDigits(r));
        });
    if (s.view.stepByStep && !s.stepCurves.empty())
        lines(0, static_cast<int>(s.stepCurves.size()) - 1, [](int k) {
            return k == 0 ? QCoreApplication::translate("granota::ui::DeCasteljauTab", "the point P₀ alone")
                          : QCoreApplication::translate("granota::ui::DeCasteljauTab", "the curve of P₀…P%1")
                                .arg(subscriptDigits(k));
        });
    if (s.view.split && n >= 1) {
        legend.entries.push_back({kDeCasteljauSplit[0], Qt::DashLine,
                                  QCoreApplication::translate("granota::ui::DeCasteljauTab", "polygon of the half on [0, t]")});
        legend.entries.push_back({kDeCasteljauSplit[1], Qt::DashLine,
                                  QCoreApplication::translate("granota::ui::DeCasteljauTab", "polygon of the half on [t, 1]")});
    }
    if (s.view.tangent && n >= 1)
        legend.entries.push_back({kDeCasteljauTangent, Qt::SolidLine,
                                  n == 1
                                      ? QCoreApplication::translate("granota::ui::DeCasteljauTab", "tangent c′(t)")
                                      : QCoreApplication::translate("granota::ui::DeCasteljauTab", "tangent c′(t)/%1").arg(n)});
    if (s.view.normal && n >= 1)
        legend.entries.push_back(
            s.curvature.normal
                ? CanvasLegendEntry{kDeCasteljauNormal, Qt::SolidLine,
                                    QCoreApplication::translate("granota::ui::DeCasteljauTab", "unit normal N(t)")}
                : CanvasLegendEntry{kDeCasteljauNormal, Qt::NoPen,
                                    QCoreApplication::translate("granota::ui::DeCasteljauTab", "no normal: c′(t) = 0")});
    if (s.view.osculatingCircle && n >= 1) {
        if (s.curvature.radius)
            legend.entries.push_back(
                {kDeCasteljauCircle, Qt::SolidLine,
                 QCoreApplication::translate("granota::ui::DeCasteljauTab", "osculating circle, r = 1/|κ| = %1")
                     .arg(panelNumber(*s.curvature.radius))});
        else if (s.curvature.curvature)
            legend.entries.push_back(
                {kDeCasteljauCircle, Qt::NoPen,
                 QCoreApplication::translate("granota::ui::DeCasteljauTab", "no osculating circle: κ(t) = 0")});
        else
            legend.entries.push_back(
                {kDeCasteljauCircle, Qt::NoPen,
                 QCoreApplication::translate("granota::ui::DeCasteljauTab", "no osculating circle: κ undefined")});
    }
    if (s.view.comb && n >= 1 && !s.comb.empty())
        legend.entries.push_back({curvatureCombColor(), Qt::SolidLine,
                                  QCoreApplication::translate("granota::ui::DeCasteljauTab", "curvature comb: teeth |κ| × %1")
                                      .arg(panelNumber(s.comb.scale))});
    if (s.view.boundingBox && n >= 0)
        legend.entries.push_back(
            {kDeCasteljauBox, Qt::DashDotLine,
             QCoreApplication::translate("granota::ui::DeCasteljauTab", "bounding box, ◆ extrema of x and y")});
    if (s.view.inflections && n >= 1) {
        legend.entries.push_back({kDeCasteljauInflection, Qt::SolidLine,
                                  QCoreApplication::translate("granota::ui::DeCasteljauTab", "○ inflections: %1 · × cusps: %2")
                                      .arg(s.features.inflections.size())
                                      .arg(s.features.cusps.size())});
    }
    return legend;
}

CanvasLegendBox deCasteljauLegendBox(const DeCasteljauScene& s, const QString& labelPrefix, const ViewTransform& view,
                                     const CanvasStyle& style)
{
    CanvasLegendObstacles avoid = deCasteljauObstacles(s, labelPrefix, view, style);
    if (const QRectF inset = deCasteljauHodographInset(s, labelPrefix, view, style); !inset.isEmpty())
        avoid.keepClear.push_back(inset);
    return canvasLegendRect(view, style, deCasteljauLegend(s), avoid);
}

CanvasLegendObstacles deCasteljauObstacles(const DeCasteljauScene& s, const QString& labelPrefix, const ViewTransform& view,
                                           const CanvasStyle& style)
{
    CanvasLegendObstacles avoid;
    for (const Point& q : s.curve)
        avoid.points.push_back(view.toScreen(q));
    if (s.view.construction)
        for (const auto& level : s.levels.levels)
            for (const Point& q : level)
                avoid.points.push_back(view.toScreen(q));
    // The handles and their labels (as the point editor draws them), c(t) and its label, the inset.
    const QFontMetricsF fm(style.labelFont());
    const double r = style.handleRadius() * 1.3;
    const auto& points = s.points;
    const auto marked = [&](const Point& q, const QString& label) {
        const QPointF s = view.toScreen(q);
        const QRectF handle(s - QPointF(r, r), QSizeF(2 * r, 2 * r));
        const QRectF text(s.x() + r + 3 * style.scale, s.y() - r - fm.ascent(), fm.horizontalAdvance(label), fm.height());
        avoid.keepClear.push_back(handle.united(text));
    };
    for (std::size_t i = 0; s.view.controlPoints && i < points.size(); ++i)
        marked(points[i], labelPrefix + QString::number(i));
    if (!s.levels.levels.empty()) {
        // c(t)'s label is below right of its dot.
        const QPointF at = view.toScreen(s.levels.point());
        avoid.keepClear.push_back(
            QRectF(at - QPointF(r, r),
                   QSizeF(2 * r + 4 * style.scale + fm.horizontalAdvance(QStringLiteral("c(t)")), 2 * r + 12 * style.scale)));
    }
    return avoid;
}

QRectF deCasteljauHodographInset(const DeCasteljauScene& s, const QString& labelPrefix, const ViewTransform& view,
                                 const CanvasStyle& style)
{
    if (!s.view.hodograph || s.hodoLevels.levels.empty())
        return {};
    const QRectF viewport = view.viewport();
    const double margin = 8 * style.scale;
    // A corner of the canvas, small enough to leave the curve its room (in presentation mode
    // too): the one that covers least of what is drawn, as the key chooses its place.
    const double w = std::min(viewport.width() * 0.3, 260.0 * style.scale);
    const double h = std::min(w * 0.75, viewport.height() * 0.32);
    const double left = viewport.left() + margin, right = viewport.right() - margin - w;
    const double top = viewport.top() + margin, bottom = viewport.bottom() - margin - h;
    const CanvasLegendObstacles avoid = deCasteljauObstacles(s, labelPrefix, view, style);
    QRectF best;
    double least = std::numeric_limits<double>::infinity();
    for (const QPointF& corner : {QPointF(right, bottom), QPointF(left, bottom), QPointF(right, top), QPointF(left, top)}) {
        const QRectF box(corner, QSizeF(w, h));
        if (const double cost = canvasCoverCost(box, avoid); cost < least) {
            least = cost;
            best = box;
        }
    }
    return best;
}

void drawDeCasteljauHodographInset(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const DeCasteljauScene& s,
                                   const QString& labelPrefix)
{
    const QRectF inset = deCasteljauHodographInset(s, labelPrefix, view, style);
    if (inset.isEmpty())
        return;
    p.setPen(QPen(style.gridMajor, style.thinLine()));
    p.setBrush(QColor(255, 255, 255, 230));
    p.drawRoundedRect(inset, 4, 4);
    QFont font;
    font.setPointSizeF(font.pointSizeF() * 0.9);
    p.setFont(font);
    const QFontMetricsF fm(font);
    const double pad = 6 * style.scale;
    const QString title = QCoreApplication::translate("granota::ui::DeCasteljauTab", "hodograph c′");
    p.setPen(style.text);
    p.drawText(QRectF(inset.left() + pad, inset.top() + pad / 2, inset.width() - 2 * pad, fm.height()),
               Qt::AlignLeft | Qt::AlignVCenter, fm.elidedText(title, Qt::ElideRight, inset.width() - 2 * pad));
    // Its own view: the hodograph's control points and the origin, fitted into the inset.
    const QRectF area = inset.adjusted(pad, pad + fm.height(), -pad, -pad);
    const auto& H = s.hodoLevels.levels.front();
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    for (const Point& q : H) {
        if (!isFinite(q))
            return;
        x0 = std::min(x0, q.x);
        x1 = std::max(x1, q.x);
        y0 = std::min(y0, q.y);
        y1 = std::max(y1, q.y);
    }
    ViewTransform own;
    own.setViewport(area);
    const double span = std::max({x1 - x0, y1 - y0, 1e-9});
    own.fit(QRectF(QPointF(x0, y0), QPointF(x1, y1)).adjusted(-span * 0.05, -span * 0.05, span * 0.05, span * 0.05), 2.0);
    p.save();
    p.setClipRect(area, Qt::IntersectClip);
    // The axes through the origin: c′(t) is a vector from there.
    const QPointF origin = own.toScreen({0, 0});
    p.setPen(QPen(style.axis, style.thinLine()));
    p.drawLine(QPointF(area.left(), origin.y()), QPointF(area.right(), origin.y()));
    p.drawLine(QPointF(origin.x(), area.top()), QPointF(origin.x(), area.bottom()));
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(style.polygon, style.thinLine(), Qt::DashLine));
    p.drawPath(polylinePath(H, own));
    QColor light = style.curve;
    light.setAlpha(160);
    p.setPen(QPen(light, style.lineWidth() * 0.8));
    p.drawPath(polylinePath(s.hodoCurve, own));
    if (s.view.construction)
        // In the small view a high degree's dots would only cover each other (and cost a frame).
        drawDeCasteljauConstruction(p, own, style, s.hodoLevels, s.hodoLevels.degree() > 10 ? 0.0 : 0.45);
    p.setPen(QPen(Qt::white, style.thinLine()));
    p.setBrush(style.handle);
    for (const Point& q : H)
        p.drawEllipse(own.toScreen(q), style.handleRadius() * 0.55, style.handleRadius() * 0.55);
    // c′(t) as the arrow from the origin, and the point itself.
    const Point d = s.hodoLevels.point();
    p.setPen(QPen(kDeCasteljauTangent, style.thinLine() * 1.5));
    drawDeCasteljauArrow(p, origin, own.toScreen(d), 8.0 * style.scale);
    p.setPen(QPen(Qt::white, style.thinLine()));
    p.setBrush(style.curve);
    p.drawEllipse(own.toScreen(d), style.handleRadius() * 0.8, style.handleRadius() * 0.8);
    p.restore();
}
} // namespace granota::ui
