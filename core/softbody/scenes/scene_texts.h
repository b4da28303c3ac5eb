#pragma once
/// \file scene_texts.h
/// The scenes' titles and descriptions as the Frog tab shows them, one place for all: each
/// scene's English title (its section first, "4.10 Revised Bézier") and one-sentence
/// description, marked with QT_TRANSLATE_NOOP in the tab's context, kSceneTextContext, so the
/// tab's translate() finds the Catalan texts of translations/granota_ca.ts under
/// "granota::ui::FrogTab".
///
/// The scene files (resources/scenes/*.json) keep their own `title` and `description`: the
/// file's data, which `simulate` prints and sceneToJson writes back.

#include <string>
#include <vector>

namespace granota {

/// The translation context of the texts: the tab that shows them.
inline constexpr const char* kSceneTextContext = "granota::ui::FrogTab";

struct SceneText {
    const char* name;        ///< the scene's name, e.g. "bezier-revised"
    const char* title;       ///< e.g. "4.10 Revised Bézier"
    const char* description; ///< one sentence
};

/// Every scene's texts, in the thesis's order.
const std::vector<SceneText>& sceneTexts();
/// The texts of scene `name`, or nullptr.
const SceneText* findSceneText(const std::string& name);

} // namespace granota
