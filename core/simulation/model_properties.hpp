#pragma once
// The properties every Euler–Lagrange model has, checked along a run of a scene: each
// with its worst value over the run, the time and pose where it occurs, the tolerance it
// passes within, and one sentence a student can read. What `lagrangelab check` prints
// and the window's Properties panel shows.
//   min_eigenvalue_B        the smallest eigenvalue of B(q): B is positive definite
//   max_condition_B         the largest condition number of B(q)
//   skew_residual           max |xᵀ(Ḃ − 2C)x| / (‖x‖² ‖B‖) at random x [1/s]
//   power_balance_residual  |dE/dt − q̇ᵀQ| relative to the run's power scale
//   newton_euler_residual   recursive Newton–Euler against B q̈ + C q̇ + g, relative (robots)
//   energy_error            max |E − E₀ − W| relative to the run's energy scale
// A robot's Ḃ comes from the exact ∂B/∂q_k of the numeric core; a typed Lagrangian's from
// central differences of its compiled B along q̇, so its tolerances are looser.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/simulation/simulate.hpp"
#include "core/simulation/trajectory.hpp"

namespace ll {

struct PropertyCheck {
    std::string key;          // the JSON key: min_eigenvalue_B, …
    std::string title;        // "B is positive definite"
    std::string explanation;  // one sentence a student reads
    bool applies = true;      // false: not for this kind of scene (Newton–Euler for a typed Lagrangian)
    double value = 0.0;       // the worst over the run
    double tolerance = 0.0;
    bool atLeast = false;  // passes when value ≥ tolerance (an eigenvalue), else when value ≤ tolerance
    bool passed = true;
    std::string unit;   // of value and tolerance ("" for relative ones)
    double time = 0.0;  // where the worst value occurs
    Eigen::VectorXd q;
};

struct ModelProperties {
    std::vector<PropertyCheck> checks;
    bool passed() const;
    const PropertyCheck* find(const std::string& key) const;
};

// Throws std::invalid_argument when the trajectory does not fit the scene or is empty.
ModelProperties checkModelProperties(const SimulationInput& input, const Trajectory& trajectory);

}  // namespace ll
