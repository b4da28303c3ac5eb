#pragma once
/// \file presentation_scale.h
/// Presentation mode (View ▸ Presentation mode, docs/classroom.md) makes what is drawn
/// readable from the back of a classroom: lines, handles, markers and the exact panels'
/// text grow by one factor, the same in every tab. (The main window enlarges the interface
/// font by its own factor; the widgets follow that font.)

namespace granota::ui {

/// How much larger lines, handles, markers and the exact panels' text are in presentation mode.
inline constexpr double kPresentationScale = 1.6;

/// The style scale for presentation mode `on`: kPresentationScale, else 1.
constexpr double presentationScale(bool on) { return on ? kPresentationScale : 1.0; }

} // namespace granota::ui
