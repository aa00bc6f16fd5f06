#pragma once
// Kinetic and potential energy (course notes):
//   E_kin = ½ q̇ᵀ B(q) q̇,  E_pot = −Σ m_i g0ᵀ p_ci(q) + Σ ½ K_j (q_j − rest_j)².
#include <Eigen/Core>

#include "core/model/effects.hpp"
#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// Requires computeMassMatrix. B holds the motors' armature, so this includes the
// rotors' ½ Jm G² q̇_j².
double kineticEnergy(const RobotData& data, const Eigen::VectorXd& qd);

// Requires forwardKinematics. Only declared effects contribute.
double potentialEnergy(const RobotModel& model, const RobotData& data, const Effects& effects, const Eigen::VectorXd& q);

}  // namespace ll
