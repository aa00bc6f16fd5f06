#pragma once
// The mass matrix B(q) of E_kin = ½ q̇ᵀ B(q) q̇.
#include <Eigen/Core>

#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// Composite-rigid-body algorithm (RBDA §6.2) in world coordinates:
// b_ij = S_iᵀ Ic_max(i,j) S_j with Ic_k the inertia of links k..n, plus each joint's
// motor armature Jm G² on b_jj (core/model/joint_motor.hpp).
// Requires forwardKinematics. Fills data.I_composite and data.B (both triangles).
void computeMassMatrix(const RobotModel& model, RobotData& data);

// The textbook sum B = Σ_i m_i J_v,ciᵀ J_v,ci + J_ω,iᵀ R_i I_ci R_iᵀ J_ω,i (Siciliano
// (7.16)) plus the armatures on the diagonal, written independently of the CRBA; for
// teaching steps and cross-checks. Requires forwardKinematics. Allocates.
Eigen::MatrixXd massMatrixFromJacobians(const RobotModel& model, const RobotData& data);

}  // namespace ll
