#include "core/pipeline/scene_check.hpp"

#include "core/simulation/scene_validation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"

namespace ll {

std::vector<Diagnostic> checkScene(const Scene& scene) {
    std::vector<Diagnostic> out = validateScene(scene);
    if (scene.lagrangian && !hasErrors(out)) try {
            const auto lock = symbolic::lockGinac();
            (void)symbolic::deriveLagrangian(scene, symbolic::ParameterMode::Numeric);
        } catch (const InputError& e) {
            out.insert(out.end(), e.diagnostics().begin(), e.diagnostics().end());
        }
    return out;
}

}  // namespace ll
