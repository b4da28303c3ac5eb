#pragma once
/// \file frame_derived.h
/// The body Annex II derives from its window: the radius r = |height/6| (l. 175, Java's
/// integer division, as Processing's `height` is an int) and the centre (width/2, height/2)
/// (l. 15; SeedFrog.java divides by 2f, which this follows). A scene file asks for them
/// with "radius": "frame" and "center": "frame" (docs/scenes.md).

#include "core/base/vec2.h"

namespace granota {

struct SceneSpec;

/// The word a scene file gives instead of a number for a value derived from the frame.
inline constexpr const char* kFromFrame = "frame";

/// `first_frame` (scene.h, SceneSpec::sketchFirstFrame): which frame the derived values come
/// from, "window" (width × height) or "sketch" (Processing's default frame, before size()).
inline constexpr const char* kFirstFrameKey = "first_frame";
inline constexpr const char* kWindowFrame = "window";
inline constexpr const char* kSketchFrame = "sketch";
/// Processing's width and height before size() is called (PApplet's DEFAULT_WIDTH and
/// DEFAULT_HEIGHT): the frame Annex II's frog is built in.
inline constexpr double kSketchDefaultSize = 100;

/// |trunc(height) / 6| in whole numbers, as `abs(height/6)` computes with an int height.
/// A height beyond ±1e15 (refused later by the scene's checks) gives 0.
double frameRadius(double height);
/// (trunc(width) / 2, trunc(height) / 2), halves kept.
Point frameCenter(double width, double height);

/// Writes the derived radius and centre into scene.params where the scene asks for them, from
/// width × height, or from the 100 × 100 default frame when scene.sketchFirstFrame.
void deriveFromFrame(SceneSpec& scene);

} // namespace granota
