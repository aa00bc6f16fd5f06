#include "core/pipeline/scene_simulation.hpp"

#include "core/symbolic/compiled_derivation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"

namespace ll {

SimulationInput prepareSimulation(const Scene& scene) {
    SimulationInput input{scene, std::nullopt};
    if (scene.lagrangian) {
        const auto lock = symbolic::lockGinac();
        input.lagrangian = symbolic::compileDerivation(symbolic::deriveLagrangian(scene, symbolic::ParameterMode::Numeric));
    }
    return input;
}

SimulationResult simulate(const Scene& scene, const SimulationSettings& settings, const ProgressCallback& progress,
                          const std::atomic<bool>* cancel) {
    return simulate(prepareSimulation(scene), settings, progress, cancel);
}

WorkPrecisionResult runWorkPrecision(const Scene& scene, const WorkPrecisionSettings& settings,
                                     const WorkPrecisionProgress& progress, const std::atomic<bool>* cancel) {
    return runWorkPrecision(prepareSimulation(scene), settings, progress, cancel);
}

}  // namespace ll
