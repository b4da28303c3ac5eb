#include "core/softbody/scenes/scene_parameters.h"

#include "core/softbody/scenes/scene.h"
#include "core/softbody/scenes/translatable_text.h"

#include <algorithm>

namespace granota {

namespace {

constexpr int kMaxBodies = 5000;
constexpr int kMaxBezierSamples = 2000;

/// The units the panel shows, translated there.
constexpr const char* kNoUnit = "";
constexpr const char* kPx = QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px");
constexpr const char* kPxSquared = QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px²");
constexpr const char* kPxPerStep = QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px/step");
constexpr const char* kPxPerStep2 = QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "px/step²");
constexpr const char* kNoNote = "";
/// SpinRange::symmetric: from −max to max, or from min.
constexpr bool kSymmetric = true;
constexpr bool kFromMin = false;

ParameterField at(int FrogParams::*frog) { return {frog, nullptr, nullptr, nullptr}; }
ParameterField at(int SceneSpec::*scene) { return {nullptr, scene, nullptr, nullptr}; }
ParameterField at(double FrogParams::*number) { return {nullptr, nullptr, number, nullptr}; }
ParameterField at(Point FrogParams::*pair) { return {nullptr, nullptr, nullptr, pair}; }

constexpr const char* kShoulderTip = QT_TRANSLATE_NOOP(
    "granota::ui::FrogParametersPanel", "anglesc: smallest and largest angle of the upper segment at the shoulder, in degrees "
                                        "(§4.15; Annex II uses 0 to π and −π to 0).");
constexpr const char* kElbowTip = QT_TRANSLATE_NOOP(
    "granota::ui::FrogParametersPanel", "angles: smallest and largest angle between the two segments at the elbow, in degrees "
                                        "(§4.15; Annex II uses ±π/12 in front, ±π/3 behind).");

} // namespace

int& SceneParameter::integerIn(SceneSpec& s) const
{
    return field.frogInteger ? s.params.*field.frogInteger : s.*field.sceneInteger;
}

double& SceneParameter::numberIn(SceneSpec& s) const { return s.params.*field.number; }

Point& SceneParameter::pairIn(SceneSpec& s) const { return s.params.*field.pair; }

bool SceneParameter::settable() const
{
    return type == ParameterType::Integer || type == ParameterType::Number || type == ParameterType::Pair ||
           type == ParameterType::Choice;
}

