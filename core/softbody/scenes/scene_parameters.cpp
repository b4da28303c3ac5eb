#include "core/softbody/scenes/scene_parameters.h"

#include "core/softbody/scenes/scene.h"
#include "core/softbody/scenes/translatable_text.h"

namespace granota {

namespace {

constexpr int kMaxBodies = 5000;
constexpr int kMaxBezierSamples = 2000;

SceneParameter row(const char* key, ParameterType type, const char* thesisName, const char* unit, SpinRange spin,
                   const char* label, const char* tip)
{
    SceneParameter p;
    p.key = key;
    p.type = type;
    p.thesisName = thesisName;
    p.unit = unit;
    p.spin = spin;
    p.label = label;
    p.tip = tip;
    return p;
}

SceneParameter integer(const char* key, const char* thesisName, int min, int max, SpinRange spin, const char* label,
                       const char* tip, int& (*field)(SceneSpec&))
{
    SceneParameter p = row(key, ParameterType::Integer, thesisName, "", spin, label, tip);
    p.min = min;
    p.max = max;
    p.integer = field;
    return p;
}

SceneParameter number(const char* key, const char* thesisName, const char* unit, SpinRange spin, const char* label,
                      const char* tip, double& (*field)(SceneSpec&))
{
    SceneParameter p = row(key, ParameterType::Number, thesisName, unit, spin, label, tip);
    p.number = field;
    return p;
}

SceneParameter pair(const char* key, const char* thesisName, const char* unit, SpinRange spin, const char* label,
                    const char* tip, Point& (*field)(SceneSpec&))
{
    SceneParameter p = row(key, ParameterType::Pair, thesisName, unit, spin, label, tip);
    p.pair = field;
    return p;
}

SceneParameter fileOnly(const char* key, ParameterType type, const char* fileNote)
{
    SceneParameter p = row(key, type, "", "", {}, "", "");
    p.fileNote = fileNote;
    return p;
}

/// `width` and `height` share their tooltip.
constexpr const char* kFrameTip = QT_TRANSLATE_NOOP(
    "granota::ui::FrogParametersPanel",
    "The frame (Processing's size(1280, 720)): vertices stay inside [0, width − 1] × [0, height − 1] (§4.2).");
constexpr const char* kShoulderTip =
    QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                      "anglesc: smallest and largest angle of the upper segment at the shoulder, in degrees "
                      "(§4.15; Annex II uses 0 to π and −π to 0).");
constexpr const char* kElbowTip =
    QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                      "angles: smallest and largest angle between the two segments at the elbow, in degrees "
                      "(§4.15; Annex II uses ±π/12 in front, ±π/3 behind).");

Point shoulder(const SceneSpec& s, std::size_t leg)
{
    return Point(s.params.legs[leg].shoulderMin, s.params.legs[leg].shoulderMax);
}

void setShoulder(SceneSpec& s, std::size_t leg, Point q)
{
    s.params.legs[leg].shoulderMin = q.x;
    s.params.legs[leg].shoulderMax = q.y;
}

/// An elbow limit is one pair of legs' (front: legs 0 and 1; back: 2 and 3); the file holds leg `first`'s.
void setElbows(SceneSpec& s, std::size_t first, Point q)
{
    for (std::size_t i : {first, first + 1}) {
        s.params.legs[i].elbowMin = q.x;
        s.params.legs[i].elbowMax = q.y;
    }
}

} // namespace

bool SceneParameter::settable() const
{
    return type == ParameterType::Integer || type == ParameterType::Number || type == ParameterType::Pair ||
           type == ParameterType::Choice;
}

