#include "core/softbody/scenes/scene.h"

#include "core/base/display_text.h"
#include "core/exact/rational.h"
#include "core/softbody/scenes/scene_files.h"
#include "core/base/number_format.h"
#include "core/softbody/scenes/scene_layout.h"
#include "core/softbody/seed/stage_body.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace granota {

namespace {

constexpr int kMaxBodies = 5000;
constexpr int kMaxBezierSamples = 2000;
/// The largest magnitude of any number of a scene (lengths, coordinates, areas, factors),
/// the seed's own limit: beyond it a body's area or a chain's reach overflows to infinity.
constexpr double kMaxMagnitude = 1e15;
/// Every body's vertices together: 5000 bodies of 10000 sides would be 50 million
/// vertices, gigabytes and minutes to build (a .granota document can ask for it).
constexpr long kMaxVertices = 100000;
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
    return makeError(ErrorCode::InvalidInput, "scene '" + scene + "': " + what);
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

Json pointJson(Point p)
{
    Json a = Json::array();
    a.push(p.x).push(p.y);
    return a;
}

/// Reads one parameter from its JSON value into the scene. Shared by the file reader
/// and by --set (which first turns "0,0.75" into [0,0.75]).
Expected<bool> setParam(SceneSpec& s, const std::string& key, const Json& v)
{
    FrogParams& p = s.params;
    const auto number = [&](double& out) -> Expected<bool> {
        if (!v.isNumber())
            return bad(s.name, key + " must be a number");
        out = *v.asNumber();
        return true;
    };
    const auto integer = [&](int& out, int lo, int hi) -> Expected<bool> {
        if (!v.isNumber() || *v.asNumber() != std::trunc(*v.asNumber()))
            return bad(s.name, key + " must be a whole number");
        const auto n = wholeNumber(v, lo, hi);
        if (!n)
            return makeError(ErrorCode::OutOfRange, "scene '" + s.name + "': " + key + " must be between " +
                                                        std::to_string(lo) + " and " + std::to_string(hi));
        out = *n;
        return true;
    };
    const auto point = [&](Point& out) -> Expected<bool> {
        auto q = pointOf(v);
        if (!q)
            return bad(s.name, key + " must be a pair x,y");
        out = *q;
        return true;
    };
    if (key == "sides")
        return integer(p.sides, 3, 10000);
    if (key == "radius")
        return number(p.radius);
    if (key == "center")
        return point(p.center);
    if (key == "width")
        return number(p.width);
    if (key == "height")
        return number(p.height);
    if (key == "gravity")
        return point(p.gravity);
    if (key == "v0")
        return point(p.v0);
    if (key == "friction")
        return point(p.friction);
    if (key == "velmax")
        return number(p.velmax);
    if (key == "spring_length")
        return number(p.springLength);
    if (key == "target_area")
        return number(p.targetArea);
    if (key == "area_factor")
        return number(p.areaFactor);
    if (key == "bodies")
        return integer(s.bodies, 1, kMaxBodies);
    if (key == "bezier_samples")
        return integer(s.bezierSamples, 3, kMaxBezierSamples);
    if (key == "bezier_fit_degree")
        return integer(s.bezierFitDegree, 1, 30);
    if (key == "grab") {
        const auto g = v.asString();
        if (g == "all")
            s.grab = GrabMode::All;
        else if (g == "above")
            s.grab = GrabMode::Above;
        else if (g == "anchors")
            s.grab = GrabMode::Anchors;
        else
            return bad(s.name, "grab must be all, above or anchors");
        return true;
    }
    if (key == "chain") {
        auto lengths = numbersOf(v);
        if (!lengths || lengths->size() < 1 || lengths->size() > 100)
            return bad(s.name, "chain must list 1 to 100 link lengths");
        s.chain = *lengths;
        return true;
    }
    if (key == "legs") {
        const Json* front = v.find("front");
        const Json* back = v.find("back");
        auto f = front ? pointOf(*front) : std::nullopt;
        auto b = back ? pointOf(*back) : std::nullopt;
        if (!f || !b)
            return bad(s.name, "legs must be {\"front\": [upper, lower], \"back\": [upper, lower]}");
        for (int i = 0; i < 4; ++i) {
            const Point l = i < 2 ? *f : *b;
            p.legs[static_cast<std::size_t>(i)].upper = l.x;
            p.legs[static_cast<std::size_t>(i)].lower = l.y;
        }
        return true;
    }
    if (key == "angle_limits") {
        if (!v.isObject())
            return bad(s.name, "angle_limits must be an object");
        for (const auto& [name, value] : *v.asObject()) {
            auto q = pointOf(value);
            if (!q)
                return bad(s.name, "angle_limits." + name + " must be a pair min,max");
            auto& L = p.legs;
            if (name == "shoulder_front_right") { L[0].shoulderMin = q->x; L[0].shoulderMax = q->y; }
            else if (name == "shoulder_front_left") { L[1].shoulderMin = q->x; L[1].shoulderMax = q->y; }
            else if (name == "shoulder_back_right") { L[2].shoulderMin = q->x; L[2].shoulderMax = q->y; }
            else if (name == "shoulder_back_left") { L[3].shoulderMin = q->x; L[3].shoulderMax = q->y; }
            else if (name == "elbow_front") { for (int i : {0, 1}) { L[i].elbowMin = q->x; L[i].elbowMax = q->y; } }
            else if (name == "elbow_back") { for (int i : {2, 3}) { L[i].elbowMin = q->x; L[i].elbowMax = q->y; } }
            else if (name == "shoulder") { s.chainShoulderMin = q->x; s.chainShoulderMax = q->y; }
            else if (name == "elbow") { s.chainElbowMin = q->x; s.chainElbowMax = q->y; }
            else
                return bad(s.name, "unknown angle limit '" + name + "'");
        }
        return true;
    }
    if (key == "obstacles") {
        const auto* list = v.asArray();
        if (!list)
            return bad(s.name, "obstacles must be a list");
        s.obstacles.clear();
        for (const Json& o : *list) {
            ObstacleSpec spec;
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
            s.obstacles.push_back(std::move(spec));
        }
        return true;
    }
    if (key == "shapes") {
        const auto* list = v.asArray();
        if (!list)
            return bad(s.name, "shapes must be a list");
        s.shapes.clear();
        for (const Json& o : *list) {
            ShapeSpec spec;
            spec.name = o.find("name") && o.find("name")->asString() ? *o.find("name")->asString() : "shape";
            auto pts = o.find("points") ? pointsOf(*o.find("points")) : std::nullopt;
            auto at = o.find("at") ? pointOf(*o.find("at")) : std::nullopt;
            if (!pts || pts->size() < 3 || !at)
                return bad(s.name, "a shape needs \"points\" (at least 3) and \"at\"");
            spec.points = *pts;
            spec.at = *at;
            s.shapes.push_back(std::move(spec));
        }
        return true;
    }
    return bad(s.name, "unknown parameter '" + key + "'");
}

/// The name of the first number of the scene beyond ±kMaxMagnitude, if any.
std::optional<std::string> tooLarge(const SceneSpec& s)
{
    const FrogParams& p = s.params;
    const std::pair<const char*, double> numbers[] = {
        {"gravity", p.gravity.x}, {"gravity", p.gravity.y}, {"friction", p.friction.x}, {"friction", p.friction.y},
        {"v0", p.v0.x}, {"v0", p.v0.y}, {"center", p.center.x}, {"center", p.center.y},
        {"area_factor", p.areaFactor}, {"target_area", p.targetArea}, {"spring_length", p.springLength},
        {"velmax", p.velmax}, {"radius", p.radius}, {"width", p.width}, {"height", p.height},
        {"angle_limits", s.chainShoulderMin}, {"angle_limits", s.chainShoulderMax},
        {"angle_limits", s.chainElbowMin}, {"angle_limits", s.chainElbowMax}};
    for (const auto& [name, v] : numbers)
        if (!(std::fabs(v) <= kMaxMagnitude))
            return name;
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
            if (!(std::fabs(q.x) <= kMaxMagnitude && std::fabs(q.y) <= kMaxMagnitude &&
                  std::fabs(sh.at.x) <= kMaxMagnitude && std::fabs(sh.at.y) <= kMaxMagnitude))
                return "shapes";
    return std::nullopt;
}

Expected<bool> validate(const SceneSpec& s)
{
    auto ok = validateFrogParams(s.params);
    if (!ok)
        return makeError(ok.error().code, "scene '" + s.name + "': " + ok.error().message);
    if (auto big = tooLarge(s))
        return makeError(ErrorCode::OutOfRange, "scene '" + s.name + "': " + *big + " must be at most 1e15 in magnitude");
    if (static_cast<long>(s.bodies) * std::max(s.params.sides, s.bezierSamples) > kMaxVertices)
        return makeError(ErrorCode::OutOfRange, "scene '" + s.name + "': bodies × sides must be at most " +
                                                    std::to_string(kMaxVertices) + " vertices in all: lower bodies or sides");
    // A document may also give the vertices themselves (shapes) or obstacles' corners.
    std::size_t shapePoints = 0, obstaclePoints = 0;
    for (const auto& sh : s.shapes)
        shapePoints += sh.points.size();
    for (const auto& o : s.obstacles)
        obstaclePoints += o.points.size();
    if (shapePoints > static_cast<std::size_t>(kMaxVertices) || obstaclePoints > static_cast<std::size_t>(kMaxVertices))
        return makeError(ErrorCode::OutOfRange, "scene '" + s.name + "': " +
                                                    (shapePoints > static_cast<std::size_t>(kMaxVertices) ? "shapes" : "obstacles") +
                                                    " must have at most " + std::to_string(kMaxVertices) +
                                                    " points in all: lower the number of points");
    if (const long vertices = static_cast<long>(s.bodies) * std::max(s.params.sides, s.bezierSamples);
        s.hasParam("bodies") && vertices > kMaxPiledVertices && !bodiesFitFrame(s))
        return makeError(ErrorCode::OutOfRange,
                         "scene '" + s.name + "': " + std::to_string(s.bodies) + " bodies of radius " +
                             formatDouble(s.params.radius) + " do not fit side by side in a " + formatDouble(s.params.width) +
                             " × " + formatDouble(s.params.height) + " px frame, and piled up their " +
                             std::to_string(vertices) + " vertices would all touch (at most " +
                             std::to_string(kMaxPiledVertices) +
                             " may start piled): lower bodies, sides or radius, or raise width and height");
    for (double l : s.chain)
        if (!(l >= 0) || !std::isfinite(l))
            return makeError(ErrorCode::OutOfRange, "scene '" + s.name + "': chain lengths must be finite and ≥ 0");
    for (const auto& o : s.obstacles)
        for (Point q : o.points)
            if (!std::isfinite(q.x) || !std::isfinite(q.y))
                return bad(s.name, "obstacle coordinates must be finite");
    return true;
}

} // namespace

