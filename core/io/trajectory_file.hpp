#pragma once
// Writing a simulated trajectory: CSV (one row per sample: t, q1..qn, qd1..qdn,
// Ekin, Epot, E, W) or JSON (the same columns as arrays, plus the run's statistics;
// for a fixed-step method also its step grid and how many samples were interpolated).
#include <ostream>
#include <string>
#include <vector>

#include "core/model/scene.hpp"
#include "core/simulation/control_history.hpp"
#include "core/simulation/torque_parts.hpp"
#include "core/simulation/trajectory.hpp"

namespace ll {

// Where the torque goes along the run (core/simulation/torque_parts.hpp), as more
// columns: tau_inertial_i (B q̈), tau_coriolis_i (C q̇), tau_potential_i (g), Q_i and its
// parts Q_actuation_i, Q_viscous_i, Q_coulomb_i, each joint in its unit (N·m or N; ""
// for a typed Lagrangian's). CSV names carry the unit ("tau_inertial_1 [N·m]"); JSON
// keys are the plain names with a "units" object beside them.
//
// A controlled scene (core/simulation/control_history.hpp) adds the controller's columns:
// q_ref_i and e_i = q_ref_i − q_i in the coordinate's unit, tau_ctrl_i (the torque applied,
// after the limits) and its terms tau_ctrl_inertial_i (B̂ q̈_d), tau_ctrl_coriolis_i (Ĉ q̇),
// tau_ctrl_gravity_i (ĝ), tau_ctrl_kp_i (K_p e), tau_ctrl_kd_i (K_d ė); with a Lyapunov
// function also V [J], Vdot [W] and minus_qdT_Kd_qd [W] (−q̇ᵀK_d q̇).
struct TorqueColumns {
    const TorqueHistory* history = nullptr;          // its samples are the trajectory's
    std::vector<std::string> units;                  // (n) per joint
    const ControlHistory* control = nullptr;         // its samples are the trajectory's
    std::vector<std::string> coordinateUnits;        // (n) per joint: rad or m
};
// The units the columns of a robot scene's run are in (empty strings for a Lagrangian's).
TorqueColumns torqueColumns(const Scene& scene, const TorqueHistory& history);

// The units of a scene's coordinates, one per coordinate: rad or m by joint type for a
// robot, "" for a typed Lagrangian's (its coordinates carry no declared unit).
std::vector<std::string> coordinateUnits(const Scene& scene);

// `units` (optional, one per coordinate as coordinateUnits gives): the header then names
// every column's unit, "t [s]", "q1 [rad]", "qd1 [rad/s]", "Ekin [J]" (the lab report).
void writeTrajectoryCsv(const Trajectory& trajectory, std::ostream& out, const TorqueColumns& torques = {},
                        const std::vector<std::string>* units = nullptr);
void writeTrajectoryJson(const SimulationResult& result, std::ostream& out, const TorqueColumns& torques = {});

// Chooses the format by extension (.csv or .json) and writes atomically
// (saveFileAtomically, no .bak). Throws MessageError (a std::runtime_error) naming the path.
void saveTrajectory(const SimulationResult& result, const std::string& path, const TorqueColumns& torques = {});

}  // namespace ll