const std::vector<SceneParameter>& sceneParameters()
{
    // Each row: key, type, thesis name, unit, the whole numbers accepted, the panel's spin box, where the
    // value lives; the panel's label; its tooltip; the file-only note.
    using T = ParameterType;
    static const std::vector<SceneParameter> table = {
        {"sides",
         T::Integer,
         "N (costats)",
         kNoUnit,
         3,
         10000,
         {kFromMin, 3, 10000, 0, 1},
         at(&FrogParams::sides),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Sides N"),
         QT_TRANSLATE_NOOP(
             "granota::ui::FrogParametersPanel",
             "N (costats): the vertices of the body, a regular polygon built from the top (§4.1). Annex II's frog has N = 10; "
             "try 3 to 200. Up to 10000, 100000 vertices in all: beyond about 3000 the stable solver runs slower than real time."),
         kNoNote},
        {"gravity",
         T::Pair,
         "g (gravetat)",
         kPxPerStep2,
         0,
         0,
         {kSymmetric, 0, 1e6, 2, 0.05},
         at(&FrogParams::gravity),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Gravity g (x, y)"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "g (gravetat): acceleration added to every "
                                                               "vertex each step, v(t) = v(t − 1) + g (§4.2)."),
         kNoNote},
        {"friction",
         T::Pair,
         "f (fregament)",
         kNoUnit,
         0,
         0,
         {kSymmetric, 0, 10, 3, 0.01},
         at(&FrogParams::friction),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Friction f (x, y)"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "f (fregament): share of the velocity kept "
                                                               "per step on each axis, f ∈ ]0, 1[ (§4.3)."),
         kNoNote},
        {"v0",
         T::Pair,
         "v⁰ (velocitat inicial)",
         kPxPerStep,
         0,
         0,
         {kSymmetric, 0, 1e6, 2, 0.5},
         at(&FrogParams::v0),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Initial velocity v₀ (x, y)"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "v⁰ (velocitat inicial): the velocity "
                                                               "the body starts with (§4.2)."),
         kNoNote},
        {"center",
         T::Pair,
         "(c₁, c₂)",
         kPx,
         0,
         0,
         {kSymmetric, 0, 1e6, 1, 10},
         at(&FrogParams::center),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Centre (x, y)"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                           "(c₁, c₂): where the first body starts, in pixels of the frame (y grows downwards). Annex II "
                           "starts at the frame’s centre, and so does the scene until a value is set here."),
         kNoNote},
        {"area_factor",
         T::Number,
         "C (reescala)",
         kNoUnit,
         0,
         0,
         {kSymmetric, 0, 1e6, 3, 0.01},
         at(&FrogParams::areaFactor),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Area factor C"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "C (reescala): how strongly each step corrects "
                                                               "the area; large values make a stiff body (§4.5)."),
         kNoNote},
        {"target_area",
         T::Number,
         "Areal",
         kPxSquared,
         0,
         0,
         {kFromMin, 0, 1e12, 0, 1000},
         at(&FrogParams::targetArea),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Target area"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Areal: the area the body tries to keep, by the trapezoid "
                                                               "rule and edge normals (§4.5). 0 or huge values are allowed."),
         kNoNote},
        {"spring_length",
         T::Number,
         "molls",
         kPx,
         0,
         0,
         {kFromMin, 0, 1e6, 2, 1},
         at(&FrogParams::springLength),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Spring length"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "molls: rest length of every edge spring; the "
                                                               "springs pull the edges back towards it (§4.4)."),
         kNoNote},
        {"velmax",
         T::Number,
         "velmax",
         kPxPerStep,
         0,
         0,
         {kFromMin, 0, 1e9, 1, 1},
         at(&FrogParams::velmax),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Largest move velmax"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "velmax: the largest move of a vertex "
                                                               "in one step, per axis (Annex II)."),
         kNoNote},
        {"radius",
         T::Number,
         "r",
         kPx,
         0,
         0,
         {kFromMin, 0, 1e6, 1, 5},
         at(&FrogParams::radius),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Radius r"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                           "r: distance from the centre to each vertex of the starting polygon (§4.1). Annex II takes "
                           "r = |height/6| from the frame, and so does the scene until a value is set here."),
         kNoNote},
        {"width",
         T::Number,
         "",
         kPx,
         0,
         0,
         {kFromMin, 1, 100000, 0, 10},
         at(&FrogParams::width),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Frame width"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "The frame (Processing's size(1280, 720)): vertices "
                                                               "stay inside [0, width − 1] × [0, height − 1] (§4.2)."),
         kNoNote},
        {"height",
         T::Number,
         "",
         kPx,
         0,
         0,
         {kFromMin, 1, 100000, 0, 10},
         at(&FrogParams::height),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Frame height"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "The frame (Processing's size(1280, 720)): vertices "
                                                               "stay inside [0, width − 1] × [0, height − 1] (§4.2)."),
         kNoNote},
        {"bodies",
         T::Integer,
         "",
         kNoUnit,
         1,
         kMaxBodies,
         {kFromMin, 1, 1000, 0, 1},
         at(&SceneSpec::bodies),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Bodies"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "How many bodies fall and collide (§5.2.2); a "
                                                               "broad phase keeps the cost close to linear."),
         kNoNote},
        {"bezier_samples",
         T::Integer,
         "",
         kNoUnit,
         3,
         kMaxBezierSamples,
         {kFromMin, 3, 2000, 0, 1},
         at(&SceneSpec::bezierSamples),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Bézier points"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                           "§4.9: the polygon is the control polygon of one Bézier curve, sampled once at this "
                           "many points by De Casteljau (Def 2.4); the samples become the body's vertices."),
         kNoNote},
        {"bezier_fit_degree",
         T::Integer,
         "n",
         kNoUnit,
         1,
         30,
         {kFromMin, 1, 30, 0, 1},
         at(&SceneSpec::bezierFitDegree),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Fit degree n"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                           "§4.9, the abandoned option: the degree n of the least-squares Bézier "
                           "curve fitted to the outline every frame (Lemma 2.2, Prop 2.2)."),
         kNoNote},
        {"grab",
         T::Choice,
         "",
         kNoUnit,
         0,
         0,
         {},
         {},
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Grab"),
         QT_TRANSLATE_NOOP(
             "granota::ui::FrogParametersPanel",
             "Which vertices hold on to the mouse: all of them (§4.6), those above the grab point (§4.7), or Annex II's fixed anchors {0, 1, N−1, N} (§4.10)."),
         kNoNote},
        {"chain",
         T::Chain,
         "",
         kPx,
         0,
         0,
         {kFromMin, 0, 1e4, 1, 5},
         {},
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Link %1"),
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                           "Length of this link of the pendulum; the links keep their length exactly (§4.13, §4.14)."),
         kNoNote},
        {"legs",
         T::Legs,
         "longit",
         kPx,
         0,
         0,
         {kFromMin, 0, 1e4, 1, 5},
         {},
         "", // the labels are legParts()'
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel",
                           "longit: lengths of the two segments of each leg, shoulder–elbow and elbow–wrist (§4.16, Annex II)."),
         kNoNote},
        // The labels and tips are angleLimits()'.
        {"angle_limits",
         T::AngleLimits,
         "anglesc (shoulder), angles (elbow)",
         "°",
         0,
         0,
         {kSymmetric, 0, 3600, 1, 5},
         {},
         "",
         "",
         kNoNote},
        {"obstacles",
         T::Obstacles,
         "",
         kNoUnit,
         0,
         0,
         {},
         {},
         "",
         "",
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "The obstacles come from the scene file.")},
        {"shapes",
         T::Shapes,
         "",
         kNoUnit,
         0,
         0,
         {},
         {},
         "",
         "",
         QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "The shapes of the bodies come from the scene file.")},
    };
    return table;
}

