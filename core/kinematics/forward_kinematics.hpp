#pragma once
// Stage 1 of every evaluation: T_i^0(q) for every frame, the COM positions p_ci,
// the joint axes, and each link's inertia in the world frame.
#include <Eigen/Core>

#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// Fills data.T_0i, p_ci, I_li0, axis, axisPoint, S and I. q: (n).
void forwardKinematics(const RobotModel& model, RobotData& data, const Eigen::VectorXd& q);

// A_i(q_i) of joint i (0-based) alone.
Eigen::Isometry3d linkTransform(const RobotModel& model, int i, double q_i);

}  // namespace ll
