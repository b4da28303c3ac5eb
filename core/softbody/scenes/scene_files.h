#pragma once
/// \file scene_files.h
/// The text of every resources/scenes/NAME.json, compiled in (see core/CMakeLists.txt).

#include <string_view>
#include <utility>
#include <vector>

namespace granota {

/// (name, JSON text) for every scene file, in file-name order.
const std::vector<std::pair<std::string_view, std::string_view>>& sceneFiles();

} // namespace granota
