#include "core/pipeline/scene_simulation.hpp"

#include "core/dynamics/finite_terms.hpp"
#include "core/symbolic/compiled_body_poses.hpp"
#include "core/symbolic/compiled_derivation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"

namespace ll {

SimulationInput prepareSimulation(const Scene& scene) {
    SimulationInput input{scene, std::nullopt};
    if (scene.lagrangian) {
        const auto lock = symbolic::lockGinac();
        input.lagrangian = symbolic::compileDerivation(symbolic::deriveLagrangian(scene, symbolic::ParameterMode::Numeric));
        // A robot's initial terms are checked by requireValidScene; a Lagrangian's here.
        if (scene.initial.q.size() == scene.dof() && scene.initial.qd.size() == scene.dof())
            if (auto bad = nonFiniteTerm(input.lagrangian->terms(scene.initial.q, scene.initial.qd, 0.0), Eigen::VectorXd(),
                                         scene.initial.q, scene.initial.qd, MessageId::WhereInitialState))
                throw InputError({*bad});
    }
    return input;
}

PreparedScene prepareScene(const Scene& scene) {
    PreparedScene prepared{prepareSimulation(scene), std::nullopt};
    if (scene.lagrangian) prepared.bodies = symbolic::compileBodyPoses(scene);
    return prepared;
}

SimulationResult simulate(const Scene& scene, const SimulationSettings& settings, const ProgressCallback& progress,
                          const std::atomic<bool>* cancel) {
    return simulate(prepareSimulation(scene), settings, progress, cancel);
}

WorkPrecisionResult runWorkPrecision(const Scene& scene, const WorkPrecisionSettings& settings, const WorkPrecisionProgress& progress,
                                     const std::atomic<bool>* cancel) {
    return runWorkPrecision(prepareSimulation(scene), settings, progress, cancel);
}

}  // namespace ll
