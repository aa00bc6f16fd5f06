#include "core/pipeline/scene_visual.hpp"

#include "core/symbolic/compiled_body_poses.hpp"

namespace ll {

VisualScene visualScene(const Scene& scene) {
    if (!scene.lagrangian) return VisualScene(scene);
    return VisualScene(scene, symbolic::compileBodyPoses(scene));
}

}  // namespace ll