const std::vector<SceneParameter>& sceneParameters()
{
    using T = ParameterType;
    static const std::vector<SceneParameter> table = {
        integer("sides", "N (costats)", 3, 10000, {3, 10000, 0, 1},
                QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Sides N"),
                QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                                  "N (costats): the vertices of the body, a regular polygon built from the top (§4.1). "
                                  "Annex II's frog has N = 10; try 3 to 200. Up to 10000, 100000 vertices in all: beyond about 3000 "
                                  "the stable solver runs slower than real time."),
                [](SceneSpec& s) -> int& { return s.params.sides; }),
        pair("gravity", "g (gravetat)", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px/step²"),
             {-1e6, 1e6, 2, 0.05}, QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Gravity g (x, y)"),
             QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                               "g (gravetat): acceleration added to every vertex each step, v(t) = v(t − 1) + g (§4.2)."),
             [](SceneSpec& s) -> Point& { return s.params.gravity; }),
        pair("friction", "f (fregament)", "", {-10, 10, 3, 0.01},
             QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Friction f (x, y)"),
             QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                               "f (fregament): share of the velocity kept per step on each axis, f ∈ ]0, 1[ (§4.3)."),
             [](SceneSpec& s) -> Point& { return s.params.friction; }),
        pair("v0", "v⁰ (velocitat inicial)", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px/step"),
             {-1e6, 1e6, 2, 0.5}, QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Initial velocity v₀ (x, y)"),
             QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                               "v⁰ (velocitat inicial): the velocity the body starts with (§4.2)."),
             [](SceneSpec& s) -> Point& { return s.params.v0; }),
        pair("center", "(c₁, c₂)", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px"), {-1e6, 1e6, 1, 10},
             QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Centre (x, y)"),
             QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                               "(c₁, c₂): where the first body starts, in pixels of the frame (y grows downwards)."),
             [](SceneSpec& s) -> Point& { return s.params.center; }),
        number("area_factor", "C (reescala)", "", {-1e6, 1e6, 3, 0.01},
               QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Area factor C"),
               QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                                 "C (reescala): how strongly each step corrects the area; large values make a stiff body (§4.5)."),
               [](SceneSpec& s) -> double& { return s.params.areaFactor; }),
        number("target_area", "Areal", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px²"), {0, 1e12, 0, 1000},
               QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Target area"),
               QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                                 "Areal: the area the body tries to keep, by the trapezoid rule and edge normals (§4.5). "
                                 "0 or huge values are allowed."),
               [](SceneSpec& s) -> double& { return s.params.targetArea; }),
        number("spring_length", "molls", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px"), {0, 1e6, 2, 1},
               QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Spring length"),
               QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                                 "molls: rest length of every edge spring; the springs pull the edges back towards it (§4.4)."),
               [](SceneSpec& s) -> double& { return s.params.springLength; }),
        number("velmax", "velmax", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px/step"), {0, 1e9, 1, 1},
               QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Largest move velmax"),
               QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                                 "velmax: the largest move of a vertex in one step, per axis (Annex II)."),
               [](SceneSpec& s) -> double& { return s.params.velmax; }),
        number("radius", "r", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px"), {0, 1e6, 1, 5},
               QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Radius r"),
               QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                                 "r: distance from the centre to each vertex of the starting polygon (§4.1)."),
               [](SceneSpec& s) -> double& { return s.params.radius; }),
        number("width", "", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px"), {1, 100000, 0, 10},
               QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Frame width"), kFrameTip,
               [](SceneSpec& s) -> double& { return s.params.width; }),
        number("height", "", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px"), {1, 100000, 0, 10},
               QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Frame height"), kFrameTip,
               [](SceneSpec& s) -> double& { return s.params.height; }),
        integer("bodies", "", 1, kMaxBodies, {1, 1000, 0, 1}, QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Bodies"),
                QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                                  "How many bodies fall and collide (§5.2.2); a broad phase keeps the cost close to linear."),
                [](SceneSpec& s) -> int& { return s.bodies; }),
        integer("bezier_samples", "", 3, kMaxBezierSamples, {3, 2000, 0, 1},
                QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Bézier points"),
                QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                                  "§4.9: the polygon is the control polygon of one Bézier curve, sampled once at this many points by "
                                  "De Casteljau (Def 2.4); the samples become the body's vertices."),
                [](SceneSpec& s) -> int& { return s.bezierSamples; }),
        integer("bezier_fit_degree", "n", 1, 30, {1, 30, 0, 1},
                QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Fit degree n"),
                QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                                  "§4.9, the abandoned option: the degree n of the least-squares Bézier curve fitted to the outline "
                                  "every frame (Lemma 2.2, Prop 2.2)."),
                [](SceneSpec& s) -> int& { return s.bezierFitDegree; }),
        row("grab", T::Choice, "", "", {}, QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Grab"),
            QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                              "Which vertices hold on to the mouse: all of them (§4.6), those above the grab point (§4.7), "
                              "or Annex II's fixed anchors {0, 1, N−1, N} (§4.10).")),
        row("chain", T::Chain, "", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px"), {0, 1e4, 1, 5},
            QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Link %1"),
            QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                              "Length of this link of the pendulum; the links keep their length exactly (§4.13, §4.14).")),
        row("legs", T::Legs, "longit", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px"), {0, 1e4, 1, 5}, "",
            QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                              "longit: lengths of the two segments of each leg, shoulder–elbow and elbow–wrist (§4.16, Annex II).")),
        row("angle_limits", T::AngleLimits, "anglesc (shoulder), angles (elbow)", "°", {-3600, 3600, 1, 5}, "", ""),
        fileOnly("obstacles", T::Obstacles,
                 QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "The obstacles come from the scene file.")),
        fileOnly("shapes", T::Shapes,
                 QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "The shapes of the bodies come from the scene file.")),
    };
    return table;
}

