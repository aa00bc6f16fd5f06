#pragma once
// Reading a scene file's JSON into a Scene: every section (format, parameters, the robot
// or a typed Lagrangian, effects, initial state, simulation), each field checked and its
// expression evaluated, every error collected with its field path (core/io/scene_file.hpp
// says how paths count).
#include <vector>

#include "core/io/scene_json.hpp"
#include "core/model/diagnostics.hpp"
#include "core/model/scene.hpp"

namespace ll {

// The scene `root` describes. Throws InputError with every error found, after
// `duplicates` (the text's duplicate keys). Warnings (angles that look like degrees typed
// as radians) go to *warnings. Holds no lock: the caller holds GiNaC's.
Scene readScene(const scene_json::Json& root, std::vector<Diagnostic> duplicates, std::vector<Diagnostic>* warnings = nullptr);

}  // namespace ll
