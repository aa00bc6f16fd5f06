#pragma once
// The Coriolis/centrifugal matrix C(q, q̇) from the Christoffel symbols of B:
//   c_ij = Σ_k ½ (∂b_ij/∂q_k + ∂b_ik/∂q_j − ∂b_jk/∂q_i) q̇_k
// (course notes; Siciliano (7.45)). With this choice Ḃ − 2C is skew-symmetric.
#include <Eigen/Core>

#include "core/dynamics/christoffel.hpp"
#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// Exact partial derivatives ∂B/∂q_k (no finite differences). With b_ij = S_iᵀ Ic_a S_j,
// a = max(i,j): ∂S_i/∂q_k = S_k × S_i for k < i (else 0) and ∂Ic_a/∂q_k =
// S_k×* Ic_b − Ic_b S_k× with b = max(a,k), the links that joint k moves.
// Requires forwardKinematics and computeMassMatrix. Fills data.dB_dq.
void computeMassMatrixDerivatives(const RobotModel& model, RobotData& data);

// Fills data.C (and data.dB_dq). Requires forwardKinematics and computeMassMatrix.
void computeCoriolisMatrix(const RobotModel& model, RobotData& data, const Eigen::VectorXd& qd);

// Christoffel symbol of the first kind Γ_ijk = ½(∂b_ij/∂q_k + ∂b_ik/∂q_j − ∂b_jk/∂q_i),
// from data.dB_dq.
inline double christoffel(const RobotData& data, int i, int j, int k) { return christoffelSymbol<double>(data.dB_dq, i, j, k); }

}  // namespace ll
