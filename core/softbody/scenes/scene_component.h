#pragma once
/// \file scene_component.h
/// The machinery a scene names (docs/scenes.md, "Components"): each one is built, stepped
/// and drawn only in a scene that lists it. Scene files write their names; an unknown name
/// is refused with a message naming it, so a typo such as "outline-bezer" never silently
/// leaves the outline out.

#include "core/base/enum_names.h"

#include <array>
#include <optional>
#include <string_view>

namespace granota {

enum class SceneComponent {
    Gravity,           ///< §4.2: g added every step
    Bounds,            ///< §4.2: the frame (the body's vertices, the legs' wrists)
    LegsInFrame,       ///< beyond the seed: every leg joint kept in the frame on the seed solver
    Bounce,            ///< §4.3: walls reverse and damp the velocity
    Springs,           ///< §4.4: edge springs towards a rest length
    Area,              ///< §4.5: the area correction
    Grab,              ///< §4.6–4.7: the mouse grabs a body
    Legs,              ///< §4.13–4.16: the frog's legs, or the pendulum's chain
    AngleLimits,       ///< §4.15: limits on the joints' angles
    Fill,              ///< §4.8: the body is filled
    OutlineBezier,     ///< §4.9/4.10: the body's vertices from a Bézier curve
    OutlineCatmullRom, ///< §4.12: a Catmull-Rom outline through the vertices
    Head,              ///< §4.16: the frog's head
    Obstacles,         ///< §5.2.1: fixed segments and polygons
    Collisions,        ///< §5.2.2: contacts between bodies
};

inline constexpr std::array<EnumName<SceneComponent>, 15> kSceneComponentNames{{
    {SceneComponent::Gravity, "gravity"},
    {SceneComponent::Bounds, "bounds"},
    {SceneComponent::LegsInFrame, "legs-in-frame"},
    {SceneComponent::Bounce, "bounce"},
    {SceneComponent::Springs, "springs"},
    {SceneComponent::Area, "area"},
    {SceneComponent::Grab, "grab"},
    {SceneComponent::Legs, "legs"},
    {SceneComponent::AngleLimits, "angle-limits"},
    {SceneComponent::Fill, "fill"},
    {SceneComponent::OutlineBezier, "outline-bezier"},
    {SceneComponent::OutlineCatmullRom, "outline-catmull-rom"},
    {SceneComponent::Head, "head"},
    {SceneComponent::Obstacles, "obstacles"},
    {SceneComponent::Collisions, "collisions"},
}};

/// The name a scene file writes ("outline-bezier").
constexpr std::string_view sceneComponentName(SceneComponent c) { return nameOf(kSceneComponentNames, c); }
/// The component a scene file names; nullopt for an unknown name (exact spelling only).
inline std::optional<SceneComponent> sceneComponentNamed(std::string_view name) { return parseName(kSceneComponentNames, name); }

} // namespace granota
