#include "ui/decasteljau/decasteljau_scene.h"

#include "core/curves/bezier/hodograph.h"

#include <algorithm>

namespace granota::ui {

namespace {

constexpr double kStepBudget = 2e7; ///< operations allowed for the step-by-step curves per update
constexpr int kMinStepSamples = 16;
constexpr int kSceneCombSamples = 160;      ///< teeth of the curvature comb
constexpr int kSceneHodographSamples = 120; ///< the hodograph's curve in its inset

} // namespace

DeCasteljauScene computeScene(const std::vector<Point>& points, const std::optional<std::vector<RPoint>>& exactPoints, double t,
                              const DeCasteljauView& view)
{
    DeCasteljauScene scene;
    scene.points = points;
    scene.exactPoints = exactPoints;
    scene.t = t;
    scene.view = view;
    if (points.empty())
        return scene;
    scene.curve = sampleBezier(points, view.samples + 1);
    if (view.stepByStep) {
        // n + 1 curves of 1…n + 1 points cost about n³/6 per sample: fewer samples at high degree.
        const double n = static_cast<double>(points.size());
        const int part = std::min(view.samples, std::max(kMinStepSamples, static_cast<int>(kStepBudget * 6.0 / (n * n * n))));
        for (std::size_t k = 1; k <= points.size(); ++k)
            scene.stepCurves.push_back(
                k == 1 ? std::vector<Point>{points[0]}
                       : sampleBezier(std::vector<Point>(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(k)),
                                      part + 1));
    }
    scene.finite = std::all_of(points.begin(), points.end(), [](const Point& q) { return isFinite(q); });
    if (scene.finite) {
        if (view.boundingBox || view.inflections)
            scene.features = curveFeatures(points);
        if (view.comb)
            scene.comb = curvatureComb(points, kSceneCombSamples, view.combScale);
        if (view.hodograph)
            scene.hodoCurve = sampleBezier(hodograph(points), kSceneHodographSamples + 1);
        scene.arc.emplace(points);
    }
    moveSceneTo(scene, t);
    return scene;
}

void moveSceneTo(DeCasteljauScene& scene, double t)
{
    scene.t = t;
    if (scene.points.empty())
        return;
    scene.levels = deCasteljau(scene.points, t);
    scene.curvature = curvatureAt(scene.points, t);
    scene.hodoLevels = scene.finite && scene.view.hodograph ? deCasteljau(hodograph(scene.points), t)
                                                            : DeCasteljauTable<double>{};
}


} // namespace granota::ui
