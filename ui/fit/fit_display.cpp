#include "ui/fit/fit_display.h"

#include "core/base/number_format.h"
#include "core/curves/bezier/de_casteljau.h"
#include "ui/common/canvas_style.h"
#include "ui/common/curvature_comb.h"
#include "ui/common/view_transform.h"
#include "ui/files/tikz_writer.h"

#include <QJsonValue>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace granota::ui {

namespace {

constexpr std::size_t kDrawLimit = 5000; ///< beyond this many points, residuals are drawn decimated
constexpr int kMaxLabelledControls = 30; ///< control points labelled P0… up to this degree
constexpr double kBreakdownBudget = 2e7; ///< operations the breakdown curves may take a refit (as the De Casteljau tab's)
constexpr int kMinBreakdownSamples = 16;
constexpr std::size_t kTikzPointLimit = 2000; ///< data points (and residuals) in a TikZ picture at most
constexpr std::size_t kTikzLabelledData = 30; ///< data points labelled Q_i up to this many

/// Every `stride`-th index so that at most `limit` items are drawn (all of them below it).
std::size_t strideFor(std::size_t count, std::size_t limit) { return count > limit ? (count + limit - 1) / limit : 1; }

QPainterPath pathOf(const std::vector<Point>& points, const ViewTransform& view)
{
    QPainterPath path;
    if (points.empty())
        return path;
    path.moveTo(view.toScreen(points[0]));
    for (std::size_t j = 1; j < points.size(); ++j)
        path.lineTo(view.toScreen(points[j]));
    return path;
}

} // namespace

void writeFitDisplay(const FitDisplay& display, QJsonObject& json)
{
    json.insert(QStringLiteral("control_points"), display.controlPoints);
    json.insert(QStringLiteral("residuals"), display.residuals);
    json.insert(QStringLiteral("breakdown"), display.breakdown);
    json.insert(QStringLiteral("samples"), display.samples);
    json.insert(QStringLiteral("error_plot_all_parametrizations"), display.errorPlotAllParametrizations);
}

std::optional<FitDisplay> readFitDisplay(const QJsonObject& json, QString* badKey)
{
    FitDisplay d;
    const std::pair<const char*, bool*> flags[] = {{"control_points", &d.controlPoints},
                                                   {"residuals", &d.residuals},
                                                   {"breakdown", &d.breakdown},
                                                   {"error_plot_all_parametrizations", &d.errorPlotAllParametrizations}};
    for (const auto& [key, target] : flags) {
        const QJsonValue v = json.value(QLatin1String(key));
        if (v.isUndefined())
            continue;
        if (!v.isBool()) {
            if (badKey)
                *badKey = QLatin1String(key);
            return std::nullopt;
        }
        *target = v.toBool();
    }
    if (const QJsonValue v = json.value(QStringLiteral("samples")); !v.isUndefined()) {
        const double s = v.toDouble(-1);
        if (!v.isDouble() || s != std::floor(s) || s < FitDisplay::kMinSamples || s > FitDisplay::kMaxSamples) {
            if (badKey)
                *badKey = QStringLiteral("samples");
            return std::nullopt;
        }
        d.samples = static_cast<int>(s);
    }
    return d;
}

std::vector<std::vector<Point>> breakdownCurves(const std::vector<Point>& controlPoints, int samples)
{
    std::vector<std::vector<Point>> curves;
    if (controlPoints.empty())
        return curves;
    // n + 1 curves of 1 … n + 1 points cost about n³/6 operations a sample: fewer samples at a high degree.
    const double n = static_cast<double>(controlPoints.size());
    const int part = std::max(1, std::min(samples, std::max(kMinBreakdownSamples,
                                                            static_cast<int>(kBreakdownBudget * 6.0 / (n * n * n)))));
    for (std::size_t k = 1; k <= controlPoints.size(); ++k)
        curves.push_back(k == 1 ? std::vector<Point>{controlPoints[0]}
                                : sampleBezier(std::vector<Point>(controlPoints.begin(),
                                                                  controlPoints.begin() + static_cast<std::ptrdiff_t>(k)),
                                               part + 1));
    return curves;
}

QColor breakdownColor(int k)
{
    QColor c = CanvasStyle::series(k);
    c.setAlpha(170);
    return c;
}

void drawFitResiduals(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const FitPicture& picture)
{
    // Residual vectors Q_i − α(t_i): thin segments from α(t_i) to Q_i.
    if (!picture.fit || !picture.display.residuals)
        return;
    const std::vector<Point>& q = picture.data;
    if (q.size() != picture.fit->residuals.size())
        return;
    p.setPen(QPen(CanvasStyle::series(4), style.thinLine()));
    const std::size_t stride = strideFor(q.size(), kDrawLimit);
    for (std::size_t i = 0; i < q.size(); i += stride)
        p.drawLine(view.toScreen(q[i] - picture.fit->residuals[i]), view.toScreen(q[i]));
}

