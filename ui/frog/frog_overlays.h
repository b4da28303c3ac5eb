#pragma once
/// \file frog_overlays.h
/// What the Frog tab draws over the scene, and the one table of it: each overlay's key (the
/// document's name), where its flag lives in FrogOverlays, and the check box's label and tooltip.
/// The check boxes, the document (frog_document.h) and the translations read the table; no
/// other list of the overlays exists.

#include <array>

namespace granota::ui {

/// What is drawn over the scene (the tab's Overlays check boxes); FrogCanvas::Overlays.
struct FrogOverlays {
    bool vertices = false;   ///< body vertices and joints, numbered
    bool springs = false;    ///< the polygon's edges (the springs of §4.4)
    bool area = false;       ///< area against the target area (§4.5), text and bar
    bool velocities = false; ///< each vertex's displacement over the last step (Verlet's x − x_prev)
    bool readouts = false;   ///< the Readouts of the solver: area error, stretch, forces, energies
    bool frameTime = false;  ///< frame, step and drawing time
    /// Both solvers at once: the other solver's run of the same scene, fed the same mouse,
    /// drawn as a ghost over this one (docs/solvers.md#both-at-once).
    bool ghost = false;
    /// The path of one vertex or joint over the last kTrailSteps steps (Shift+click
    /// chooses which).
    bool trail = false;
    /// §5.2.2: the broad phase's candidate pairs (their boxes, a line between them) and
    /// the number of contacts (stable solver).
    bool pairs = false;
    /// §4.15: each link's angle against the range its limits allow (link_angles.h).
    bool protractor = false;

    bool operator==(const FrogOverlays& o) const;
    bool operator!=(const FrogOverlays& o) const { return !(*this == o); }
};

/// One overlay: its document key, its flag, and its check box's English label and tooltip,
/// marked for translation in kFrogOverlayContext (translated where they are shown).
struct FrogOverlay {
    const char* key;
    bool FrogOverlays::*flag;
    const char* label;
    const char* tip;
};

/// The translation context of the labels and tooltips: the tab that shows them.
inline constexpr const char* kFrogOverlayContext = "granota::ui::FrogTab";

inline constexpr std::size_t kFrogOverlayCount = 10;
/// Every overlay, in the order of the check boxes (frogOverlay0 … frogOverlay9) and the document.
const std::array<FrogOverlay, kFrogOverlayCount>& frogOverlays();

} // namespace granota::ui
