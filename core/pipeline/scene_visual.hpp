#pragma once
// A scene's 3D picture (core/visual: plain data, no GiNaC), for callers on any thread. A
// typed Lagrangian's bodies are posed by expressions of q and t, compiled here once
// (core/symbolic/compiled_body_poses, under the GiNaC lock); a robot's by its DH table.
#include "core/model/scene.hpp"
#include "core/visual/visual_scene.hpp"

namespace ll {

// Throws InputError naming lagrangian.bodies[i]… for a body expression that does not parse.
VisualScene visualScene(const Scene& scene);

}  // namespace ll
