#include "ui/catmull_rom/plane_spline_curves.h"

#include "ui/catmull_rom/catmull_rom_curves.h"
#include "ui/common/error_text.h"

#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/catmull_rom_ends.h"
#include "core/curves/splines/parametric_spline.h"

namespace granota::ui {

namespace {

/// α of the Catmull-Rom spacing that matches the spline's parameters (h_i = |Δq|^α).
double planeSplineMatchingAlpha(SplineParameters parameters)
{
    switch (parameters) {
    case SplineParameters::Uniform: return 0.0;
    case SplineParameters::Centripetal: return 0.5;
    case SplineParameters::Chord: return 1.0;
    }
    return 0.0;
}

void finishPlaneSplineCurve(PlaneSplineCurve& curve, const std::vector<Vec2<Polynomial<double>>>& segments, bool curvature)
{
    curve.bezier = bezierSegments(segments);
    curve.samples = sampleSegments(segments, PlaneSplineScene::kSamplesPerSegment);
    if (curvature)
        curve.curvature = curvatureProfile(controlPolygons(curve.bezier), PlaneSplineScene::kSamplesPerSegment);
}

} // namespace

QString planeSplineEndsLabel(ParametricEnds ends)
{
    switch (ends) {
    case ParametricEnds::Natural: return PlaneSplineCurves::tr("natural");
    case ParametricEnds::Clamped: return PlaneSplineCurves::tr("clamped");
    case ParametricEnds::NotAKnot: return PlaneSplineCurves::tr("not-a-knot");
    case ParametricEnds::Periodic: return PlaneSplineCurves::tr("periodic (closed)");
    }
    return {};
}

QString planeSplineParametersLabel(SplineParameters parameters)
{
    switch (parameters) {
    case SplineParameters::Uniform: return PlaneSplineCurves::tr("uniform");
    case SplineParameters::Chord: return PlaneSplineCurves::tr("chord length");
    case SplineParameters::Centripetal: return PlaneSplineCurves::tr("centripetal");
    }
    return {};
}

QString translatedPlaneSplineError(const Error& error, const std::vector<Point>& points, const PlaneSplineSettings& settings)
{
    switch (error.code) {
    case ErrorCode::TooFewPoints:
        return settings.ends == ParametricEnds::Periodic ? PlaneSplineCurves::tr("A closed C² spline needs at least 3 points.")
                                                         : PlaneSplineCurves::tr("An open C² spline needs at least 2 points.");
    case ErrorCode::InvalidInput:
        // The core's InvalidInput is a repeated point only with chord or centripetal parameters.
        if (settings.parameters != SplineParameters::Uniform && points.size() >= 2) {
            const bool closed = settings.ends == ParametricEnds::Periodic;
            const std::size_t count = closed ? points.size() : points.size() - 1;
            for (std::size_t i = 0; i < count; ++i) {
                const std::size_t next = (i + 1) % points.size();
                if (points[i] == points[next])
                    return PlaneSplineCurves::tr("Points q%1 and q%2 coincide: %3 parameters need distinct consecutive "
                                                 "points (use uniform parameters, or move one).")
                        .arg(i)
                        .arg(next)
                        .arg(planeSplineParametersLabel(settings.parameters));
            }
        }
        return PlaneSplineCurves::tr("A point or an end tangent is not a finite number.");
    case ErrorCode::OutOfRange: return PlaneSplineCurves::tr("The spline overflows: the coordinates are too large.");
    default: return ErrorText::of(error);
    }
}

PlaneSplineScene computePlaneSplineScene(const std::vector<Point>& points, const PlaneSplineSettings& settings, bool curvature)
{
    PlaneSplineScene scene;
    const auto spline = parametricSpline(points, settings.ends, settings.parameters,
                                         Point(toDouble(settings.startTangent.x), toDouble(settings.startTangent.y)),
                                         Point(toDouble(settings.endTangent.x), toDouble(settings.endTangent.y)));
    if (!spline) {
        scene.spline.error = translatedPlaneSplineError(spline.error(), points, settings);
    } else {
        scene.spline.knots = spline->knots;
        finishPlaneSplineCurve(scene.spline, parametricSplinePolynomials(*spline), curvature);
    }
    if (settings.catmullRomToo) {
        const CatmullRomEnds ends = settings.ends == ParametricEnds::Periodic ? CatmullRomEnds::Closed : CatmullRomEnds::Open;
        const auto segments = curveSegments(points, 0.5, ends, planeSplineMatchingAlpha(settings.parameters));
        if (!segments)
            scene.catmullRom.error = translatedError(segments.error(), ends);
        else
            finishPlaneSplineCurve(scene.catmullRom, *segments, curvature);
    }
    return scene;
}

} // namespace granota::ui
