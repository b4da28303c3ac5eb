#include "ui/decasteljau/decasteljau_tikz.h"

#include "core/base/math_constants.h"
#include "core/base/number_format.h"
#include "ui/common/bezier_exact_html.h"
#include "ui/decasteljau/decasteljau_scene_painter.h"
#include "ui/files/tikz_writer.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

constexpr int kCircleSegments = 96; ///< the osculating circle as a polygon (TikZ)

/// Text for TeX: its special characters written as TeX reads them literally.
QString literalTexText(const QString& text)
{
    QString out;
    for (const QChar c : text) {
        if (c == QLatin1Char('\\'))
            out += QStringLiteral("\\textbackslash{}");
        else if (c == QLatin1Char('~'))
            out += QStringLiteral("\\textasciitilde{}");
        else if (c == QLatin1Char('^'))
            out += QStringLiteral("\\textasciicircum{}");
        else if (QStringLiteral("&%$#_{}").contains(c))
            out += QLatin1Char('\\') + QString(c);
        else
            out += c;
    }
    return out;
}

} // namespace

void writeDeCasteljauTikz(TikzWriter& w, const DeCasteljauScene& s, const QRectF& content)
{
    const CanvasStyle style;
    const auto& points = s.points;
    w.comment(QStringLiteral("Bezier curve of degree %1 (De Casteljau, Def 2.4) at t = %2").arg(points.size() - 1).arg(s.t));
    if (s.view.controlPoints)
        w.polyline(points, style.polygon, 0.6, true);
    if (s.view.construction)
        for (int r = 1; r < s.levels.degree(); ++r)
            w.polyline(s.levels.levels[static_cast<std::size_t>(r)], CanvasStyle::series(r), 0.6);
    if (s.view.comb) {
        for (const auto& tooth : s.comb.teeth)
            w.polyline({tooth.base, tooth.tip}, curvatureCombColor(), 0.3);
        for (const auto& stretch : s.comb.outline)
            w.polyline(stretch, curvatureCombColor(), 0.6);
    }
    if (s.view.boundingBox && isFinite(s.features.bbox.minCorner()) && isFinite(s.features.bbox.maxCorner())) {
        const Aabb& b = s.features.bbox;
        w.comment(QStringLiteral("tight bounding box and the extrema of x and y"));
        w.polyline({b.minCorner(), {b.maxX, b.minY}, b.maxCorner(), {b.minX, b.maxY}}, kDeCasteljauBox, 0.6, true, true);
        for (const auto* list : {&s.features.extremaX, &s.features.extremaY})
            for (double t : *list)
                w.point(deCasteljauPoint(points, t), kDeCasteljauBox);
    }
    w.polyline(s.curve, style.curve, 1.2);
    if (s.view.inflections && !points.empty()) {
        for (double t : s.features.inflections)
            w.point(deCasteljauPoint(points, t), kDeCasteljauInflection, QStringLiteral("\\mathrm{infl.}"));
        for (double t : s.features.cusps)
            w.point(deCasteljauPoint(points, t), kDeCasteljauCusp, QStringLiteral("\\mathrm{cusp}"));
    }
    const int n = s.levels.degree();
    // Arrows, as on the canvas: c′(t)/n and N(t) are vectors from c(t).
    if (s.view.tangent && n >= 1 && isFinite(s.levels.point()) && isFinite(s.levels.tangent()))
        w.arrow(s.levels.point(), s.levels.point() + (1.0 / n) * s.levels.tangent(), kDeCasteljauTangent, 1.0);
    if (s.view.normal && n >= 1 && s.curvature.normal) {
        const double length = std::hypot(s.curvature.tangent.x, s.curvature.tangent.y) / n;
        const Point tip = s.curvature.point + length * *s.curvature.normal;
        if (isFinite(tip))
            w.arrow(s.curvature.point, tip, kDeCasteljauNormal, 1.0);
    }
    const double contentSize = std::max(content.width(), content.height());
    // A nearly straight piece has a circle far larger than the picture: it would shrink it to nothing.
    if (s.view.osculatingCircle && s.curvature.center && s.curvature.radius && isFinite(*s.curvature.center) &&
        *s.curvature.radius <= 4 * contentSize) {
        std::vector<Point> circle;
        for (int k = 0; k < kCircleSegments; ++k) {
            const double a = 2 * kPi * k / kCircleSegments;
            circle.push_back(*s.curvature.center + *s.curvature.radius * Point(std::cos(a), std::sin(a)));
        }
        w.comment(
            QStringLiteral("osculating circle at t, radius %1").arg(QString::fromStdString(formatDouble(*s.curvature.radius))));
        w.polyline(circle, kDeCasteljauCircle, 0.8, false, true);
    }
    for (std::size_t i = 0; s.view.controlPoints && i < points.size(); ++i)
        w.point(points[i], style.handle, QStringLiteral("P_{%1}").arg(i));
    if (!s.levels.levels.empty())
        w.point(s.levels.point(), style.curve, QStringLiteral("c(t)"));
    if (s.view.hodograph && !s.hodoLevels.levels.empty() && triangleFitsInDoubles(s.hodoLevels)) {
        // The inset of the canvas: c′ with its control polygon, its curve, its construction at t
        // and c′(t) as the vector from the origin.
        const auto& H = s.hodoLevels.levels.front();
        const QString title = literalTexText(QCoreApplication::translate("granota::ui::DeCasteljauTab", "hodograph c′"))
                                  .replace(QStringLiteral("c′"), QStringLiteral("$c'$"));
        w.beginInset(title);
        QStringList coordinates;
        for (const Point& q : H)
            coordinates << QStringLiteral("(%1, %2)")
                               .arg(QString::fromStdString(formatDouble(q.x)), QString::fromStdString(formatDouble(q.y)));
        w.comment(QStringLiteral("hodograph: control points n (P_{i+1} - P_i) = %1").arg(coordinates.join(QStringLiteral(", "))));
        w.polyline(H, style.polygon, 0.4, true);
        w.polyline(s.hodoCurve, style.curve, 0.8);
        if (s.view.construction)
            for (int r = 1; r < s.hodoLevels.degree(); ++r)
                w.polyline(s.hodoLevels.levels[static_cast<std::size_t>(r)], CanvasStyle::series(r), 0.4);
        for (const Point& q : H)
            w.point(q, style.handle);
        w.arrow({0, 0}, s.hodoLevels.point(), kDeCasteljauTangent, 0.8);
        w.point(s.hodoLevels.point(), style.curve, QStringLiteral("c'(t)"));
        w.endInset();
    }
    // The canvas's key, placed as it is: where it covers least, clear of the inset.
    const CanvasLegend key = deCasteljauLegend(s);
    std::vector<TikzLegendEntry> entries;
    for (const CanvasLegendEntry& e : key.entries)
        entries.push_back({e.color, e.pen, TikzWriter::texText(e.text)});
    w.legend(entries, TikzWriter::texText(key.note), key.alertColor);
}
} // namespace granota::ui
