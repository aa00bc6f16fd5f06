#pragma once
// Renaming a parameter of a scene: its entry under "parameters" keeps its place and
// value, and every expression that uses it is rewritten, whole names only (a1 in
// "lc1-a1" and "a1/2", not in "a10" or "1e1"). Prose is left alone: name, description,
// source, and the words of the format (convention, joint types, the integrator).
#include <string>
#include <vector>

#include "ui/document/scene_document.hpp"

namespace ll::ui {

// The scene with parameter `from` called `to` (the caller checks that `to` is a free,
// valid name). Unchanged when there is no parameter `from`.
SceneJson renamedParameter(const SceneJson& scene, const std::string& from, const std::string& to);

// `text` with every whole-name occurrence of `from` replaced by `to`.
std::string renamedInExpression(const std::string& text, const std::string& from, const std::string& to);

// The whole names `text` uses, in order, each once ("lc1-a1/2" → lc1, a1; "1e1" → none).
std::vector<std::string> namesInExpression(const std::string& text);

// Whether the strings under `key` are words (name, description, joint type, integrator),
// not expressions of the parameters.
bool proseKey(const std::string& key);

}  // namespace ll::ui
