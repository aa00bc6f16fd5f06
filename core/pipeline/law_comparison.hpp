#pragma once
// `lagrangelab compare-laws`: a controlled scene run under each law in turn (pd,
// pd_gravity, computed_torque, feedforward) with its own gains, reference, controller
// model and limits, and how each did: tracking error, torque, the actuators' work,
// time spent saturated. A law the robot cannot carry out (computed torque with fewer
// actuated joints than joints) is listed with the reason instead of a run.
#include <optional>
#include <vector>

#include "core/model/control.hpp"
#include "core/model/message.hpp"
#include "core/model/scene.hpp"
#include "core/simulation/control_history.hpp"
#include "core/simulation/trajectory.hpp"

namespace ll {

struct LawRun {
    ControlLaw law = ControlLaw::Pd;
    Message impossible;         // why this law cannot drive this robot; empty: it ran
    SimulationResult result;    // the run (partial when it stopped early: result.message says why)
    std::vector<double> error;  // max_i |e_i| at each sample
    std::vector<double> torque; // max_i |τ_i| at each sample
    TrackingSummary summary;
    double saturatedSeconds = 0.0;  // the largest joint's saturated fraction × the simulated time
};

// The scene must be a valid robot scene with effects.control; throws std::invalid_argument
// otherwise. Runs one law after the other on the calling thread.
std::vector<LawRun> compareLaws(const Scene& scene);

}  // namespace ll
