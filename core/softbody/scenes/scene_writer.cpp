#include "core/softbody/scenes/scene.h"

#include "core/softbody/scenes/frame_derived.h"
#include "core/softbody/scenes/scene_parameters.h"

#include <atomic>

/// \file scene_writer.cpp
/// The scene writer: a SceneSpec as its file (sceneToJson), only its own keys with their current
/// values. With setParam in scene.cpp (the reader), the one place that knows the file's JSON
/// shapes of each parameter type; an edit of one value goes through withParameter and never here.

namespace granota {

namespace {

std::atomic<long> g_sceneWrites{0}; ///< sceneToJson's calls, for sceneWriteCount()

Json pointJson(Point p)
{
    Json a = Json::array();
    a.push(p.x).push(p.y);
    return a;
}

Json pointsJson(const std::vector<Point>& points)
{
    Json a = Json::array();
    for (Point q : points)
        a.push(pointJson(q));
    return a;
}

} // namespace

long sceneWriteCount() { return g_sceneWrites.load(); }

Json sceneToJson(const SceneSpec& s)
{
    ++g_sceneWrites;
    const FrogParams& p = s.params;
    Json params = Json::object();
    SceneSpec& values = const_cast<SceneSpec&>(s); // only read, as in tooLarge
    for (const std::string& key : s.paramKeys) {
        const SceneParameter* param = findSceneParameter(key);
        if (!param)
            continue;
        switch (param->type) {
        case ParameterType::Integer: params.set(key, param->integerIn(values)); break;
        case ParameterType::Number:
            if (key == "radius" && s.radiusFromFrame)
                params.set(key, kFromFrame);
            else
                params.set(key, param->numberIn(values));
            break;
        case ParameterType::Pair:
            if (key == "center" && s.centerFromFrame)
                params.set(key, kFromFrame);
            else
                params.set(key, pointJson(param->pairIn(values)));
            break;
        case ParameterType::Choice:
            for (const GrabChoice& c : grabChoices())
                if (c.mode == s.grab)
                    params.set(key, c.name);
            break;
        case ParameterType::Chain: {
            Json a = Json::array();
            for (double l : s.chain)
                a.push(l);
            params.set(key, a);
            break;
        }
        case ParameterType::Legs: {
            Json legs = Json::object();
            for (std::size_t i = 0; i < legParts().size(); ++i)
                legs.set(legParts()[i].name, pointJson(Point(p.legs[2 * i].upper, p.legs[2 * i].lower)));
            params.set(key, legs);
            break;
        }
        case ParameterType::AngleLimits: {
            Json limits = Json::object();
            for (const AngleLimitParameter& l : angleLimits())
                if (l.belongsTo(s))
                    limits.set(l.name, pointJson(l.in(s)));
            params.set(key, limits);
            break;
        }
        case ParameterType::Obstacles: {
            Json list = Json::array();
            for (const auto& o : s.obstacles)
                list.push(Json::object().set(o.closed ? "polygon" : "segment", pointsJson(o.points)));
            params.set(key, list);
            break;
        }
        case ParameterType::Shapes: {
            Json list = Json::array();
            for (const auto& sh : s.shapes)
                list.push(Json::object().set("name", sh.name).set("points", pointsJson(sh.points)).set("at", pointJson(sh.at)));
            params.set(key, list);
            break;
        }
        }
    }
    Json components = Json::array();
    for (const SceneComponent c : s.components)
        components.push(std::string(sceneComponentName(c)));
    const char* model = s.model == SceneModel::Stage      ? "stage"
                        : s.model == SceneModel::Body     ? "body"
                        : s.model == SceneModel::Pendulum ? "pendulum"
                                                          : "frog";
    Json doc = Json::object();
    doc.set("name", s.name)
        .set("section", s.section)
        .set("title", s.title)
        .set("description", s.description)
        .set("model", model)
        .set("order", s.order)
        .set("components", components)
        .set("params", params);
    if (s.sketchFirstFrame)
        doc.set(kFirstFrameKey, kSketchFrame);
    if (!s.stable.isDefault()) {
        doc.set("stable", stableSettingsToJson(s.stable));
    }
    return doc;
}

Json stableSettingsToJson(const StableSettings& stable)
{
    Json out = Json::object();
    const auto key = [](StableKnob k) { return std::string(stableKnobName(k)); };
    out.set(key(StableKnob::Substeps), stable.substeps).set(key(StableKnob::EdgeCompliance), stable.edgeCompliance);
    if (stable.edgeDampingRatio != 0) // written only when set, as "stable" itself
        out.set(key(StableKnob::EdgeDampingRatio), stable.edgeDampingRatio);
    return out;
}

} // namespace granota