void drawFitCurve(QPainter& p, const ViewTransform& view, const CanvasStyle& style, const FitPicture& picture)
{
    if (!picture.fit)
        return;
    const FitDisplay& display = picture.display;
    const std::vector<Point>& P = picture.fit->controlPoints;
    // Desglossar: the curves of the first 1, 2, …, n + 1 control points, lighter and thinner.
    if (display.breakdown) {
        p.setBrush(Qt::NoBrush);
        for (std::size_t k = 0; k < picture.breakdown.size(); ++k) {
            const QColor c = breakdownColor(static_cast<int>(k));
            p.setPen(QPen(c, style.lineWidth() * 0.75));
            if (picture.breakdown[k].size() == 1) {
                p.setBrush(c);
                const double r = style.handleRadius() * 0.5;
                p.drawEllipse(view.toScreen(picture.breakdown[k][0]), r, r);
                p.setBrush(Qt::NoBrush);
            } else {
                p.drawPath(pathOf(picture.breakdown[k], view));
            }
        }
    }
    if (display.controlPoints && P.size() > 1) {
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(style.polygon, style.thinLine(), Qt::DashLine));
        p.drawPath(pathOf(P, view));
    }
    if (picture.curve.size() > 1) {
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(style.curve, style.lineWidth()));
        p.drawPath(pathOf(picture.curve, view));
    }
    if (!display.controlPoints)
        return;
    const double r = style.handleRadius() * 0.8;
    p.setFont(style.labelFont());
    for (std::size_t j = 0; j < P.size(); ++j) {
        const QPointF s = view.toScreen(P[j]);
        p.setPen(QPen(Qt::white, style.thinLine()));
        p.setBrush(style.curve);
        p.drawRect(QRectF(s.x() - r, s.y() - r, 2 * r, 2 * r)); // squares: computed, not dragged
        if (P.size() <= kMaxLabelledControls + 1) {
            p.setPen(style.curve);
            p.drawText(s + QPointF(r + 3 * style.scale, r + p.fontMetrics().ascent()), QStringLiteral("P%1").arg(j));
        }
    }
}

void writeFitTikz(TikzWriter& w, const FitPicture& picture, const CurvatureComb* comb)
{
    const CanvasStyle style;
    const FitDisplay& display = picture.display;
    const std::vector<Point>& q = picture.data;
    const std::size_t stride = strideFor(q.size(), kTikzPointLimit);
    if (picture.fit) {
        const std::vector<Point>& P = picture.fit->controlPoints;
        if (display.controlPoints)
            w.polyline(P, style.polygon, 0.6, true);
        if (comb) {
            w.comment(
                QStringLiteral("curvature comb: teeth |kappa| x %1").arg(QString::fromStdString(formatDouble(comb->scale))));
            for (const auto& tooth : comb->teeth)
                w.polyline({tooth.base, tooth.tip}, curvatureCombColor(), 0.3);
            for (const auto& stretch : comb->outline)
                w.polyline(stretch, curvatureCombColor(), 0.6);
        }
        if (display.breakdown) {
            w.comment(QStringLiteral("desglossar: the curves of the first 1, 2, ..., n+1 control points"));
            for (std::size_t k = 0; k < picture.breakdown.size(); ++k) {
                const QColor c = breakdownColor(static_cast<int>(k));
                if (picture.breakdown[k].size() == 1)
                    w.point(picture.breakdown[k][0], c);
                else
                    w.polyline(picture.breakdown[k], c, 0.8);
            }
        }
        w.polyline(picture.curve, style.curve, 1.2);
        if (display.residuals && picture.fit->residuals.size() == q.size()) {
            w.comment(QStringLiteral("residuals Q_i - alpha(t_i)"));
            for (std::size_t i = 0; i < q.size(); i += stride)
                w.polyline({q[i] - picture.fit->residuals[i], q[i]}, CanvasStyle::series(4), 0.4);
        }
        for (std::size_t j = 0; display.controlPoints && j < P.size(); ++j)
            w.point(P[j], style.curve, P.size() <= kMaxLabelledControls + 1 ? QStringLiteral("P_{%1}").arg(j) : QString());
    }
    for (std::size_t i = 0; i < q.size(); i += stride)
        w.point(q[i], style.handle, q.size() <= kTikzLabelledData ? QStringLiteral("Q_{%1}").arg(i) : QString());
}

} // namespace granota::ui
