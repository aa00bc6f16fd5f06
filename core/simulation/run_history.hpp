#pragma once
// What the torques and the controller did along a run, for `simulate --out`, `check` and
// compare-laws alike: torqueHistory, and controlHistory when the scene declares a
// controller; neither when B is singular somewhere on the run (the simulation stopped
// there and says so in its message).
#include <optional>

#include "core/simulation/control_history.hpp"
#include "core/simulation/simulate.hpp"
#include "core/simulation/torque_parts.hpp"

namespace ll {

struct RunHistory {
    std::optional<TorqueHistory> torques;
    std::optional<ControlHistory> control;  // a robot scene with a controller only
};

// `trajectory` is a run of `input` (throws std::invalid_argument when it does not fit).
RunHistory runHistory(const SimulationInput& input, const Trajectory& trajectory);

}  // namespace ll
