#pragma once
// The gradient of the potential energy, g(q) = ∂E_pot/∂q: gravity (if the scene
// declares it) plus joint springs. Conservative forces live here, never in Q.
#include <Eigen/Core>

#include "core/model/effects.hpp"
#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// g_j = −Σ_{i>=j} m_i g0ᵀ J_v,ci col j + K_j (q_j − rest_j): the gravity wrench on
// links j..n projected on joint j's motion, summed tip to base (O(n)).
// Requires forwardKinematics. Fills data.g.
void computePotentialGradient(const RobotModel& model, RobotData& data, const Effects& effects, const Eigen::VectorXd& q);

// The two parts of g(q) on their own, added into `out` (size n), so a right-hand side
// composed from the declared effects computes only the terms it has.
// Gravity g0 (world frame); requires forwardKinematics.
void addGravityTorques(const RobotModel& model, const RobotData& data, const Eigen::Vector3d& g0, Eigen::VectorXd& out);
// Joint springs K (q − rest).
void addSpringTorques(const std::vector<JointSpring>& springs, const Eigen::VectorXd& q, Eigen::VectorXd& out);

}  // namespace ll
