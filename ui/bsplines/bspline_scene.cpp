#include "ui/bsplines/bspline_scene.h"

#include "core/curves/bezier/degree_elevation.h"
#include "core/curves/bsplines/bezier_extraction.h"
#include "core/curves/bsplines/circle_arcs.h"

#include <QRectF>

#include <algorithm>
#include <cmath>

namespace granota::ui {

BSplineScene computeBSplineScene(const std::vector<Point>& points, const std::vector<RPoint>& exactValues, bool allExact,
                                 const BSplineModel& model)
{
    BSplineScene s;
    const int count = static_cast<int>(points.size());
    s.curve = model.curve(points);
    s.exact = model.curve(exactValues);
    s.u = model.uFor(count);
    if (model.cubicCircle) {
        s.cubicCircle = cubicQuarterCircle(cubicCircleHandle());
        s.cubicCircleError = cubicCircleRadialError(cubicCircleHandle()).maxError;
    }
    if (const Expected<void> ok = checkBSpline(s.curve); !ok) {
        s.error = QString::fromStdString(ok.error().message);
        return s;
    }
    // The exact knots decide: two doubles may round equal where the fractions differ.
    if (const Expected<void> ok = checkBSpline(s.exact); !ok) {
        s.error = QString::fromStdString(ok.error().message);
        return s;
    }
    if (allExact)
        s.exactNet = deBoor(s.exact, s.u);
    s.net = deBoor(s.curve, toDouble(s.u));
    if (s.exactNet) // the drawn net at exactly the exact values, rounded once
        for (std::size_t r = 0; r < s.net.levels.size(); ++r)
            for (std::size_t i = 0; i < s.net.levels[r].size(); ++i) {
                const RPoint& q = s.exactNet->levels[r][i];
                s.net.levels[r][i] = Point(toDouble(q.x), toDouble(q.y));
            }

    const int p = s.curve.degree;
    const auto& k = s.curve.knots;
    for (int span = p; span < count; ++span) {
        const double a = k[static_cast<std::size_t>(span)], b = k[static_cast<std::size_t>(span + 1)];
        if (!(a < b))
            continue;
        for (int j = 0; j < BSplineScene::kSamplesPerSpan; ++j) {
            if (j == 0 && !s.samples.empty())
                continue; // the previous span's end
            const double t = static_cast<double>(j) / (BSplineScene::kSamplesPerSpan - 1);
            // The span's own end value, not the next one's start, so that each sample is in its span.
            const double u = j + 1 == BSplineScene::kSamplesPerSpan ? b : a + t * (b - a);
            s.samples.push_back(bsplinePointInSpan(s.curve, u, span)); // the span known: no search
        }
    }
    const auto pieces = toBezierSegments(s.curve);
    for (const auto& segment : pieces) {
        s.bezier.push_back(segment.points);
        s.bezierWeights.push_back(segment.weights);
        if (!s.curve.rational() && p <= 3) {
            // Degree elevation (Farin §5.1) keeps the segment and gives TikZ and SVG their cubics.
            std::vector<Point> b = segment.points;
            while (b.size() < 4)
                b = elevateDegree(b);
            s.cubics.push_back({b[0], b[1], b[2], b[3]});
        }
    }
    if (model.homogeneousCurve)
        s.homogeneous = homogeneousView(s.curve, BSplineScene::kHomogeneousSamples);
    if (model.curvaturePlot) {
        s.curvature = curvatureProfile(s.bezier, s.bezierWeights, BSplineScene::kCurvatureSamples);
        // Piece i ≥ 1 starts at an interior knot of the domain; its multiplicity m is counted
        // among the knots (pieces[i].start is one of them: the extraction keeps the knot values).
        for (std::size_t i = 1; i < pieces.size() && i < s.curvature.knots.size(); ++i) {
            const auto m = static_cast<int>(std::count(s.curve.knots.begin(), s.curve.knots.end(), pieces[i].start));
            s.curvatureKnots.push_back({s.curvature.knots[i], m});
        }
    }
    return s;
}

QRectF bsplineContentBounds(const std::vector<Point>& points, const BSplineScene& scene)
{
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    const auto add = [&](const Point& q) {
        if (!isFinite(q))
            return;
        x0 = std::min(x0, q.x);
        y0 = std::min(y0, q.y);
        x1 = std::max(x1, q.x);
        y1 = std::max(y1, q.y);
    };
    for (const Point& q : points)
        add(q);
    for (const Point& q : scene.samples)
        add(q);
    if (!(x0 <= x1))
        return {-1, -1, 2, 2};
    return QRectF(QPointF(x0, y0), QPointF(x1, y1));
}

} // namespace granota::ui
