#pragma once
// The derivation's results at one pose, for the window's teach mode: E_kin, E_pot, B(q),
// C(q, q̇) and g(q) with the numbers of this state in them, as a display step (numbered
// poseStepNumber) the derivation view shows after the derivation's last step. The values come from the numeric core (which
// agrees with the symbolic derivation to 1e-12, tests/test_symbolic_vs_numeric), so a
// slider move costs microseconds, not a re-derivation, and no GiNaC (any thread).
// Shown with 4 significant digits; each item's note gives its units.
#include <Eigen/Core>

#include "core/model/scene.hpp"
#include "core/present/derivation_document.hpp"

namespace ll {

inline constexpr int poseStepNumber = symbolic::lastDerivationStep + 1;

// q: the pose; qd: the velocities C(q, q̇) and E_kin are taken at (the scene's initial
// q̇ in the window). A robot scene (a hand-typed Lagrangian has no robot to pose).
present::DisplayStep poseResults(const Scene& scene, const Eigen::VectorXd& q, const Eigen::VectorXd& qd);

// The teach panel's matrices at pose q: E_pot, g(q) and B(q) with the unit beside each
// number — once after the matrix when every entry has the same (a robot with only
// revolute joints: B in kg·m²), else in every entry (kg·m² | kg·m | kg, N·m | N).
present::DisplayStep teachMatrices(const Scene& scene, const Eigen::VectorXd& q);

}  // namespace ll
