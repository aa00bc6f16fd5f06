#include "core/pipeline/law_comparison.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/pipeline/scene_simulation.hpp"
#include "core/simulation/run_history.hpp"

namespace ll {

std::vector<LawRun> compareLaws(const Scene& scene) {
    if (scene.lagrangian || !scene.effects.control) throw std::invalid_argument("compareLaws: the scene declares no controller");
    std::vector<LawRun> runs;
    for (ControlLaw law : {ControlLaw::Pd, ControlLaw::PdGravity, ControlLaw::ComputedTorque, ControlLaw::Feedforward}) {
        LawRun run;
        run.law = law;
        Scene variant = scene;
        variant.effects.control->law = law;
        run.impossible = lawImpossible(*variant.effects.control, scene.dof());
        if (!run.impossible.empty()) {
            runs.push_back(std::move(run));
            continue;
        }
        const SimulationInput input = prepareSimulation(variant);
        run.result = simulate(input, variant.simulation);
        const Trajectory& tr = run.result.trajectory;
        // Nothing when B is singular on the run: it stopped there and says so in result.message.
        if (const RunHistory history = runHistory(input, tr); history.control) {
            for (const ControlParts& p : history.control->parts) {
                run.error.push_back(p.error.cwiseAbs().maxCoeff());
                run.torque.push_back(p.tau.cwiseAbs().maxCoeff());
            }
            run.summary = history.control->summary;
            if (run.summary.saturatedFraction.size() > 0)
                run.saturatedSeconds = run.summary.saturatedFraction.maxCoeff() * run.result.stats.simulatedSeconds;
        }
        runs.push_back(std::move(run));
    }
    return runs;
}

}  // namespace ll
