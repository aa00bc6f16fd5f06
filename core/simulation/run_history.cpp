#include "core/simulation/run_history.hpp"

#include "core/dynamics/forward_dynamics.hpp"

namespace ll {

RunHistory runHistory(const SimulationInput& input, const Trajectory& trajectory) {
    RunHistory history;
    try {
        history.torques = torqueHistory(input, trajectory);
        if (!input.scene.lagrangian && input.scene.effects.control) history.control = controlHistory(input, trajectory, *history.torques);
    } catch (const SingularMassMatrix&) {
        history = {};
    }
    return history;
}

}  // namespace ll