bool SceneSpec::has(const std::string& component) const
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
            return makeError(ErrorCode::OutOfRange, "scene '" + s.name + "': order must be a whole number between 0 and " +
                                                        std::to_string(kMaxOrder));
        s.order = *place;
    }
    if (const Json* c = doc.find("components"); c && c->asArray())
        for (const Json& name : *c->asArray())
            if (name.asString())
                s.components.push_back(*name.asString());
    const Json* params = doc.find("params");
    if (!params || !params->isObject())
        return bad(s.name, "a scene needs a \"params\" object");
    for (const auto& [key, value] : *params->asObject()) {
        auto ok = setParam(s, key, value);
        if (!ok)
            return ok.error();
        s.paramKeys.push_back(key);
    }
    auto ok = validate(s);
    if (!ok)
        return ok.error();
    return s;
}

Expected<bool> applySetting(SceneSpec& scene, const std::string& keyValue)
{
    const auto eq = keyValue.find('=');
    if (eq == std::string::npos || eq == 0)
        return makeError(ErrorCode::InvalidInput, "--set takes key=value, got " + quotedForDisplay(keyValue));
    const std::string key = keyValue.substr(0, eq), value = keyValue.substr(eq + 1);
    if (!scene.hasParam(key)) {
        std::string keys;
        for (const auto& k : scene.paramKeys)
            keys += (keys.empty() ? "" : ", ") + k;
        return makeError(ErrorCode::InvalidInput,
                         "scene '" + scene.name + "' has no parameter " + quotedForDisplay(key) + " (it has: " + keys + ")");
    }
    if (key == "legs" || key == "angle_limits" || key == "obstacles" || key == "shapes" || key == "chain")
        return makeError(ErrorCode::InvalidInput, quotedForDisplay(key) + " is set in the scene file, not with --set");
    // "0,0.75" → [0, 0.75]; "all" → "all"; numbers may be fractions.
    Json json;
    if (key == "grab") {
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
                return makeError(ErrorCode::InvalidInput, "--set " + key + ": " + quotedForDisplay(item) + " is not a finite number");
            list.push(toDouble(*q));
            ++count;
            if (comma == std::string::npos)
                break;
            start = comma + 1;
        }
        json = count == 1 ? (*list.asArray())[0] : list;
    }
    SceneSpec changed = scene;
    auto ok = setParam(changed, key, json);
    if (!ok)
        return ok;
    ok = validate(changed);
    if (!ok)
        return ok;
    scene = std::move(changed);
    return true;
}

