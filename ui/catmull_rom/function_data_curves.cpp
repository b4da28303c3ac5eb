#include "ui/catmull_rom/function_data_curves.h"

#include "ui/catmull_rom/catmull_rom_curves.h"
#include "ui/catmull_rom/catmull_rom_drawing.h"
#include "ui/catmull_rom/tension_colour.h"
#include "ui/common/error_text.h"

#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/catmull_rom_ends.h"
#include "core/curves/splines/cubic_spline.h"
#include "core/curves/splines/function_spline_segments.h"
#include "core/curves/splines/monotone_spline.h"

#include <algorithm>

namespace granota::ui {

namespace {

/// The data's error in the user's language: the curves exist only for y(x).
QString functionDataErrorText(const Error& error)
{
    switch (error.code) {
    case ErrorCode::TooFewPoints: return FunctionDataCurves::tr("Function data need at least 2 points.");
    case ErrorCode::NotIncreasing:
        return FunctionDataCurves::tr("The points are not data y(x): their abscissae must increase strictly from q0 to qn. "
                                      "Move a point, or choose another family: the points are kept.");
    case ErrorCode::InvalidInput: return FunctionDataCurves::tr("A point is not a finite number.");
    case ErrorCode::OutOfRange: return FunctionDataCurves::tr("The curve overflows: the coordinates are too large.");
    default: return ErrorText::of(error);
    }
}

Expected<std::vector<Vec2<Polynomial<double>>>> functionDataSegments(const std::vector<Point>& points, FunctionDataCurve curve)
{
    switch (curve) {
    case FunctionDataCurve::CatmullRom: return curveSegments(points, 0.5, CatmullRomEnds::Open, 0.0);
    case FunctionDataCurve::Natural: {
        const auto spline = naturalCubicSpline(points);
        if (!spline)
            return spline.error();
        return functionSplineSegments(*spline).segments;
    }
    case FunctionDataCurve::FritschCarlson:
    case FunctionDataCurve::Steffen: {
        const auto spline = monotoneSpline(points, curve == FunctionDataCurve::Steffen ? MonotoneMethod::Steffen
                                                                                       : MonotoneMethod::FritschCarlson);
        if (!spline)
            return spline.error();
        return functionSplineSegments(*spline).segments;
    }
    }
    return std::vector<Vec2<Polynomial<double>>>{};
}

} // namespace

QColor functionDataCurveColour(FunctionDataCurve curve)
{
    switch (curve) {
    case FunctionDataCurve::Natural: return kCatmullRomSplineColor;
    case FunctionDataCurve::CatmullRom: return tensionColour(0.5);
    case FunctionDataCurve::FritschCarlson: return QColor(0x1f, 0x5f, 0xbf);
    case FunctionDataCurve::Steffen: return QColor(0xd9, 0x5f, 0x02);
    }
    return Qt::black;
}

QString functionDataCurveLabel(FunctionDataCurve curve)
{
    switch (curve) {
    case FunctionDataCurve::Natural: return FunctionDataCurves::tr("natural spline");
    case FunctionDataCurve::CatmullRom: return FunctionDataCurves::tr("Catmull-Rom τ = 1/2");
    case FunctionDataCurve::FritschCarlson: return FunctionDataCurves::tr("Fritsch–Carlson");
    case FunctionDataCurve::Steffen: return FunctionDataCurves::tr("Steffen");
    }
    return {};
}

FunctionDataScene computeFunctionDataScene(const std::vector<Point>& points, const FunctionDataSettings& settings, bool curvature)
{
    FunctionDataScene scene;
    // The data check first (x increasing, enough points, finite): the natural spline's.
    if (const auto check = naturalCubicSpline(points); !check) {
        scene.error = functionDataErrorText(check.error());
        return scene;
    }
    double yMin = points.front().y, yMax = yMin;
    for (const Point& q : points) {
        yMin = std::min(yMin, q.y);
        yMax = std::max(yMax, q.y);
    }
    const double rounding = FunctionDataScene::kOvershootRoundingFraction * std::max(yMax - yMin, 1e-300);
    for (FunctionDataCurve kind : kFunctionDataCurves) {
        if (!settings.isShown(kind))
            continue;
        auto segments = functionDataSegments(points, kind);
        if (!segments) {
            scene.error = functionDataErrorText(segments.error());
            continue;
        }
        FunctionDataCurveShape shape;
        shape.curve = kind;
        shape.segments = std::move(*segments);
        shape.bezier = bezierSegments(shape.segments);
        shape.samples = sampleSegments(shape.segments, FunctionDataScene::kSamplesPerSegment);
        for (std::size_t i = 0; i < shape.segments.size() && i + 1 < points.size(); ++i) {
            const double lo = std::min(points[i].y, points[i + 1].y), hi = std::max(points[i].y, points[i + 1].y);
            IntervalOvershoot o = polynomialOvershoot(shape.segments[i].y, lo, hi);
            if (o.amount <= rounding)
                o = IntervalOvershoot{};
            shape.overshoot.push_back(o);
            if (o.amount > shape.largestOvershoot) {
                shape.largestOvershoot = o.amount;
                shape.largestInterval = static_cast<int>(i);
            }
            if (o.amount > 0) {
                const auto begin = shape.samples.begin() + static_cast<std::ptrdiff_t>(i * FunctionDataScene::kSamplesPerSegment);
                std::vector<Point> region(begin, begin + FunctionDataScene::kSamplesPerSegment);
                for (auto it = begin + FunctionDataScene::kSamplesPerSegment; it != begin;) {
                    --it;
                    region.push_back({it->x, std::clamp(it->y, lo, hi)});
                }
                shape.overshootRegions.push_back(std::move(region));
            }
        }
        if (curvature)
            shape.curvature = curvatureProfile(controlPolygons(shape.bezier), FunctionDataScene::kSamplesPerSegment);
        scene.curves.push_back(std::move(shape));
    }
    return scene;
}

} // namespace granota::ui
