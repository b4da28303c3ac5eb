#include "core/softbody/scenes/frame_derived.h"

#include "core/softbody/scenes/scene.h"

#include <cmath>
#include <cstdlib>

namespace granota {

namespace {

/// Processing's int of a frame size; 0 where the value could not be one.
long long frameInt(double v) { return std::isfinite(v) && std::fabs(v) <= 1e15 ? static_cast<long long>(v) : 0; }

} // namespace

double frameRadius(double height) { return static_cast<double>(std::llabs(frameInt(height) / 6)); }

Point frameCenter(double width, double height)
{
    return {static_cast<double>(frameInt(width)) / 2, static_cast<double>(frameInt(height)) / 2};
}

void deriveFromFrame(SceneSpec& scene)
{
    const double width = scene.sketchFirstFrame ? kSketchDefaultSize : scene.params.width;
    const double height = scene.sketchFirstFrame ? kSketchDefaultSize : scene.params.height;
    if (scene.radiusFromFrame)
        scene.params.radius = frameRadius(height);
    if (scene.centerFromFrame)
        scene.params.center = frameCenter(width, height);
}

} // namespace granota