Expected<SceneSpec> withBodies(SceneSpec scene, int bodies)
{
    if (!scene.hasParam("bodies"))
        return makeError(ErrorCode::InvalidInput, "scene '" + scene.name + "' has a single body");
    if (bodies >= 1 && bodies <= kMaxBodies) { // out of range: applySetting says so
        const FrameSize f = frameForBodies(scene, bodies);
        scene.params.width = f.width;
        scene.params.height = f.height;
    }
    auto ok = applySetting(scene, "bodies=" + std::to_string(bodies));
    if (!ok)
        return ok.error();
    return scene;
}

Json sceneToJson(const SceneSpec& s)
{
    const FrogParams& p = s.params;
    Json params = Json::object();
    for (const std::string& key : s.paramKeys) {
        if (key == "sides") params.set(key, p.sides);
        else if (key == "radius") params.set(key, p.radius);
        else if (key == "center") params.set(key, pointJson(p.center));
        else if (key == "width") params.set(key, p.width);
        else if (key == "height") params.set(key, p.height);
        else if (key == "gravity") params.set(key, pointJson(p.gravity));
        else if (key == "v0") params.set(key, pointJson(p.v0));
        else if (key == "friction") params.set(key, pointJson(p.friction));
        else if (key == "velmax") params.set(key, p.velmax);
        else if (key == "spring_length") params.set(key, p.springLength);
        else if (key == "target_area") params.set(key, p.targetArea);
        else if (key == "area_factor") params.set(key, p.areaFactor);
        else if (key == "bodies") params.set(key, s.bodies);
        else if (key == "bezier_samples") params.set(key, s.bezierSamples);
        else if (key == "bezier_fit_degree") params.set(key, s.bezierFitDegree);
        else if (key == "grab") params.set(key, s.grab == GrabMode::All ? "all" : s.grab == GrabMode::Above ? "above" : "anchors");
        else if (key == "chain") {
            Json a = Json::array();
            for (double l : s.chain)
                a.push(l);
            params.set(key, a);
        } else if (key == "legs") {
            Json legs = Json::object();
            legs.set("front", pointJson(Point(p.legs[0].upper, p.legs[0].lower)));
            legs.set("back", pointJson(Point(p.legs[2].upper, p.legs[2].lower)));
            params.set(key, legs);
        } else if (key == "angle_limits") {
            Json limits = Json::object();
            if (s.model == SceneModel::Pendulum) {
                limits.set("shoulder", pointJson(Point(s.chainShoulderMin, s.chainShoulderMax)));
                limits.set("elbow", pointJson(Point(s.chainElbowMin, s.chainElbowMax)));
            } else {
                const char* names[] = {"shoulder_front_right", "shoulder_front_left", "shoulder_back_right", "shoulder_back_left"};
                for (int i = 0; i < 4; ++i)
                    limits.set(names[i], pointJson(Point(p.legs[static_cast<std::size_t>(i)].shoulderMin, p.legs[static_cast<std::size_t>(i)].shoulderMax)));
                limits.set("elbow_front", pointJson(Point(p.legs[0].elbowMin, p.legs[0].elbowMax)));
                limits.set("elbow_back", pointJson(Point(p.legs[2].elbowMin, p.legs[2].elbowMax)));
            }
            params.set(key, limits);
        } else if (key == "obstacles") {
            Json list = Json::array();
            for (const auto& o : s.obstacles) {
                Json pts = Json::array();
                for (Point q : o.points)
                    pts.push(pointJson(q));
                Json item = Json::object();
                item.set(o.closed ? "polygon" : "segment", pts);
                list.push(item);
            }
            params.set(key, list);
        } else if (key == "shapes") {
            Json list = Json::array();
            for (const auto& sh : s.shapes) {
                Json pts = Json::array();
                for (Point q : sh.points)
                    pts.push(pointJson(q));
                Json item = Json::object();
                item.set("name", sh.name).set("points", pts).set("at", pointJson(sh.at));
                list.push(item);
            }
            params.set(key, list);
        }
    }
    Json components = Json::array();
    for (const auto& c : s.components)
        components.push(c);
    const char* model = s.model == SceneModel::Stage ? "stage" : s.model == SceneModel::Body ? "body"
                        : s.model == SceneModel::Pendulum ? "pendulum" : "frog";
    Json doc = Json::object();
    doc.set("name", s.name).set("section", s.section).set("title", s.title).set("description", s.description)
        .set("model", model).set("order", s.order).set("components", components).set("params", params);
    return doc;
}

} // namespace granota
