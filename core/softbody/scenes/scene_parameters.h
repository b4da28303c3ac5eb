#pragma once
/// \file scene_parameters.h
/// Every parameter a scene file may hold (docs/scenes.md, "Parameters"), in one table: its key,
/// its type, where its value lives in a SceneSpec, the whole numbers the core accepts, the
/// thesis's name (Annex II, chapter 4), and what the Frog tab's parameter panel shows — the unit,
/// the spin box's range and step, an English label and tooltip. The scene reader and `--set`
/// (scene.cpp: setParam, applySetting, the magnitude check), the scene writer (sceneToJson) and
/// the panel (ui/frog/frog_parameters_panel.cpp) all read it; no other list of keys exists.
///
/// The labels and tooltips are marked with QT_TRANSLATE_NOOP in the panel's context,
/// kParameterPanelContext, so the panel's translate() finds the Catalan texts of
/// translations/granota_ca.ts under "granota::ui::FrogParametersPanel".

#include "core/base/vec2.h"
#include "core/softbody/scenes/frog_params.h"
#include "core/softbody/scenes/grab_mode.h"

#include <string>
#include <vector>

namespace granota {

struct SceneSpec;

/// The translation context of the table's labels and tooltips: the panel that shows them.
inline constexpr const char* kParameterPanelContext = "granota::ui::FrogParametersPanel";

/// What a parameter's value is in the scene file; `--set` takes the first four.
enum class ParameterType {
    Integer,     ///< a whole number in [min, max]; --set N
    Number,      ///< a number; --set x
    Pair,        ///< [x, y]; --set x,y
    Choice,      ///< a name of grabChoices(); --set name
    Chain,       ///< [length, …]: the pendulum's links, 1 to 100
    Legs,        ///< {"front": [upper, lower], "back": [upper, lower]} (legParts())
    AngleLimits, ///< {"name": [min, max], …} (angleLimits()), radians
    Obstacles,   ///< [{"segment": [p, q]} or {"polygon": [p, …]}, …]
    Shapes,      ///< [{"name", "points", "at"}, …]
};

/// The panel's spin box for a parameter, in the unit it shows (degrees for angle limits). Wide
/// ranges on purpose: docs/extreme-cases.md lists huge gravity, target area 0 or huge, 3 to 200
/// sides and more; the core refuses what makes no sense, with a message.
struct SpinRange {
    bool symmetric = false; ///< from −max to max (min unused), else from min
    double min = 0, max = 0;
    int decimals = 0;
    double step = 0;
    double lowest() const { return symmetric ? -max : min; }
};

/// Where an Integer, Number or Pair parameter's value lives: the one member pointer of its type.
struct ParameterField {
    int FrogParams::*frogInteger = nullptr;
    int SceneSpec::*sceneInteger = nullptr;
    double FrogParams::*number = nullptr;
    Point FrogParams::*pair = nullptr;
};

struct SceneParameter {
    const char* key = ""; ///< the scene file's and --set's key, e.g. "spring_length"
    ParameterType type = ParameterType::Number;
    const char* thesisName = ""; ///< Annex II's or chapter 4's name, e.g. "molls"; "" if none
    const char* unit = "";       ///< the unit the panel shows (translated there), "" if none
    int min = 0, max = 0;        ///< Integer: the values the core accepts
    SpinRange spin;              ///< the panel's spin boxes (Integer, Number, Pair, Chain, Legs, AngleLimits)
    ParameterField field;        ///< Integer, Number, Pair: where the value lives
    const char* label = "";      ///< the panel's row (Chain: "Link %1"; Legs, AngleLimits: per part)
    const char* tip = "";        ///< the panel's tooltip (AngleLimits: per limit)
    const char* fileNote = "";   ///< Obstacles, Shapes: the panel's note that the file gives them

    /// The value in `s`, as the type says (integerIn for Integer, …).
    int& integerIn(SceneSpec& s) const;
    double& numberIn(SceneSpec& s) const;
    Point& pairIn(SceneSpec& s) const;
    /// Integer, Number, Pair and Choice are set with --set; the others only in the file.
    bool settable() const;
};

/// Every parameter. The order is that of the core's magnitude check (its first number beyond
/// 1e15 names the error); the file writer and the panel follow the scene file's order.
const std::vector<SceneParameter>& sceneParameters();
/// The parameter `key`, or nullptr.
const SceneParameter* findSceneParameter(const std::string& key);

/// A named part of a parameter's value, with the panel's label.
struct ParameterPart {
    const char* name;
    const char* label;
};
/// `legs`: "front" (legs 0 and 1 of FrogParams::legs) and "back" (legs 2 and 3).
const std::vector<ParameterPart>& legParts();

/// One limit of `angle_limits` (§4.15), [min, max] in radians.
struct AngleLimitParameter {
    enum class Joint {
        Shoulder, ///< the upper segment's angle (Annex II's anglesc)
        Elbow,    ///< the angle between the two segments (Annex II's angles)
    };
    static constexpr int kChain = -1; ///< `leg` of the pendulum's limits

    const char* name;  ///< e.g. "shoulder_front_right"
    const char* label; ///< the panel's row
    const char* tip;   ///< the panel's tooltip
    Joint joint;
    int leg; ///< FrogParams::legs index (an elbow limit: this leg and the next), or kChain

    bool pendulum() const { return leg == kChain; }
    /// The frog's limits belong to every scene but the pendulum's, the pendulum's to it alone.
    bool belongsTo(const SceneSpec& s) const;
    /// The limit's [min, max] in `s`; setIn writes it (an elbow limit to both legs of its pair).
    Point in(const SceneSpec& s) const;
    void setIn(SceneSpec& s, Point q) const;
};
/// The frog's six (four shoulders, two elbow pairs), then the pendulum's two, in the panel's order.
const std::vector<AngleLimitParameter>& angleLimits();

/// The numbers a panel shows of parameter `p` in `s`: parts × components. Parts: the leg pairs
/// (legParts()), the angle limits that belong to the scene (in angleLimits()' order), the links
/// of the chain, or 1; none for Obstacles and Shapes (the file gives them). Components: 2 for
/// Pair, Legs and AngleLimits (x and y, upper and lower, min and max), else 1.
int parameterPartCount(const SceneSpec& s, const SceneParameter& p);
int parameterComponentCount(const SceneParameter& p);
/// The number at (part, index) of `p` in `s` (radians for angle limits; the index of
/// grabChoices() for Choice); what withParameter (scene.h) sets. 0 for a place `p` lacks.
double parameterNumber(const SceneSpec& s, const SceneParameter& p, int part, int index);
/// The part-th angle limit of `s` (parameterPartCount), or nullptr.
const AngleLimitParameter* angleLimitOf(const SceneSpec& s, int part);

/// One value of `grab`.
struct GrabChoice {
    const char* name; ///< the file's and --set's value: all, above, anchors
    GrabMode mode;
    const char* label; ///< the panel's list
};
const std::vector<GrabChoice>& grabChoices();

} // namespace granota
