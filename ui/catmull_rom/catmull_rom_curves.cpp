#include "ui/catmull_rom/catmull_rom_curves.h"
#include "ui/common/error_text.h"

#include "core/curves/bezier/de_casteljau.h"
#include "core/curves/splines/cubic_spline.h"
#include "core/curves/splines/function_spline_segments.h"

#include <algorithm>

namespace granota::ui {

std::vector<std::vector<Point>> controlPolygons(const std::vector<BezierSegment<double>>& segments)
{
    std::vector<std::vector<Point>> out;
    out.reserve(segments.size());
    for (const auto& b : segments)
        out.push_back({b[0], b[1], b[2], b[3]});
    return out;
}

QString translatedError(const Error& error, CatmullRomEnds ends)
{
    switch (error.code) {
    case ErrorCode::TooFewPoints:
        switch (ends) {
        case CatmullRomEnds::Open: return CatmullRomCurves::tr("An open curve needs at least 2 points.");
        case CatmullRomEnds::Segment: return CatmullRomCurves::tr("A single segment (Def 2.8) needs at least 4 points.");
        default: return CatmullRomCurves::tr("A cyclic or closed curve needs at least 3 points.");
        }
    case ErrorCode::InvalidInput: return CatmullRomCurves::tr("A point or a tension is not a finite number.");
    case ErrorCode::OutOfRange: return CatmullRomCurves::tr("The curve overflows: the coordinates are too large.");
    case ErrorCode::NotIncreasing:
        return CatmullRomCurves::tr("No cubic spline (Def 2.3): the points are not a function of x — their abscissae must "
                                    "increase strictly from q0 to qn.");
    case ErrorCode::Singular:
        return CatmullRomCurves::tr("No unique cubic spline with these ends: as Ex 2.1, the last but one abscissa must not "
                                    "be 0.");
    default: return ErrorText::of(error);
    }
}

CatmullRomScene computeScene(const std::vector<Point>& points, const CatmullRomSettings& settings)
{
    CatmullRomScene scene;
    const double alpha = spacingAlpha(settings.spacing);
    // About as many segments as points per curve, one curve per τ and per compared end mode.
    const std::size_t segmentsProfiled = std::max<std::size_t>(1, settings.taus.size() * (settings.compareEnds ? 2 : 1) *
                                                                      points.size());
    const int curvatureSamples = static_cast<int>(
        std::clamp<std::size_t>(CatmullRomScene::kCurvatureSampleBudget / segmentsProfiled, CatmullRomScene::kMinCurvatureSamples,
                                CatmullRomScene::kSamplesPerSegment));
    auto makeCurve = [&](const Rational& tau, CatmullRomEnds ends) {
        CatmullRomCurve curve;
        curve.tau = tau;
        curve.ends = ends;
        auto segs = curveSegments(points, toDouble(tau), ends, alpha);
        if (!segs) {
            curve.error = translatedError(segs.error(), ends);
            return curve;
        }
        curve.segments = std::move(*segs);
        if (curve.segments.empty())
            return curve;
        curve.samples = sampleSegments(curve.segments, CatmullRomScene::kSamplesPerSegment);
        curve.bezier = bezierSegments(curve.segments);
        // The knot spacing of the segments shown: Segment mode drops the open curve's first and last.
        std::vector<double> h = catmullRomIntervals(points, coreMode(ends), alpha);
        if (ends == CatmullRomEnds::Segment && h.size() >= 2)
            h = std::vector<double>(h.begin() + 1, h.end() - 1);
        if (h.size() != curve.segments.size())
            h.assign(curve.segments.size(), 1.0);
        for (double& hi : h)
            if (!(hi > 0.0))
                hi = 1.0; // a segment between coincident points is constant: any length will do
        curve.intervals = std::move(h);
        if (settings.curvaturePlot)
            curve.curvature = curvatureProfile(controlPolygons(curve.bezier), curvatureSamples);
        return curve;
    };
    for (const Rational& tau : settings.taus)
        scene.curves.push_back(makeCurve(tau, settings.ends));
    if (settings.compareEnds)
        for (const Rational& tau : settings.taus)
            scene.otherEnds.push_back(makeCurve(tau, comparedEnds(settings.ends)));
    if (settings.bezier && points.size() >= 2) {
        scene.bezier = sampleBezier(points, CatmullRomScene::kBezierSamples);
        if (settings.curvaturePlot)
            scene.bezierCurvature = curvatureProfile({points}, CatmullRomScene::kBezierSamples);
    }
    if (settings.spline) {
        const auto spline = cubicSpline(points, SplineEndConditions<double>{settings.splineEnds, toDouble(settings.startSlope),
                                                                            toDouble(settings.endSlope)});
        if (!spline) {
            scene.splineError = translatedError(spline.error(), settings.ends);
        } else {
            for (int i = 0; i < spline->pieceCount(); ++i) {
                const double a = spline->knots[static_cast<std::size_t>(i)];
                const double b = spline->knots[static_cast<std::size_t>(i) + 1];
                for (int j = 0; j < CatmullRomScene::kSamplesPerSegment; ++j) {
                    const double x = a + (b - a) * j / (CatmullRomScene::kSamplesPerSegment - 1);
                    scene.spline.push_back({x, spline->evaluatePiece(i, x)});
                }
            }
            scene.splinePieces = *spline;
            auto graph = functionSplineSegments(*spline);
            scene.splineSegments = std::move(graph.segments);
            scene.splineIntervals = std::move(graph.intervals);
            scene.splineBezier = bezierSegments(scene.splineSegments);
            if (settings.curvaturePlot)
                scene.splineCurvature = curvatureProfile(controlPolygons(scene.splineBezier),
                                                         CatmullRomScene::kSamplesPerSegment);
        }
    }
    // The family selector's switch point: Catmull-Rom is the τ curves above, every other
    // family its own curve (family_curves.cpp).
    scene.family = computeFamilyCurve(points, settings);
    if (settings.family == CurveFamily::PlaneSpline)
        scene.planeSpline = computePlaneSplineScene(points, settings.planeSpline, settings.curvaturePlot);
    if (settings.family == CurveFamily::FunctionData)
        scene.functionData = computeFunctionDataScene(points, settings.functionData, settings.curvaturePlot);
    return scene;
}

CatmullRomAnalysis computeAnalysis(const std::optional<std::vector<RPoint>>& exactPoints, const CatmullRomSettings& settings)
{
    CatmullRomQuestion q;
    q.taus = settings.taus;
    q.selectedTau = settings.selectedTau;
    q.ends = settings.ends;
    q.compareEnds = settings.compareEnds;
    q.uniform = settings.spacing == CatmullRomSpacing::Uniform;
    q.spline = settings.spline;
    q.splineEnds = SplineEndConditions<Rational>{settings.splineEnds, settings.startSlope, settings.endSlope};
    return analyseCatmullRom(exactPoints, q);
}

} // namespace granota::ui