const SceneParameter* findSceneParameter(const std::string& key)
{
    const auto& all = sceneParameters();
    const auto it = std::find_if(all.begin(), all.end(), [&](const SceneParameter& x) { return key == x.key; });
    return it == all.end() ? nullptr : &*it;
}

const std::vector<ParameterPart>& legParts()
{
    static const std::vector<ParameterPart> parts = {
        {"front", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Front legs (upper, lower)")},
        {"back", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Back legs (upper, lower)")},
    };
    return parts;
}

const std::vector<AngleLimitParameter>& angleLimits()
{
    using J = AngleLimitParameter::Joint;
    static const std::vector<AngleLimitParameter> limits = {
        {"shoulder_front_right", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Front right shoulder (min, max)"),
         kShoulderTip, J::Shoulder, 0},
        {"shoulder_front_left", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Front left shoulder (min, max)"),
         kShoulderTip, J::Shoulder, 1},
        {"shoulder_back_right", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Back right shoulder (min, max)"),
         kShoulderTip, J::Shoulder, 2},
        {"shoulder_back_left", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Back left shoulder (min, max)"),
         kShoulderTip, J::Shoulder, 3},
        {"elbow_front", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Front elbows (min, max)"), kElbowTip, J::Elbow, 0},
        {"elbow_back", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Back elbows (min, max)"), kElbowTip, J::Elbow, 2},
        {"shoulder", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Shoulder (min, max)"), kShoulderTip, J::Shoulder,
         AngleLimitParameter::kChain},
        {"elbow", QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Elbow (min, max)"), kElbowTip, J::Elbow,
         AngleLimitParameter::kChain},
    };
    return limits;
}

Point AngleLimitParameter::in(const SceneSpec& s) const
{
    if (leg == kChain)
        return joint == Joint::Shoulder ? Point(s.chainShoulderMin, s.chainShoulderMax) : Point(s.chainElbowMin, s.chainElbowMax);
    const LegParams& l = s.params.legs[static_cast<std::size_t>(leg)];
    return joint == Joint::Shoulder ? Point(l.shoulderMin, l.shoulderMax) : Point(l.elbowMin, l.elbowMax);
}

void AngleLimitParameter::setIn(SceneSpec& s, Point q) const
{
    if (leg == kChain) {
        (joint == Joint::Shoulder ? s.chainShoulderMin : s.chainElbowMin) = q.x;
        (joint == Joint::Shoulder ? s.chainShoulderMax : s.chainElbowMax) = q.y;
        return;
    }
    // An elbow limit holds for a pair of legs (front: 0 and 1; back: 2 and 3), a shoulder limit for one.
    for (int i = leg; i <= (joint == Joint::Elbow ? leg + 1 : leg); ++i) {
        LegParams& l = s.params.legs[static_cast<std::size_t>(i)];
        (joint == Joint::Shoulder ? l.shoulderMin : l.elbowMin) = q.x;
        (joint == Joint::Shoulder ? l.shoulderMax : l.elbowMax) = q.y;
    }
}

bool AngleLimitParameter::belongsTo(const SceneSpec& s) const { return pendulum() == (s.model == SceneModel::Pendulum); }

const AngleLimitParameter* angleLimitOf(const SceneSpec& s, int part)
{
    for (const AngleLimitParameter& l : angleLimits())
        if (l.belongsTo(s) && part-- == 0)
            return &l;
    return nullptr;
}

int parameterPartCount(const SceneSpec& s, const SceneParameter& p)
{
    switch (p.type) {
    case ParameterType::Legs: return static_cast<int>(legParts().size());
    case ParameterType::AngleLimits:
        return static_cast<int>(std::count_if(angleLimits().begin(), angleLimits().end(),
                                              [&s](const AngleLimitParameter& l) { return l.belongsTo(s); }));
    case ParameterType::Chain: return static_cast<int>(s.chain.size());
    case ParameterType::Obstacles:
    case ParameterType::Shapes: return 0;
    default: return 1;
    }
}

int parameterComponentCount(const SceneParameter& p)
{
    return p.type == ParameterType::Pair || p.type == ParameterType::Legs || p.type == ParameterType::AngleLimits ? 2 : 1;
}

double parameterNumber(const SceneSpec& s, const SceneParameter& p, int part, int index)
{
    if (part < 0 || part >= parameterPartCount(s, p) || index < 0 || index >= parameterComponentCount(p))
        return 0;
    SceneSpec& values = const_cast<SceneSpec&>(s); // only read: the accessors take a SceneSpec& for the reader's sake
    const auto coordinate = [index](Point q) { return index == 0 ? q.x : q.y; };
    switch (p.type) {
    case ParameterType::Integer: return p.integerIn(values);
    case ParameterType::Number: return p.numberIn(values);
    case ParameterType::Pair: return coordinate(p.pairIn(values));
    case ParameterType::Choice: {
        const auto& choices = grabChoices();
        for (std::size_t i = 0; i < choices.size(); ++i)
            if (choices[i].mode == s.grab)
                return static_cast<double>(i);
        return 0;
    }
    case ParameterType::Chain: return s.chain[static_cast<std::size_t>(part)];
    case ParameterType::Legs: { // a pair's two legs have the same lengths (legs 2·part and 2·part + 1)
        const LegParams& l = s.params.legs[static_cast<std::size_t>(2 * part)];
        return index == 0 ? l.upper : l.lower;
    }
    case ParameterType::AngleLimits: return coordinate(angleLimitOf(s, part)->in(s));
    case ParameterType::Obstacles:
    case ParameterType::Shapes: break;
    }
    return 0;
}

const std::vector<GrabChoice>& grabChoices()
{
    static const std::vector<GrabChoice> choices = {
        {"all", GrabMode::All, QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "All vertices (§4.6)")},
        {"above", GrabMode::Above, QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Above the mouse (§4.7)")},
        {"anchors", GrabMode::Anchors, QT_TRANSLATE_NOOP("granota::ui::FrogParametersPanel", "Anchors {0, 1, N−1, N} (§4.10)")},
    };
    return choices;
}

} // namespace granota
