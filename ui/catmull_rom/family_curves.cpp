#include "ui/catmull_rom/family_curves.h"

#include "ui/catmull_rom/catmull_rom_curves.h"

namespace granota::ui {

namespace {

/// Samples, Bézier segments and κ(s) of the segments already in `curve`.
void finishFamilyCurve(FamilyCurve& curve, const CatmullRomSettings& settings)
{
    if (curve.segments.empty())
        return;
    if (curve.intervals.size() != curve.segments.size())
        curve.intervals.assign(curve.segments.size(), 1.0);
    curve.samples = sampleSegments(curve.segments, CatmullRomScene::kSamplesPerSegment);
    curve.bezier = bezierSegments(curve.segments);
    if (settings.curvaturePlot)
        curve.curvature = curvatureProfile(controlPolygons(curve.bezier), CatmullRomScene::kSamplesPerSegment);
}

} // namespace

FamilyCurve computeFamilyCurve(const std::vector<Point>& points, const CatmullRomSettings& settings)
{
    FamilyCurve curve;
    curve.family = settings.family;
    curve.points = points;
    switch (settings.family) {
    case CurveFamily::CatmullRom: return curve; // the τ curves of CatmullRomScene::curves
    case CurveFamily::Cardinal:
    case CurveFamily::KochanekBartels:
    case CurveFamily::Hermite: break;
    case CurveFamily::PlaneSpline:
    case CurveFamily::FunctionData:
        // Several curves each: CatmullRomScene::planeSpline and ::functionData (plane_spline_curves.h,
        // function_data_curves.h), computed by computeScene.
        return curve;
    }
    finishFamilyCurve(curve, settings);
    return curve;
}

} // namespace granota::ui
