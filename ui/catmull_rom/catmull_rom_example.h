#pragma once
/// \file catmull_rom_example.h
/// The thesis's worked examples on the Catmull-Rom tab (docs/tabs.md): Ex 2.1's cubic spline
/// alone, as Fig 2.1; Ex 2.11's single segment with τ ∈ {0, 1/2, 2}; Ex 2.12's blending
/// functions of every τ, on the points already there; Ex 2.13's curve in its end mode, compared
/// with the other one. What an example makes of the points and the settings, without a widget:
/// the tab loads the result as one undo step.

#include "core/io/worked_examples.h"
#include "ui/catmull_rom/catmull_rom_settings.h"

#include <optional>
#include <vector>

namespace granota::ui {

struct CatmullRomExampleState {
    std::vector<Point> points;
    CatmullRomSettings settings;
};

/// The points and settings after loading `example` over the current `points` and `settings`
/// (what the example does not set keeps its value); nullopt when it is no Catmull-Rom example,
/// or its tensions or points are beyond the tab's limits (CatmullRomSettings).
std::optional<CatmullRomExampleState> catmullRomExample(const WorkedExample& example, const std::vector<Point>& points,
                                                        const CatmullRomSettings& settings);

} // namespace granota::ui
