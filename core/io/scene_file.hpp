#pragma once
// Scene files: JSON with "format": "lagrangelab-scene/1" (see examples/).
//
// Field paths in diagnostics and in Scene::expressions number everything from 1,
// as the student reads it in the textbook: joints ("robot.joints[2].a"), effect
// entries ("effects.springs[1].stiffness") and the entries of plain arrays
// ("robot.joints[2].com[1]" is the x coordinate, "initial.q[3]" is q3,
// "effects.gravity[2]" is the y component). Parameters are "parameters.<name>".
// Joints named in effects are 1-based in the file and 0-based in the structs.
//
// Every numeric field may be a number or a string expression of the parameters
// (see core/symbolic/expression.hpp), except the joint numbers of effects, which are
// integers. Unknown keys are errors, so a misspelt effect is never dropped silently.
#include <string>
#include <vector>

#include "core/model/diagnostics.hpp"
#include "core/model/scene.hpp"

namespace ll {

struct LoadedScene {
    Scene scene;
    std::vector<Diagnostic> warnings;  // from requireValidScene, fields prefixed as in loadScene
};

// Reads the structure and evaluates the expressions; no physical checks. Throws
// InputError with every error found (a JSON syntax error alone, first).
Scene parseScene(const std::string& jsonText);

// Reads the file, parses it and runs requireValidScene. A mesh path of the robot's look
// (robot.links) relative to the file becomes absolute. Every diagnostic it throws
// or returns names the file: its field is "<path>: <field path>", or just "<path>"
// for whole-file problems (unreadable, JSON syntax errors).
LoadedScene loadScene(const std::string& path);

// Pretty JSON, 2-space indent, keys in the order of the format. A field listed in
// Scene::expressions is written as its expression text, not its value, so whoever
// changes such a value must erase (or update) its entry.
std::string serializeScene(const Scene& scene);

// Writes atomically with saveFileAtomically (core/io/atomic_file.hpp): PATH is always
// either the old or the new file, whole, and an existing PATH is first copied to
// PATH.bak, the recovery copy. Mesh paths are written relative to PATH's folder. Throws std::runtime_error naming the path if anything
// fails; PATH is then untouched.
void saveScene(const Scene& scene, const std::string& path);

}  // namespace ll
