#pragma once
/// \file tension_colour.h
/// The colour of a Catmull-Rom curve is a fixed function of its tension τ, not of its place
/// in the list: adding or removing a τ never recolours the others, the same τ has the same
/// colour in every document and export, and dragging τ with the slider moves its colour
/// smoothly along the scale. The hue runs from magenta (τ = −10) through violet, blue
/// (τ = 0), green (τ = 1/2) and yellow to red (τ = 10), linearly between the anchors below,
/// which are spread so that the tensions of Ex 2.11 (0, 1/2, 2) and Ex 2.12 (−2, 0, 1/2, 2)
/// fall on clearly different hues.

#include "ui/catmull_rom/catmull_rom_settings.h"

#include <QColor>

#include <algorithm>
#include <array>
#include <utility>

namespace granota::ui {

/// The colour of the curves (canvas, plots, key, TikZ) of tension `tau`.
inline QColor tensionColour(double tau)
{
    // (τ, hue in degrees): decreasing hue, never wrapping round, so that a hue names one τ.
    static constexpr std::array<std::pair<double, double>, 9> kAnchors{{{-CatmullRomSettings::kMaxTensionAbs, 300},
                                                                        {-2, 270},
                                                                        {-1, 250},
                                                                        {-0.5, 232},
                                                                        {0, 210},
                                                                        {0.5, 135},
                                                                        {1, 85},
                                                                        {2, 30},
                                                                        {CatmullRomSettings::kMaxTensionAbs, 0}}};
    const double t = std::clamp(tau, kAnchors.front().first, kAnchors.back().first);
    double hue = kAnchors.back().second;
    for (std::size_t i = 1; i < kAnchors.size(); ++i)
        if (t <= kAnchors[i].first) {
            const auto [t0, h0] = kAnchors[i - 1];
            const auto [t1, h1] = kAnchors[i];
            hue = h0 + (h1 - h0) * (t - t0) / (t1 - t0);
            break;
        }
    // Saturated and darkish: readable on white and in print (yellow becomes olive).
    return QColor::fromHsvF(static_cast<float>(hue / 360.0), 0.85f, 0.78f);
}

inline QColor tensionColour(const Rational& tau) { return tensionColour(toDouble(tau)); }

} // namespace granota::ui
