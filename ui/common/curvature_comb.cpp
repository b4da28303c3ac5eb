#include "ui/common/curvature_comb.h"

#include "core/curves/bezier/curvature.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {
constexpr double kToothShare = 0.15; ///< an automatic comb: a typical tooth is this share of the curve's size
constexpr double kToothCap = 0.5;    ///< no tooth is longer than this share of the curve's size (a cusp's)
constexpr double kPercentile = 0.9;  ///< the typical tooth: the 90th percentile of |κ|, not a cusp's huge one

/// The diagonal of the box of the curve's samples: its size on the canvas. Not the control
/// polygon's, which at a high fitted degree lies orders of magnitude beyond the curve
/// (× 10⁶ at n = 30), so that teeth scaled by it would leave any view of the curve.
double curveSize(const std::vector<Point>& samples)
{
    double x0 = samples.front().x, x1 = x0, y0 = samples.front().y, y1 = y0;
    for (const Point& q : samples) {
        x0 = std::min(x0, q.x);
        x1 = std::max(x1, q.x);
        y0 = std::min(y0, q.y);
        y1 = std::max(y1, q.y);
    }
    return std::hypot(x1 - x0, y1 - y0);
}
} // namespace

CurvatureComb curvatureComb(const std::vector<Point>& P, int samples, double scale)
{
    CurvatureComb comb;
    if (P.size() < 2 || samples < 1)
        return comb;
    struct Sample {
        Point point, normal;
        double kappa = 0;
        bool defined = false;
    };
    std::vector<Sample> at(static_cast<std::size_t>(samples) + 1);
    std::vector<double> magnitudes;
    for (int j = 0; j <= samples; ++j) {
        const CurvatureAt c = curvatureAt(P, static_cast<double>(j) / samples);
        Sample& s = at[static_cast<std::size_t>(j)];
        s.point = c.point;
        if (c.curvature && c.normal && std::isfinite(*c.curvature) && isFinite(*c.normal)) {
            s.defined = true;
            s.kappa = *c.curvature;
            s.normal = *c.normal;
            magnitudes.push_back(std::fabs(s.kappa));
        }
    }
    std::vector<Point> points;
    points.reserve(at.size());
    for (const Sample& s : at)
        points.push_back(s.point);
    const double size = curveSize(points);
    if (!(size > 0) || !std::isfinite(size))
        return {};
    if (!(scale > 0)) {
        double typical = 0;
        if (!magnitudes.empty()) {
            const auto k = static_cast<std::ptrdiff_t>(kPercentile * static_cast<double>(magnitudes.size() - 1));
            std::nth_element(magnitudes.begin(), magnitudes.begin() + k, magnitudes.end());
            typical = magnitudes[static_cast<std::size_t>(k)];
        }
        scale = typical > 0 ? kToothShare * size / typical : 1.0; // a straight curve: teeth of length 0 whatever the scale
    }
    comb.scale = scale;
    std::vector<Point> stretch;
    for (const Sample& s : at) {
        if (!s.defined) {
            ++comb.undefinedSamples;
            if (stretch.size() > 1)
                comb.outline.push_back(stretch);
            stretch.clear();
            continue;
        }
        // Away from the centre of curvature c + N/κ: −κ N, cut at a share of the curve's size.
        const double cap = kToothCap * size;
        const double length = std::clamp(-s.kappa * scale, -cap, cap);
        const Point tip = s.point + length * s.normal;
        comb.teeth.push_back({s.point, tip});
        stretch.push_back(tip);
    }
    if (stretch.size() > 1)
        comb.outline.push_back(stretch);
    return comb;
}

void drawCurvatureComb(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const CurvatureComb& comb,
                       const QColor& color)
{
    if (comb.empty())
        return;
    QColor light = color;
    light.setAlpha(150);
    p.setBrush(Qt::NoBrush);
    // The teeth as one path: one stroke for all of them.
    QPainterPath teeth;
    for (const auto& tooth : comb.teeth) {
        teeth.moveTo(view.toScreen(tooth.base));
        teeth.lineTo(view.toScreen(tooth.tip));
    }
    p.setPen(QPen(light, style.thinLine()));
    p.drawPath(teeth);
    QPainterPath outline;
    for (const auto& stretch : comb.outline) {
        outline.moveTo(view.toScreen(stretch.front()));
        for (std::size_t i = 1; i < stretch.size(); ++i)
            outline.lineTo(view.toScreen(stretch[i]));
    }
    p.setPen(QPen(color, style.thinLine() * 1.5));
    p.drawPath(outline);
}

} // namespace granota::ui
