#pragma once
// A scene file's JSON as the user typed it: expressions, degrees, parameter names and the
// order of the keys kept (scene_document.hpp edits it).
#include <nlohmann/json.hpp>

namespace ll::ui {

using SceneJson = nlohmann::ordered_json;

}  // namespace ll::ui
