#pragma once
// Every term of B q̈ + C q̇ + g = Q at one state of a scene, robot or hand-typed
// Lagrangian, as plain data: what `lagrangelab eval` prints (and what the mutation
// tests call in-process). A Lagrangian is derived and compiled under the GiNaC lock.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/dynamics/compiled_lagrangian.hpp"
#include "core/model/scene.hpp"

namespace ll {

struct SceneEvaluation {
    ModelTerms terms;           // B, C, g, Q, E_kin, E_pot
    Eigen::VectorXd qdd;        // B⁻¹(Q − C q̇ − g)
    std::vector<int> actuated;  // 0-based coordinates with an input (without tau)
    bool underactuated = false;
    std::vector<std::string> coordinates;  // a Lagrangian's names; empty for a robot
};

// Q: the scene's torques or forces at t, or `tau` in place of its inputs, plus
// friction at q̇. The scene must be valid (requireValidScene). Throws InputError when
// B is not positive definite at q (field "q") and when any term is not finite (field:
// the quantity, "Epot", "qdd", ...); never returns a non-finite number.
SceneEvaluation evaluateScene(const Scene& scene, const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t,
                              const std::optional<Eigen::VectorXd>& tau = std::nullopt);

}  // namespace ll
