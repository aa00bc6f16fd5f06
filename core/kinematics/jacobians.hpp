#pragma once
// Geometric Jacobians, the textbook way (Siciliano et al., Robotics, §3.1.3):
// column j of the Jacobian of a point p on link i, for j <= i,
//   revolute j:  J_v = z_j × (p − o_j),  J_ω = z_j
//   prismatic j: J_v = z_j,              J_ω = 0
// with z_j, o_j the axis and a point of joint j; columns j > i are zero.
#include <Eigen/Core>

#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

using Jacobian = Eigen::Matrix<double, 6, Eigen::Dynamic>;  // rows: [J_v (3); J_ω (3)]

// Jacobian of the point p (world) carried by link i (0-based). Requires
// forwardKinematics. J is resized to 6 x n.
void pointJacobian(const RobotData& data, int link, const Eigen::Vector3d& p, Jacobian& J);

// J_v,ci and J_ω,i of link i: the Jacobian of its centre of mass.
inline void comJacobian(const RobotData& data, int link, Jacobian& J) { pointJacobian(data, link, data.p_ci[link], J); }

}  // namespace ll