const SceneParameter* findSceneParameter(const std::string& key)
{
    for (const SceneParameter& p : sceneParameters())
        if (key == p.key)
            return &p;
    return nullptr;
}

const std::vector<ParameterPart>& legParts()
{
    static const std::vector<ParameterPart> parts = {
        {"front", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Front legs (upper, lower)")},
        {"back", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Back legs (upper, lower)")},
    };
    return parts;
}

const std::vector<AngleLimit>& angleLimits()
{
    static const std::vector<AngleLimit> limits = {
        {"shoulder_front_right", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Front right shoulder (min, max)"),
         kShoulderTip, false, [](const SceneSpec& s) { return shoulder(s, 0); },
         [](SceneSpec& s, Point q) { setShoulder(s, 0, q); }},
        {"shoulder_front_left", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Front left shoulder (min, max)"),
         kShoulderTip, false, [](const SceneSpec& s) { return shoulder(s, 1); },
         [](SceneSpec& s, Point q) { setShoulder(s, 1, q); }},
        {"shoulder_back_right", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Back right shoulder (min, max)"),
         kShoulderTip, false, [](const SceneSpec& s) { return shoulder(s, 2); },
         [](SceneSpec& s, Point q) { setShoulder(s, 2, q); }},
        {"shoulder_back_left", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Back left shoulder (min, max)"),
         kShoulderTip, false, [](const SceneSpec& s) { return shoulder(s, 3); },
         [](SceneSpec& s, Point q) { setShoulder(s, 3, q); }},
        {"elbow_front", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Front elbows (min, max)"), kElbowTip, false,
         [](const SceneSpec& s) { return Point(s.params.legs[0].elbowMin, s.params.legs[0].elbowMax); },
         [](SceneSpec& s, Point q) { setElbows(s, 0, q); }},
        {"elbow_back", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Back elbows (min, max)"), kElbowTip, false,
         [](const SceneSpec& s) { return Point(s.params.legs[2].elbowMin, s.params.legs[2].elbowMax); },
         [](SceneSpec& s, Point q) { setElbows(s, 2, q); }},
        {"shoulder", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Shoulder (min, max)"), kShoulderTip, true,
         [](const SceneSpec& s) { return Point(s.chainShoulderMin, s.chainShoulderMax); },
         [](SceneSpec& s, Point q) {
             s.chainShoulderMin = q.x;
             s.chainShoulderMax = q.y;
         }},
        {"elbow", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Elbow (min, max)"), kElbowTip, true,
         [](const SceneSpec& s) { return Point(s.chainElbowMin, s.chainElbowMax); },
         [](SceneSpec& s, Point q) {
             s.chainElbowMin = q.x;
             s.chainElbowMax = q.y;
         }},
    };
    return limits;
}

const std::vector<GrabChoice>& grabChoices()
{
    static const std::vector<GrabChoice> choices = {
        {"all", GrabMode::All, QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "All vertices (§4.6)")},
        {"above", GrabMode::Above, QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Vertices above the mouse (§4.7)")},
        {"anchors", GrabMode::Anchors,
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Fixed anchors {0, 1, N−1, N} (§4.10)")},
    };
    return choices;
}

} // namespace granota
