#include "core/softbody/scenes/scene.h"

#include "core/base/display_text.h"
#include "core/base/input_limits.h"
#include "core/exact/rational.h"
#include "core/softbody/scenes/frame_derived.h"
#include "core/softbody/scenes/scene_files.h"
#include "core/base/number_format.h"
#include "core/softbody/scenes/scene_layout.h"
#include "core/softbody/scenes/scene_parameters.h"
#include "core/softbody/scenes/scene_texts.h"
#include "core/softbody/outline.h"
#include "core/softbody/seed/stage_body.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace granota {

namespace {

/// The largest magnitude of any number of a scene (lengths, coordinates, areas, factors),
/// the seed's own limit: beyond it a body's area or a chain's reach overflows to infinity.
constexpr double kMaxMagnitude = 1e15;
/// The most vertices (all bodies together) a scene may start piled up, in a frame too small
/// to hold its bodies side by side: piled, every body is a broad-phase pair of every other
/// and every vertex is tested against every other body's edges, about 35 ns × vertices² a
/// step of the stable solver on the reference machine (50 bodies of 10 sides: 10 ms; 100:
/// 38 ms; 12 bodies of 1000 sides: 3.4 s; 5000 of 10 — what `--set bodies=5000` asked for
/// in 1280 × 720 px — seconds). 600 keeps a piled step near 15 ms.
constexpr long kMaxPiledVertices = 600;
/// A scene's place in the thesis's order (`"order"`): 1 to 18 today, room for more.
constexpr int kMaxOrder = 100000;

/// The JSON number v as an int when it is a whole number in [lo, hi]; nullopt otherwise.
/// The range is checked on the double, before converting: 1e300, ±inf or NaN cast to int
/// is undefined behaviour (found by the scene fuzz target, UBSan).
std::optional<int> wholeNumber(const Json& v, int lo, int hi)
{
    const auto d = v.asNumber();
    if (!d || !(*d >= lo && *d <= hi) || *d != std::trunc(*d))
        return std::nullopt;
    return static_cast<int>(*d);
}

Error bad(const std::string& scene, const std::string& what)
{
    return makeError(ErrorCode::InvalidInput, "scene " + quotedForDisplay(scene) + ": " + what);
}

/// bad(), with the sentence the GUI translates (message_id.h).
Error bad(const std::string& scene, const std::string& what, MessageId id, std::vector<MessageArg> args,
          ErrorCode code = ErrorCode::InvalidInput)
{
    return makeError(code, "scene " + quotedForDisplay(scene) + ": " + what, id, std::move(args));
}

/// The keys of "stable" (StableSettings), also taken by --set on any scene.
bool isStableKey(const std::string& key)
{
    const auto& keys = stableKnobKeys();
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

/// Sets the stable solver's `key` in `s` from `v` (stableKnobRange says what each takes).
Expected<void> setStableSetting(SceneSpec& s, const std::string& key, const Json& v)
{
    if (!isStableKey(key))
        return bad(s.name, "\"stable\" has substeps, edge_compliance and edge_damping_ratio, not " + quotedForDisplay(key));
    const auto number = v.asNumber();
    if (!number || !setStableKnob(s.stable, key, *number))
        return bad(s.name, key + " must be " + stableKnobRange(key), MessageId::StableKnobOutOfRange, {textArg(key)});
    return {};
}

/// The file's "stable" object into `s` (setStableSetting for each key).
Expected<void> readStable(SceneSpec& s, const Json& stable)
{
    if (!stable.isObject())
        return bad(s.name, "\"stable\" must be an object: {\"substeps\": n, \"edge_compliance\": α, "
                           "\"edge_damping_ratio\": ζ}");
    for (const auto& [key, value] : *stable.asObject()) {
        auto ok = setStableSetting(s, key, value);
        if (!ok)
            return ok;
    }
    return {};
}

/// `first_frame` (frame_derived.h): "window" or "sketch", on the frog scene only (the sketch whose
/// first frame is known is Annex II's).
Expected<void> setFirstFrame(SceneSpec& s, const Json& v)
{
    const auto word = v.asString();
    if (s.model != SceneModel::Frog)
        return bad(s.name, std::string(kFirstFrameKey) + " belongs to the frog scene (Annex II builds its frog before size())");
    if (word != kWindowFrame && word != kSketchFrame)
        return bad(s.name, std::string(kFirstFrameKey) + " must be " + kWindowFrame + " (r and centre from width × height) or " +
                               kSketchFrame + " (from the sketch's first 100 × 100 frame: r = 16 at (50, 50))");
    s.sketchFirstFrame = word == kSketchFrame;
    return {};
}

std::optional<Point> pointOf(const Json& v)
{
    const auto* a = v.asArray();
    if (!a || a->size() != 2 || !(*a)[0].isNumber() || !(*a)[1].isNumber())
        return std::nullopt;
    return Point(*(*a)[0].asNumber(), *(*a)[1].asNumber());
}

std::optional<std::vector<Point>> pointsOf(const Json& v)
{
    const auto* a = v.asArray();
    if (!a)
        return std::nullopt;
    std::vector<Point> out;
    for (const Json& p : *a) {
        auto q = pointOf(p);
        if (!q)
            return std::nullopt;
        out.push_back(*q);
    }
    return out;
}

std::optional<std::vector<double>> numbersOf(const Json& v)
{
    const auto* a = v.asArray();
    if (!a)
        return std::nullopt;
    std::vector<double> out;
    for (const Json& x : *a) {
        if (!x.isNumber())
            return std::nullopt;
        out.push_back(*x.asNumber());
    }
    return out;
}

/// A list parameter (obstacles, shapes): `out` becomes the items `one` reads from the list `v`.
template <typename Item, typename ReadOne>
Expected<void> setList(SceneSpec& s, const std::string& key, const Json& v, std::vector<Item>& out, ReadOne one)
{
    const auto* list = v.asArray();
    if (!list)
        return bad(s.name, key + " must be a list");
    out.clear();
    for (const Json& o : *list) {
        Item item;
        if (auto ok = one(o, item); !ok)
            return ok;
        out.push_back(std::move(item));
    }
    return {};
}

/// One of `obstacles`: a segment or a polygon (§5.2.1).
Expected<void> readObstacle(const SceneSpec& s, const Json& o, ObstacleSpec& spec)
{
    if (const Json* seg = o.find("segment")) {
        auto pts = pointsOf(*seg);
        if (!pts || pts->size() != 2)
            return bad(s.name, "a segment obstacle has two points");
        spec.points = *pts;
    } else if (const Json* poly = o.find("polygon")) {
        auto pts = pointsOf(*poly);
        if (!pts || pts->size() < 3)
            return bad(s.name, "a polygon obstacle has at least three points");
        spec.points = *pts;
        spec.closed = true;
    } else {
        return bad(s.name, "an obstacle is {\"segment\": …} or {\"polygon\": …}");
    }
    return {};
}

/// One of `shapes`: a body's rest shape and start (§5.2.3).
Expected<void> readShape(const SceneSpec& s, const Json& o, ShapeSpec& spec)
{
    spec.name = o.find("name") && o.find("name")->asString() ? *o.find("name")->asString() : "shape";
    auto pts = o.find("points") ? pointsOf(*o.find("points")) : std::nullopt;
    auto at = o.find("at") ? pointOf(*o.find("at")) : std::nullopt;
    if (!pts || pts->size() < 3 || !at)
        return bad(s.name, "a shape needs \"points\" (at least 3) and \"at\"");
    spec.points = *pts;
    spec.at = *at;
    return {};
}

/// An Integer parameter `param` from the number `v`, whole and within the table's range.
Expected<void> setWhole(SceneSpec& s, const SceneParameter& param, const Json& v)
{
    const std::string key = param.key;
    if (!v.isNumber() || *v.asNumber() != std::trunc(*v.asNumber()))
        return bad(s.name, key + " must be a whole number", MessageId::ParameterNotWhole, {textArg(key)});
    const auto n = wholeNumber(v, param.min, param.max);
    if (!n)
        return bad(s.name, key + " must be between " + std::to_string(param.min) + " and " + std::to_string(param.max),
                   MessageId::ParameterOutOfRange, {textArg(key), numberArg(param.min), numberArg(param.max)},
                   ErrorCode::OutOfRange);
    param.integerIn(s) = *n;
    return {};
}

/// Reads one parameter from its JSON value into the scene. Shared by the file reader
/// and by --set (which first turns "0,0.75" into [0,0.75]).
Expected<void> setParam(SceneSpec& s, const std::string& key, const Json& v)
{
    const SceneParameter* param = findSceneParameter(key);
    if (!param)
        return bad(s.name, "unknown parameter " + quotedForDisplay(key), MessageId::SceneUnknownParameter,
                   {textArg(quotedForDisplay(key))});
    switch (param->type) {
    case ParameterType::Integer: return setWhole(s, *param, v);
    case ParameterType::Number: {
        const bool radius = key == "radius";
        if (radius && v.asString() == kFromFrame) {
            s.radiusFromFrame = true;
            return {};
        }
        if (!v.isNumber())
            return bad(s.name, key + (radius ? " must be a number or \"frame\" (|height/6|, as Annex II)" : " must be a number"),
                       MessageId::ParameterNotANumber, {textArg(key)});
        param->numberIn(s) = *v.asNumber();
        if (radius)
            s.radiusFromFrame = false;
        return {};
    }
    case ParameterType::Pair: {
        const bool center = key == "center";
        if (center && v.asString() == kFromFrame) {
            s.centerFromFrame = true;
            return {};
        }
        auto q = pointOf(v);
        if (!q)
            return bad(s.name,
                       key + (center ? " must be a pair x,y or \"frame\" (the frame's centre, as Annex II)"
                                     : " must be a pair x,y"),
                       MessageId::ParameterNotAPair, {textArg(key)});
        param->pairIn(s) = *q;
        if (center)
            s.centerFromFrame = false;
        return {};
    }
    case ParameterType::Choice: {
        const auto g = v.asString();
        std::string names;
        const auto& choices = grabChoices();
        for (std::size_t i = 0; i < choices.size(); ++i) {
            if (g == choices[i].name) {
                s.grab = choices[i].mode;
                return {};
            }
            names += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + std::string(choices[i].name);
        }
        return bad(s.name, key + " must be " + names);
    }
    case ParameterType::Chain: {
        auto lengths = numbersOf(v);
        if (!lengths || lengths->size() < 1 || lengths->size() > 100)
            return bad(s.name, "chain must list 1 to 100 link lengths");
        s.chain = *lengths;
        return {};
    }
    case ParameterType::Legs: {
        std::vector<Point> lengths; // upper, lower of each part: front (legs 0, 1), back (legs 2, 3)
        for (const ParameterPart& part : legParts()) {
            const Json* given = v.find(part.name);
            auto l = given ? pointOf(*given) : std::nullopt;
            if (!l)
                return bad(s.name, "legs must be {\"front\": [upper, lower], \"back\": [upper, lower]}");
            lengths.push_back(*l);
        }
        for (std::size_t i = 0; i < s.params.legs.size(); ++i) {
            s.params.legs[i].upper = lengths[i / 2].x;
            s.params.legs[i].lower = lengths[i / 2].y;
        }
        return {};
    }
    case ParameterType::AngleLimits: {
        if (!v.isObject())
            return bad(s.name, "angle_limits must be an object");
        for (const auto& [name, value] : *v.asObject()) {
            auto q = pointOf(value);
            if (!q)
                return bad(s.name, "angle_limits." + escapedForDisplay(name) + " must be a pair min,max");
            const auto& limits = angleLimits();
            const std::string& limitName = name; // C++17 lambdas cannot capture a structured binding
            const auto limit = std::find_if(limits.begin(), limits.end(),
                                            [&](const AngleLimitParameter& l) { return limitName == l.name; });
            if (limit == limits.end())
                return bad(s.name, "unknown angle limit " + quotedForDisplay(name));
            limit->setIn(s, *q);
        }
        return {};
    }
    case ParameterType::Obstacles:
        return setList(s, key, v, s.obstacles, [&](const Json& o, ObstacleSpec& spec) { return readObstacle(s, o, spec); });
    case ParameterType::Shapes:
        return setList(s, key, v, s.shapes, [&](const Json& o, ShapeSpec& spec) { return readShape(s, o, spec); });
    }
    return bad(s.name, "unknown parameter " + quotedForDisplay(key), MessageId::SceneUnknownParameter,
               {textArg(quotedForDisplay(key))});
}

/// The name of the first number of the scene beyond ±kMaxMagnitude, if any.
std::optional<std::string> tooLarge(const SceneSpec& s)
{
    const FrogParams& p = s.params;
    // Only read: the table's accessors take a SceneSpec& for the reader's sake.
    SceneSpec& values = const_cast<SceneSpec&>(s);
    for (const SceneParameter& param : sceneParameters()) {
        if (param.type == ParameterType::Number && !(std::fabs(param.numberIn(values)) <= kMaxMagnitude))
            return std::string(param.key);
        if (param.type == ParameterType::Pair &&
            !(std::fabs(param.pairIn(values).x) <= kMaxMagnitude && std::fabs(param.pairIn(values).y) <= kMaxMagnitude))
            return std::string(param.key);
    }
    for (double v : {s.chainShoulderMin, s.chainShoulderMax, s.chainElbowMin, s.chainElbowMax})
        if (!(std::fabs(v) <= kMaxMagnitude))
            return "angle_limits";
    for (const LegParams& l : p.legs) {
        for (double v : {l.upper, l.lower})
            if (!(std::fabs(v) <= kMaxMagnitude))
                return "legs";
        for (double v : {l.shoulderMin, l.shoulderMax, l.elbowMin, l.elbowMax})
            if (!(std::fabs(v) <= kMaxMagnitude))
                return "angle_limits";
    }
    for (double l : s.chain)
        if (!(std::fabs(l) <= kMaxMagnitude))
            return "chain";
    for (const auto& o : s.obstacles)
        for (Point q : o.points)
            if (!(std::fabs(q.x) <= kMaxMagnitude && std::fabs(q.y) <= kMaxMagnitude))
                return "obstacles";
    for (const auto& sh : s.shapes)
        for (Point q : sh.points)
            if (!(std::fabs(q.x) <= kMaxMagnitude && std::fabs(q.y) <= kMaxMagnitude && std::fabs(sh.at.x) <= kMaxMagnitude &&
                  std::fabs(sh.at.y) <= kMaxMagnitude))
                return "shapes";
    return std::nullopt;
}

Expected<void> validate(const SceneSpec& s)
{
    auto ok = validateFrogParams(s.params);
    if (!ok)
        return withContext("scene " + quotedForDisplay(s.name) + ": ", ok.error());
    if (auto big = tooLarge(s))
        return bad(s.name, *big + " must be at most 1e15 in magnitude", MessageId::ParameterTooLarge, {textArg(*big)},
                   ErrorCode::OutOfRange);
    if (sceneVertexCount(s) > kMaxVertices)
        return bad(s.name,
                   "bodies × sides must be at most " + std::to_string(kMaxVertices) + " vertices in all: lower bodies or sides",
                   MessageId::TooManyVertices, {numberArg(static_cast<double>(kMaxVertices))}, ErrorCode::OutOfRange);
    // §4.9: the body's points are sampled once from a Bézier curve of degree `sides`, a
    // cost of sides² × bezier_samples (10 000 sides and 2000 points froze the window 48 s).
    if (s.has(SceneComponent::OutlineBezier) && s.bezierSamples >= 3 &&
        bezierBodyPointsWork(s.params.sides, s.bezierSamples) > kMaxBezierOutlineWork)
        return bad(s.name,
                   "a Bézier curve of degree " + std::to_string(s.params.sides) + " sampled at " +
                       std::to_string(s.bezierSamples) + " points is " +
                       formatDouble(bezierBodyPointsWork(s.params.sides, s.bezierSamples)) + " interpolations, more than " +
                       formatDouble(kMaxBezierOutlineWork) +
                       " (sides × (sides + 1) / 2 × bezier_samples): lower sides or bezier_samples",
                   MessageId::BezierOutlineTooCostly,
                   {numberArg(s.params.sides), numberArg(s.bezierSamples),
                    numberArg(bezierBodyPointsWork(s.params.sides, s.bezierSamples)), numberArg(kMaxBezierOutlineWork)},
                   ErrorCode::OutOfRange);
    // A document may also give the vertices themselves (shapes) or obstacles' corners.
    std::size_t shapePoints = 0, obstaclePoints = 0;
    for (const auto& sh : s.shapes)
        shapePoints += sh.points.size();
    for (const auto& o : s.obstacles)
        obstaclePoints += o.points.size();
    if (shapePoints > static_cast<std::size_t>(kMaxVertices) || obstaclePoints > static_cast<std::size_t>(kMaxVertices))
        return makeError(ErrorCode::OutOfRange,
                         "scene " + quotedForDisplay(s.name) + ": " +
                             (shapePoints > static_cast<std::size_t>(kMaxVertices) ? "shapes" : "obstacles") +
                             " must have at most " + std::to_string(kMaxVertices) + " points in all: lower the number of points");
    if (const long vertices = sceneVertexCount(s); s.hasParam("bodies") && vertices > kMaxPiledVertices && !bodiesFitFrame(s))
        return bad(s.name,
                   std::to_string(s.bodies) + " bodies of radius " + formatDouble(s.params.radius) +
                       " do not fit side by side in a " + formatDouble(s.params.width) + " × " + formatDouble(s.params.height) +
                       " px frame, and piled up their " + std::to_string(vertices) + " vertices would all touch (at most " +
                       std::to_string(kMaxPiledVertices) +
                       " may start piled): lower bodies, sides or radius, or raise width and height",
                   MessageId::BodiesDoNotFit,
                   {numberArg(s.bodies), numberArg(s.params.radius), numberArg(s.params.width), numberArg(s.params.height),
                    numberArg(static_cast<double>(vertices)), numberArg(static_cast<double>(kMaxPiledVertices))},
                   ErrorCode::OutOfRange);
    for (double l : s.chain)
        if (!(l >= 0) || !std::isfinite(l))
            return makeError(ErrorCode::OutOfRange,
                             "scene " + quotedForDisplay(s.name) + ": chain lengths must be finite and ≥ 0");
    for (const auto& o : s.obstacles)
        for (Point q : o.points)
            if (!std::isfinite(q.x) || !std::isfinite(q.y))
                return bad(s.name, "obstacle coordinates must be finite");
    return {};
}

/// `key` is not a parameter of the scene: the reader's message for an unknown parameter.
Error notInScene(const SceneSpec& s, const std::string& key)
{
    return bad(s.name, "unknown parameter " + quotedForDisplay(key), MessageId::SceneUnknownParameter,
               {textArg(quotedForDisplay(key))});
}

/// `s` after parameters were set: what follows the frame follows it again, and the whole scene
/// is checked as a file is.
Expected<SceneSpec> checkedScene(SceneSpec s)
{
    deriveFromFrame(s);
    auto ok = validate(s);
    if (!ok)
        return ok.error();
    return s;
}

} // namespace

bool SceneSpec::has(SceneComponent component) const
{
    return std::find(components.begin(), components.end(), component) != components.end();
}

bool SceneSpec::hasParam(const std::string& key) const
{
    return std::find(paramKeys.begin(), paramKeys.end(), key) != paramKeys.end();
}

std::vector<std::string> sceneNames()
{
    std::vector<std::pair<int, std::string>> ordered;
    for (const auto& [name, text] : sceneFiles()) {
        auto doc = Json::parse(text);
        const Json* order = doc ? doc->find("order") : nullptr;
        const auto place = order ? wholeNumber(*order, 0, kMaxOrder) : std::nullopt;
        ordered.emplace_back(place ? *place : kMaxOrder, std::string(name));
    }
    std::sort(ordered.begin(), ordered.end());
    std::vector<std::string> names;
    for (auto& [order, name] : ordered)
        names.push_back(std::move(name));
    return names;
}

Expected<SceneSpec> loadScene(const std::string& name)
{
    for (const auto& [fileName, text] : sceneFiles())
        if (fileName == name) {
            auto doc = Json::parse(text);
            if (!doc)
                return makeError(doc.error().code, "scene file " + name + ".json: " + doc.error().message);
            return parseScene(*doc);
        }
    std::string list;
    for (const auto& n : sceneNames())
        list += (list.empty() ? "" : ", ") + n;
    return makeError(ErrorCode::InvalidInput, "unknown scene " + quotedForDisplay(name) + " (scenes: " + list + ")");
}

Expected<SceneSpec> parseScene(const Json& doc)
{
    SceneSpec s;
    const auto text = [&](const char* key) {
        const Json* v = doc.find(key);
        return v && v->asString() ? *v->asString() : std::string();
    };
    s.name = text("name");
    s.section = text("section");
    s.title = text("title");
    s.description = text("description");
    if (const SceneText* builtIn = findSceneText(s.name)) { // a built-in scene's texts live in scene_texts.cpp
        if (s.section.empty())
            s.section = builtIn->section;
        if (s.title.empty())
            s.title = builtIn->title;
        if (s.description.empty())
            s.description = builtIn->description;
    }
    if (s.name.empty())
        return bad("?", "a scene needs a \"name\"");
    const std::string model = text("model");
    if (model == "stage")
        s.model = SceneModel::Stage;
    else if (model == "body")
        s.model = SceneModel::Body;
    else if (model == "pendulum")
        s.model = SceneModel::Pendulum;
    else if (model == "frog")
        s.model = SceneModel::Frog;
    else
        return bad(s.name, "model must be stage, body, pendulum or frog");
    if (const Json* o = doc.find("order")) {
        const auto place = wholeNumber(*o, 0, kMaxOrder);
        if (!place)
            return makeError(ErrorCode::OutOfRange, "scene " + quotedForDisplay(s.name) +
                                                        ": order must be a whole number between 0 and " +
                                                        std::to_string(kMaxOrder));
        s.order = *place;
    }
    if (const Json* c = doc.find("components"); c && c->asArray())
        for (const Json& name : *c->asArray()) {
            // A name the code does not know would silently build nothing ("outline-bezer").
            const std::optional<SceneComponent> component = name.asString() ? sceneComponentNamed(*name.asString())
                                                                            : std::nullopt;
            if (!component) {
                const std::string shown = name.asString() ? quotedForDisplay(*name.asString()) : name.dump();
                std::string known;
                for (const auto& entry : kSceneComponentNames)
                    known += (known.empty() ? "" : ", ") + std::string(entry.name);
                return bad(s.name, "unknown component " + shown + " (the components are " + known + ")",
                           MessageId::SceneUnknownComponent, {textArg(shown), textArg(known)});
            }
            if (!s.has(*component))
                s.components.push_back(*component);
        }
    const Json* params = doc.find("params");
    if (!params || !params->isObject())
        return bad(s.name, "a scene needs a \"params\" object");
    for (const auto& [key, value] : *params->asObject()) {
        auto ok = setParam(s, key, value);
        if (!ok)
            return ok.error();
        s.paramKeys.push_back(key);
    }
    if (const Json* stable = doc.find("stable")) {
        auto ok = readStable(s, *stable);
        if (!ok)
            return ok.error();
    }
    if (const Json* firstFrame = doc.find(kFirstFrameKey)) {
        auto ok = setFirstFrame(s, *firstFrame);
        if (!ok)
            return ok.error();
    }
    deriveFromFrame(s);
    auto ok = validate(s);
    if (!ok)
        return ok.error();
    return s;
}

Expected<void> applySetting(SceneSpec& scene, const std::string& keyValue)
{
    const auto eq = keyValue.find('=');
    if (eq == std::string::npos || eq == 0)
        return makeError(ErrorCode::InvalidInput, "--set takes key=value, got " + quotedForDisplay(keyValue));
    const std::string key = keyValue.substr(0, eq), value = keyValue.substr(eq + 1);
    if (key == kFirstFrameKey) { // both derived again, from the frame it names
        SceneSpec changed = scene;
        auto ok = setFirstFrame(changed, Json(value));
        if (!ok)
            return ok;
        changed.radiusFromFrame = changed.centerFromFrame = true;
        deriveFromFrame(changed);
        ok = validate(changed);
        if (!ok)
            return ok;
        scene = std::move(changed);
        return {};
    }
    if (isStableKey(key)) {
        const auto q = parseRational(value);
        if (!q)
            return makeError(ErrorCode::InvalidInput, "--set " + key + ": " + quotedForDisplay(value) + " " +
                                                          numberBeyondReach(value).value_or("is not a finite number"));
        SceneSpec changed = scene;
        auto ok = setStableSetting(changed, key, Json(toDouble(*q)));
        if (!ok)
            return ok;
        scene = std::move(changed);
        return {};
    }
    if (!scene.hasParam(key)) {
        std::string keys;
        for (const auto& k : scene.paramKeys)
            keys += (keys.empty() ? "" : ", ") + k;
        return makeError(ErrorCode::InvalidInput,
                         "scene " + quotedForDisplay(scene.name) + " has no parameter " + quotedForDisplay(key) +
                             " (it has: " + keys + (scene.model == SceneModel::Frog ? ", first_frame" : "") +
                             "; and for the stable solver: substeps, edge_compliance, edge_damping_ratio)");
    }
    const SceneParameter* param = findSceneParameter(key);
    if (param && !param->settable())
        return makeError(ErrorCode::InvalidInput, quotedForDisplay(key) + " is set in the scene file, not with --set");
    // "0,0.75" → [0, 0.75]; "all" → "all"; numbers may be fractions.
    Json json;
    if (param && param->type == ParameterType::Choice) {
        json = Json(value);
    } else {
        Json list = Json::array();
        std::size_t start = 0;
        int count = 0;
        while (true) {
            const auto comma = value.find(',', start);
            const std::string item = value.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
            auto q = parseRational(item);
            if (!q)
                return makeError(ErrorCode::InvalidInput, "--set " + key + ": " + quotedForDisplay(item) + " " +
                                                              numberBeyondReach(item).value_or("is not a finite number"));
            list.push(toDouble(*q));
            ++count;
            if (comma == std::string::npos)
                break;
            start = comma + 1;
        }
        json = count == 1 ? (*list.asArray())[0] : list;
    }
    auto changed = withParameter(scene, key, json);
    if (!changed)
        return changed.error();
    scene = std::move(*changed);
    return {};
}

Expected<SceneSpec> withParameter(SceneSpec scene, const std::string& key, const Json& value)
{
    return withParameters(std::move(scene), {{key, value}});
}

Expected<SceneSpec> withParameters(SceneSpec scene, const std::vector<std::pair<std::string, Json>>& values)
{
    for (const auto& [key, value] : values) {
        if (!scene.hasParam(key))
            return notInScene(scene, key);
        auto ok = setParam(scene, key, value);
        if (!ok)
            return ok.error();
    }
    return checkedScene(std::move(scene));
}

Expected<SceneSpec> withParameter(SceneSpec scene, const std::string& key, int part, int index, double value)
{
    if (!scene.hasParam(key))
        return notInScene(scene, key);
    const SceneParameter& param = *findSceneParameter(key); // every key a scene has is in the table
    if (part < 0 || part >= parameterPartCount(scene, param) || index < 0 || index >= parameterComponentCount(param))
        return bad(scene.name, key + " has no number at part " + std::to_string(part) + ", index " + std::to_string(index));
    const auto set = [index](Point& q, double v) { (index == 0 ? q.x : q.y) = v; };
    switch (param.type) {
    case ParameterType::Integer: {
        auto ok = setWhole(scene, param, Json(value));
        if (!ok)
            return ok.error();
        break;
    }
    case ParameterType::Number:
        param.numberIn(scene) = value;
        if (key == "radius") // a number set: no longer derived from the frame
            scene.radiusFromFrame = false;
        break;
    case ParameterType::Pair:
        set(param.pairIn(scene), value);
        if (key == "center")
            scene.centerFromFrame = false;
        break;
    case ParameterType::Choice: {
        const auto& choices = grabChoices();
        if (!(value >= 0 && value < static_cast<double>(choices.size())) || value != std::trunc(value))
            return bad(scene.name, key + " has no choice " + formatDouble(value));
        scene.grab = choices[static_cast<std::size_t>(value)].mode;
        break;
    }
    case ParameterType::Chain: scene.chain[static_cast<std::size_t>(part)] = value; break;
    case ParameterType::Legs: // a pair of legs: 2·part and 2·part + 1, as the file's "front" and "back"
        for (std::size_t leg = 2 * static_cast<std::size_t>(part); leg < 2 * static_cast<std::size_t>(part) + 2; ++leg)
            (index == 0 ? scene.params.legs[leg].upper : scene.params.legs[leg].lower) = value;
        break;
    case ParameterType::AngleLimits: {
        const AngleLimitParameter& limit = *angleLimitOf(scene, part);
        Point q = limit.in(scene);
        set(q, value);
        limit.setIn(scene, q);
        break;
    }
    case ParameterType::Obstacles:
    case ParameterType::Shapes: break; // no numbers (parameterPartCount is 0): refused above
    }
    return checkedScene(std::move(scene));
}

Expected<SceneSpec> withParameterOf(SceneSpec scene, const SceneSpec& source, const std::string& key)
{
    if (!scene.hasParam(key))
        return notInScene(scene, key);
    const SceneParameter& param = *findSceneParameter(key);
    SceneSpec& from = const_cast<SceneSpec&>(source); // only read, as in tooLarge
    switch (param.type) {
    case ParameterType::Integer: param.integerIn(scene) = param.integerIn(from); break;
    case ParameterType::Number:
        param.numberIn(scene) = param.numberIn(from);
        if (key == "radius")
            scene.radiusFromFrame = source.radiusFromFrame;
        break;
    case ParameterType::Pair:
        param.pairIn(scene) = param.pairIn(from);
        if (key == "center")
            scene.centerFromFrame = source.centerFromFrame;
        break;
    case ParameterType::Choice: scene.grab = source.grab; break;
    case ParameterType::Chain: scene.chain = source.chain; break;
    case ParameterType::Legs:
        for (std::size_t i = 0; i < scene.params.legs.size(); ++i) {
            scene.params.legs[i].upper = source.params.legs[i].upper;
            scene.params.legs[i].lower = source.params.legs[i].lower;
        }
        break;
    case ParameterType::AngleLimits:
        for (const AngleLimitParameter& limit : angleLimits())
            limit.setIn(scene, limit.in(source));
        break;
    case ParameterType::Obstacles: scene.obstacles = source.obstacles; break;
    case ParameterType::Shapes: scene.shapes = source.shapes; break;
    }
    return checkedScene(std::move(scene));
}

Expected<SceneSpec> withStableSettings(SceneSpec scene, const Json& stable)
{
    auto ok = readStable(scene, stable);
    if (!ok)
        return ok.error();
    return scene;
}

Expected<SceneSpec> withBodies(SceneSpec scene, int bodies)
{
    if (!scene.hasParam("bodies"))
        return makeError(ErrorCode::InvalidInput, "scene " + quotedForDisplay(scene.name) + " has a single body");
    if (const SceneParameter* count = findSceneParameter("bodies");
        bodies >= count->min && bodies <= count->max) { // out of range: applySetting says so
        const FrameSize f = frameForBodies(scene, bodies);
        scene.params.width = f.width;
        scene.params.height = f.height;
    }
    auto ok = applySetting(scene, "bodies=" + std::to_string(bodies));
    if (!ok)
        return ok.error();
    return scene;
}

} // namespace granota
