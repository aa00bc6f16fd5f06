#pragma once
// Every term of a robot scene's B q̈ + C q̇ + g = Q at one state, from the numeric core:
// what `eval` prints and what the validation checks at the initial state.
#include <optional>

#include <Eigen/Core>

#include "core/dynamics/compiled_lagrangian.hpp"
#include "core/model/scene.hpp"

namespace ll {

struct RobotEvaluation {
    ModelTerms terms;     // B, C, g, Q, E_kin, E_pot
    Eigen::VectorXd qdd;  // B⁻¹(Q − C q̇ − g); empty when a term is not finite
};

// Q is the scene's torques at t (or `tau` in their place) plus friction at q̇. Throws
// SingularMassMatrix (core/dynamics/forward_dynamics.hpp) when B is not positive
// definite, std::invalid_argument when a vector does not have dof() entries.
RobotEvaluation evaluateRobot(const Scene& scene, const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t,
                              const std::optional<Eigen::VectorXd>& tau = std::nullopt);

}  // namespace ll
