#pragma once
/// \file scene.h
/// A scene is data: a JSON file under resources/scenes naming the stage of chapter 4 (or
/// the future work of §5.2) it shows, the components it uses (docs/scenes.md vocabulary) and
/// the parameters of those components only. Only what a scene names is built, stepped,
/// drawn, shown as a parameter and written back to its file.

#include "core/base/expected.h"
#include "core/softbody/scenes/frog_params.h"
#include "core/softbody/scenes/stable_settings.h"
#include "core/softbody/scenes/grab_mode.h"
#include "core/softbody/scenes/scene_component.h"
#include "core/io/json.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace granota {

/// Which machinery a scene runs on.
enum class SceneModel {
    Stage,    ///< §4.1–4.5: explicit velocities (StageBody)
    Body,     ///< §4.6–4.12 and §5.2: Verlet soft bodies
    Pendulum, ///< §4.13–4.15: a chain of joints
    Frog,     ///< §4.16: body, four legs and head
};

struct ObstacleSpec {
    std::vector<Point> points; ///< a segment (2 points, open) or a closed polygon
    bool closed = false;
};

struct ShapeSpec {
    std::string name;
    std::vector<Point> points; ///< rest shape around (0, 0)
    Point at;                  ///< where it starts
};

struct SceneSpec {
    std::string name;        ///< CLI and file name, e.g. "bezier-revised"
    std::string section;     ///< the thesis's section, e.g. "4.10"
    std::string title;       ///< English title (the GUI translates it)
    std::string description; ///< one sentence
    SceneModel model = SceneModel::Body;
    int order = 0;                          ///< position in the thesis's order
    std::vector<SceneComponent> components; ///< in file order
    std::vector<std::string> paramKeys;     ///< the parameters this scene has, in file order

    FrogParams params;
    GrabMode grab = GrabMode::Anchors;
    int bodies = 1;            ///< many-bodies: how many
    int bezierSamples = 0;     ///< §4.9/4.10: vertices sampled from the Bézier curve
    int bezierFitDegree = 0;   ///< §4.9/4.10: degree of the per-frame least-squares fit
    std::vector<double> chain; ///< pendulum link lengths, px
    double chainShoulderMin = 0, chainShoulderMax = 0, chainElbowMin = 0, chainElbowMax = 0;
    std::vector<ObstacleSpec> obstacles;
    std::vector<ShapeSpec> shapes;
    /// Annex II derives the body from the frame: r = |height/6| in integer division (l. 175)
    /// and the centre (width/2, height/2) (l. 15, as SeedFrog.java divides). A scene file
    /// asks for that with "radius": "frame" and "center": "frame"; params then holds the
    /// derived value, which follows width and height until a number is set.
    bool radiusFromFrame = false;
    bool centerFromFrame = false;
    /// The frame those derived values come from. Annex II builds its frog in a field initialiser
    /// (l. 15), before setup() calls size(1280, 720) (l. 19): Processing's width and height are
    /// still their defaults, 100 × 100, so the sketch's true first frog has r = 100/6 = 16 at
    /// (50, 50). `"first_frame": "sketch"` (the file's top level) or `--set first_frame=sketch`
    /// asks for that, on the frog scene only; "window" (the default) derives them from width ×
    /// height, as the sketch's space-bar respawn and the reference trace do.
    bool sketchFirstFrame = false;
    /// The stable solver's substeps and edge stiffness (every scene has them; the seed
    /// ignores them). `--set substeps=16` and `--set edge_compliance=0.01` set them.
    StableSettings stable;

    bool has(SceneComponent component) const;
    bool hasParam(const std::string& key) const;
};

/// Every scene name in the thesis's order: polygon, gravity, …, frog, obstacles,
/// many-bodies, shapes.
std::vector<std::string> sceneNames();
Expected<SceneSpec> loadScene(const std::string& name);
Expected<SceneSpec> parseScene(const Json& doc);

/// Applies "key=value" (docs/scenes.md keys: gravity=gx,gy, friction=fx,fy, v0=vx,vy,
/// area_factor=C, sides=N, target_area=A, spring_length=L, velmax=V, center=x,y,
/// radius=r, width=W, height=H; and the scene's own: bodies, bezier_samples, …; on the
/// frog, first_frame=window|sketch, which also makes radius and centre derived again).
/// A key the scene does not have, a malformed value, or a value that makes no sense
/// (negative sides, a frame of zero size, more bodies than the frame holds side by side)
/// is an error with a message.
Expected<void> applySetting(SceneSpec& scene, const std::string& keyValue);

/// The scene with its parameter `key` set to `value` in the scene file's form (what `--set` and
/// a document's "params" give), checked as a scene file is, without writing the scene to JSON
/// and reading it back. A key the scene does not have, or a value it refuses, is an error with a
/// message; `scene` is taken by value and never half changed.
Expected<SceneSpec> withParameter(SceneSpec scene, const std::string& key, const Json& value);
/// As withParameter, for several keys at once (a document's "params"): all are set, then the
/// scene is checked once, so that keys that only make sense together (bodies and the frame
/// that holds them) are taken in any order.
Expected<SceneSpec> withParameters(SceneSpec scene, const std::vector<std::pair<std::string, Json>>& values);
/// One number of parameter `key` set to `value` and the scene checked: what one tick of the Frog
/// tab's parameter panel does, with no JSON on the way. `part` and `index` say which number
/// (parameterNumber, scene_parameters.h): the leg pair, the angle limit or the link, and the
/// coordinate; a whole number for Integer, the index of grabChoices() for Choice. Errors and
/// guarantees as withParameter; a part or index the parameter does not have is an error too.
Expected<SceneSpec> withParameter(SceneSpec scene, const std::string& key, int part, int index, double value);
/// The scene with parameter `key` as `source` has it (every number of it, and whether radius or
/// centre follow the frame), checked: what an undo of the panel's edits gives back.
Expected<SceneSpec> withParameterOf(SceneSpec scene, const SceneSpec& source, const std::string& key);
/// The scene with the stable solver's knobs of a scene file's "stable" object (a document's
/// "stable"), with the reader's checks and messages.
Expected<SceneSpec> withStableSettings(SceneSpec scene, const Json& stable);

/// `bodies` bodies at the scene's density: where the scene's frame was drawn for fewer,
/// it grows as frameForBodies() says (core/softbody/scenes/scene_layout.h) so that the bodies fit (a
/// thousand frogs do not fit in 1280 × 720 px; piled up, they would measure a pile, not the
/// broad phase, and cost seconds a step). `bench --bodies` and `--set bodies=N` both come
/// here. Errors as applySetting.
Expected<SceneSpec> withBodies(SceneSpec scene, int bodies);

/// The scene as its file: only its own keys, with their current values (scene_writer.cpp).
Json sceneToJson(const SceneSpec& scene);
/// How many times sceneToJson has run in this process: a test counts that a parameter tick
/// writes nothing (issue 35).
long sceneWriteCount();
/// The file's "stable" object: {"substeps": n, "edge_compliance": α[, "edge_damping_ratio": ζ
/// when not 0]} (sceneToJson writes it when the knobs differ from their defaults; a Frog
/// document always).
Json stableSettingsToJson(const StableSettings& stable);

/// The soft-body vertices the scene's bodies start with, all together: bodies × sides, or
/// × bezier_samples where §4.9 samples the body from a Bézier curve (the larger); what the
/// validation bounds by kMaxVertices (core/base/input_limits.h).
inline long sceneVertexCount(const SceneSpec& s)
{
    return static_cast<long>(s.bodies) * std::max(s.params.sides, s.bezierSamples);
}

} // namespace granota
