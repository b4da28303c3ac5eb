#include "ui/catmull_rom/family_curves.h"

#include "core/curves/splines/cardinal_spline.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/curves/splines/catmull_rom_ends.h"
#include "ui/catmull_rom/catmull_rom_curves.h"

#include <algorithm>

namespace granota::ui {

namespace {

/// How many segments Def 2.10 strings through n points (Segment: the interior ones).
std::size_t familySegmentCount(std::size_t n, CatmullRomEnds ends)
{
    switch (ends) {
    case CatmullRomEnds::Open:
    case CatmullRomEnds::Cyclic: return n >= 2 ? n - 1 : 0;
    case CatmullRomEnds::Closed: return n >= 3 ? n : 0;
    case CatmullRomEnds::Segment: return n >= 4 ? n - 3 : 0;
    }
    return 0;
}

/// Samples, Bézier segments and κ(s) of the Hermite segments already in `curve`.
void finishFamilyCurve(FamilyCurve& curve, const CatmullRomSettings& settings)
{
    curve.segments = hermitePolynomials(curve.hermite);
    if (curve.segments.empty())
        return;
    if (curve.intervals.size() != curve.segments.size())
        curve.intervals.assign(curve.segments.size(), 1.0);
    for (double& h : curve.intervals)
        if (!(h > 0.0))
            h = 1.0; // a segment between coincident points is a point: any length will do
    curve.samples = sampleSegments(curve.segments, CatmullRomScene::kSamplesPerSegment);
    curve.bezier = bezierSegments(curve.segments);
    if (settings.curvaturePlot)
        curve.curvature = curvatureProfile(controlPolygons(curve.bezier), CatmullRomScene::kSamplesPerSegment);
}

} // namespace

std::vector<Point> catmullRomTangents(const std::vector<Point>& points, const CatmullRomSettings& settings)
{
    std::vector<Point> out(points.size(), Point{0, 0});
    if (settings.selectedTau < 0 || settings.selectedTau >= static_cast<int>(settings.taus.size()))
        return out;
    const double tau = toDouble(settings.taus[static_cast<std::size_t>(settings.selectedTau)]);
    const auto segs = catmullRomHermiteSegments(points, tau, coreMode(settings.ends), spacingAlpha(settings.spacing));
    if (!segs)
        return out;
    const auto t = familyTangentsOf(*segs, points.size(), 0);
    for (std::size_t i = 0; i < points.size(); ++i)
        out[i] = t[i].out;
    return out;
}

std::vector<Point> hermiteTangentsOf(const std::vector<Point>& points, const CatmullRomSettings& settings)
{
    std::vector<Point> t = settings.hermiteTangents;
    if (t.size() > points.size())
        t.resize(points.size());
    if (t.size() < points.size()) {
        const std::vector<Point> rule = catmullRomTangents(points, settings);
        for (std::size_t i = t.size(); i < points.size(); ++i)
            t.push_back(rule[i]);
    }
    return t;
}

FamilyCurve computeFamilyCurve(const std::vector<Point>& points, const CatmullRomSettings& settings)
{
    FamilyCurve curve;
    curve.family = settings.family;
    curve.points = points;
    const CatmullRomMode mode = coreMode(settings.ends);
    const double alpha = spacingAlpha(settings.spacing);
    const int first = firstSegmentStart(settings.ends);
    const auto intervals = [&] { return familyShownSegments(catmullRomIntervals(points, mode, alpha), settings.ends); };
    switch (settings.family) {
    case CurveFamily::CatmullRom: return curve; // the τ curves of CatmullRomScene::curves
    case CurveFamily::Cardinal: {
        // The Catmull-Rom segments of τ = (1 − c)/2 (cardinal_spline.h).
        auto segs = cardinalHermiteSegments(points, toDouble(settings.cardinalTension), mode, alpha);
        if (!segs) {
            curve.error = translatedError(segs.error(), settings.ends);
            return curve;
        }
        curve.hermite = familyShownSegments(std::move(*segs), settings.ends);
        curve.intervals = intervals();
        break;
    }
    case CurveFamily::KochanekBartels: {
        std::vector<TcbKnot<double>> tcb;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const TcbKnot<Rational> k = tcbAt(settings, i);
            tcb.push_back({toDouble(k.tension), toDouble(k.continuity), toDouble(k.bias)});
        }
        auto kb = kochanekBartels(points, tcb, mode, alpha);
        if (!kb) {
            curve.error = translatedError(kb.error(), settings.ends);
            return curve;
        }
        curve.hermite = familyShownSegments(std::move(kb->segments), settings.ends);
        curve.intervals = intervals();
        break;
    }
    case CurveFamily::Hermite: {
        // Def 2.8 with the student's tangents, uniform: segment k joins its two points with
        // their tangents (as the Catmull-Rom segments of the same ends do).
        const std::vector<Point> t = hermiteTangentsOf(points, settings);
        const std::size_t n = points.size(), count = familySegmentCount(n, settings.ends);
        if (count == 0) {
            Error tooFew;
            tooFew.code = ErrorCode::TooFewPoints;
            curve.error = translatedError(tooFew, settings.ends);
            return curve;
        }
        for (std::size_t k = 0; k < count; ++k) {
            const std::size_t a = (static_cast<std::size_t>(first) + k) % n, b = (a + 1) % n;
            curve.hermite.push_back({points[a], points[b], t[a], t[b]});
        }
        break;
    }
    case CurveFamily::PlaneSpline:
        // cr-c2: the C² spline in the plane with its ends (parametric_spline.h) goes here.
        return curve;
    case CurveFamily::FunctionData:
        // cr-c2: function data y(x), natural / Catmull-Rom / Fritsch–Carlson / Steffen (monotone_spline.h), here.
        return curve;
    }
    curve.tangents = familyTangentsOf(curve.hermite, points.size(), first);
    finishFamilyCurve(curve, settings);
    return curve;
}

} // namespace granota::ui
