#pragma once
// Writing a Scene as a scene file's JSON, keys in the order of the format; a field listed
// in Scene::expressions as its expression text, not its value.
#include "core/io/scene_json.hpp"
#include "core/model/scene.hpp"

namespace ll {

// Needs GiNaC's lock held (expressions are re-checked).
scene_json::Json writeScene(const Scene& scene);

}  // namespace ll
