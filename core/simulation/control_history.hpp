#pragma once
// The declared controller (core/model/control.hpp) along a run: its terms at every sample,
// how well it tracked, what it spent, and — for PD and PD + g holding a pose — the
// Lyapunov function whose fall the skew property guarantees. What `simulate --out`,
// `check`, `compare-laws` and the window's Tracking tab show.
//
// Lyapunov (reference held, q̇_d = 0 between steps; B, g the robot's own):
//   pd_gravity  V = ½ q̇ᵀB q̇ + ½ eᵀK_p e
//   pd          V = ½ q̇ᵀB q̇ + ½ eᵀK_p e + E_pot(q) − E_pot(q_d)
// With q̈ from the equations of motion, V̇ = q̇ᵀB q̈ + ½ q̇ᵀḂ q̇ − eᵀK_p q̇ (+ gᵀq̇ for pd)
// = −q̇ᵀK_d q̇ + q̇ᵀ(ĝ − g) + q̇ᵀQ_rest, because q̇ᵀ(Ḃ − 2C)q̇ = 0: the dissipation alone when
// the controller's ĝ is the robot's g and nothing else acts (Q_rest: friction, typed
// torques, saturation's shortfall). V̇ here is computed from that first form (Ḃ from the
// exact ∂B/∂q_k), never from the second, so the two agreeing is the property, not an identity.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/simulation/controller.hpp"
#include "core/simulation/simulate.hpp"
#include "core/simulation/torque_parts.hpp"
#include "core/simulation/trajectory.hpp"

namespace ll {

struct LyapunovHistory {
    std::vector<double> V;            // [J]
    std::vector<double> Vdot;         // [W] q̇ᵀB q̈ + ½ q̇ᵀḂ q̇ − eᵀK_p q̇ (+ gᵀq̇)
    std::vector<double> dissipation;  // [W] −q̇ᵀK_d q̇
    // max |V̇ + q̇ᵀK_d q̇| over the run relative to max q̇ᵀK_d q̇ (0 when nothing moves).
    double largestDeparture = 0.0;
};

struct TrackingSummary {
    Eigen::VectorXd rmsError;           // per joint, over the samples [rad or m]
    Eigen::VectorXd maxError;           // max |e_i|
    Eigen::VectorXd maxTorque;          // max |τ_i| (after the limits) [N·m or N]
    Eigen::VectorXd saturatedFraction;  // of the samples where |τ_i| was clipped to its limit
    double energySpent = 0.0;           // ∫ Σ |τ_i q̇_i| dt [J]: the actuators' work, none given back
};

struct ControlHistory {
    std::vector<ControlParts> parts;          // one per sample of the trajectory
    std::optional<LyapunovHistory> lyapunov;  // pd and pd_gravity with a held (or stepped) reference
    TrackingSummary summary;
};

// True when the scene's control has the Lyapunov function above (pd or pd_gravity, the
// reference hold or step).
bool hasLyapunovFunction(const Control& control);

// The controller's history along `trajectory`, a run of `input`'s robot scene with a
// control; `torques` is torqueHistory of the same run (its q̈). Throws
// std::invalid_argument for a scene without a controller or a trajectory that does not fit.
ControlHistory controlHistory(const SimulationInput& input, const Trajectory& trajectory, const TorqueHistory& torques);

}  // namespace ll
