#pragma once
/// \file scene_texts.h
/// What each built-in scene is called, in one place: its section of the thesis ("4.10"), its
/// English title ("Revised Bézier") and a one-sentence description. The scene files
/// (resources/scenes/*.json) hold only the scene's data; the reader (scene.h) takes these texts
/// for a built-in scene, the CLI prints them, and the Frog tab shows "4.10 Revised Bézier"
/// translated. The texts are marked with QT_TRANSLATE_NOOP in the tab's context,
/// kSceneTextContext, so translate() finds the Catalan of translations/granota_ca.ts under
/// "granota::ui::FrogTab". A scene file of the user's own may carry its own "section",
/// "title" and "description"; those are its data and are not translated.

#include <string>
#include <vector>

namespace granota {

/// The translation context of the texts: the tab that shows them.
inline constexpr const char* kSceneTextContext = "granota::ui::FrogTab";

struct SceneText {
    const char* name;        ///< the scene's name, e.g. "bezier-revised"
    const char* section;     ///< the thesis's section, e.g. "4.10"
    const char* title;       ///< e.g. "Revised Bézier"
    const char* description; ///< one sentence
};

/// Every scene's texts, in the thesis's order.
const std::vector<SceneText>& sceneTexts();
/// The texts of scene `name`, or nullptr.
const SceneText* findSceneText(const std::string& name);

} // namespace granota
