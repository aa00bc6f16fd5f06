#pragma once
// Inverse dynamics by the recursive Newton–Euler algorithm (RBDA §5.3, in world
// coordinates): τ = B(q) q̈ + C(q, q̇) q̇ + g(q). An algorithm independent of the
// Lagrangian route (no B, no Christoffel symbols), so the two check each other.
#include <Eigen/Core>

#include "core/model/effects.hpp"
#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// Requires forwardKinematics at q. Gravity and springs are included when declared,
// and each joint's armature as Jm G² q̈_j.
// Fills data.V, A, F and data.tau; returns data.tau.
const Eigen::VectorXd& rnea(const RobotModel& model, RobotData& data, const Effects& effects, const Eigen::VectorXd& q,
                            const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd);

// forwardKinematics + rnea.
const Eigen::VectorXd& inverseDynamics(const RobotModel& model, RobotData& data, const Effects& effects, const Eigen::VectorXd& q,
                                       const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd);

}  // namespace ll
