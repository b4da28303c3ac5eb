#pragma once
/// \file frog_document.h
/// The Frog tab's part of a .granota document (its "frog" object, docs/documents.md): the stage
/// and its parameters, the solver and the knobs its run started with, the overlays, the Bézier
/// outline, pause and speed, the ruler, and the recorded run. A plain struct that reads and
/// writes that object and checks it whole, with a translated message for what it refuses; the
/// tab (frog_tab.h) shows what it read. Nothing here needs a window.

#include "core/base/expected.h"
#include "core/base/vec2.h"
#include "core/softbody/recorded_run.h"
#include "core/softbody/scenes/scene.h"
#include "core/softbody/simulation.h"
#include "ui/frog/frog_overlays.h"

#include <QJsonObject>
#include <QString>

#include <optional>
#include <utility>

namespace granota::ui {

struct FrogDocument {
    /// The stage with its parameters, and in `scene.stable` the knobs the run started with.
    SceneSpec scene;
    SolverKind solver = SolverKind::Seed;
    FrogOverlays overlays;
    bool fitOutline = false; ///< §4.9: "bezier_outline" is "fit" (else "precomputed")
    bool paused = false;
    double speed = 1;                             ///< one of StepPacer::kSpeeds
    std::optional<std::pair<Point, Point>> ruler; ///< its two ends, scene px
    /// The run read from "recording" (fromJson only: toJson writes the run itself).
    std::optional<DocumentRun> recording;

    /// The "frog" object: every field, and `run` as "recording" when given.
    QJsonObject toJson(const RecordedRun* run) const;
    /// Reads `state` (a "frog" object). "scene" names the stage (its file gives the parameters
    /// "params" does not); the solver is the seed unless named; overlays, outline, pause, speed
    /// and the knobs the state lacks are `current`'s; no ruler or recording unless given. Nothing
    /// when a value is refused, with the message in `error`.
    static std::optional<FrogDocument> fromJson(const QJsonObject& state, const FrogDocument& current, QString* error);
};

/// Why the scene `name` did not load: unknown (listing the scenes), or the core's own message for
/// a known one (FrogTab::sceneLoadError).
QString frogSceneLoadError(const QString& name, const Error& coreError);

} // namespace granota::ui
