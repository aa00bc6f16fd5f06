#pragma once
// Where the torque goes: the terms of B q̈ + C q̇ + g = Q along a run, per joint, with Q
// split as the scene declares it (the torques typed as actuation, viscous friction,
// Coulomb friction; a typed Lagrangian's Q whole, as actuation). For a robot, q̈ at each
// sample is the simulation's own (C q̇ + g by recursive Newton–Euler, then B's Cholesky
// solve) while C q̇ and g are the Lagrangian route's (Christoffel symbols of B, the
// potential's gradient), so `residual` is the two routes' disagreement plus rounding;
// a typed Lagrangian's parts come from its compiled B, C, g alone. Coulomb friction is
// its sliding (or smoothed) law: a joint held at rest by the stick model shows no
// Coulomb part there.
#include <vector>

#include <Eigen/Core>

#include "core/simulation/simulate.hpp"
#include "core/simulation/trajectory.hpp"

namespace ll {

struct TorqueParts {
    Eigen::VectorXd inertial;   // B q̈
    Eigen::VectorXd coriolis;   // C q̇
    Eigen::VectorXd potential;  // g: gravity and springs
    Eigen::VectorXd actuation;  // the declared torques and forces (a Lagrangian's whole Q)
    Eigen::VectorXd viscous;    // −b q̇
    Eigen::VectorXd coulomb;    // −F_c sign q̇ (or its smooth law)
    Eigen::VectorXd qdd;        // the accelerations they make
    Eigen::VectorXd Q() const { return actuation + viscous + coulomb; }
    // max_i |(B q̈ + C q̇ + g − Q)_i|
    double residual() const;
};

struct TorqueHistory {
    std::vector<double> t;
    std::vector<TorqueParts> parts;  // one per sample of the trajectory
    double largestResidual = 0.0;    // over the run
    // The residual's scale: the largest |B q̈|, |C q̇|, |g| or |Q| of any joint over the run.
    double scale = 0.0;
};

// The parts at every sample of `trajectory`, a run of `input`'s scene. Throws
// std::invalid_argument when the trajectory does not fit the scene, SingularMassMatrix
// when B is singular at a sample.
TorqueHistory torqueHistory(const SimulationInput& input, const Trajectory& trajectory);

}  // namespace ll
