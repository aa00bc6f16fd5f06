#pragma once
// The generalized forces Q of Lagrange–d'Alembert: only the non-conservative effects
// the scene declares (viscous and Coulomb friction, external torques). Gravity and
// springs are conservative and live in E_pot; putting them here would model them twice.
#include <Eigen/Core>

#include "core/model/effects.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// Q(t, q̇) into Q (size n, overwritten). Joints with no declared effect get 0.
void computeGeneralizedForces(const Effects& effects, double t, const Eigen::VectorXd& qd, Eigen::VectorXd& Q);

// Only the external torques τ(t) part of Q.
void computeExternalTorques(const Effects& effects, double t, Eigen::VectorXd& tau);

// Only the friction part of Q (viscous + Coulomb); always Q_fᵀ q̇ <= 0. Stick-model
// Coulomb friction is −F_c sign(q̇_i) here (0 at q̇_i = 0, where it is the holding force).
void addFrictionForces(const Effects& effects, const Eigen::VectorXd& qd, Eigen::VectorXd& Q);

// The declared controller's τ(t, q, q̇) added into Q (nothing without one). Makes a
// Controller for the call: for evaluations and analyses, not the integrator's hot loop
// (RobotOde keeps its own).
void addControlTorques(const RobotModel& robot, const Effects& effects, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                       Eigen::VectorXd& Q);

}  // namespace ll
