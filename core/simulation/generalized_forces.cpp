#include "core/simulation/generalized_forces.hpp"

#include <cmath>

namespace ll {

void computeExternalTorques(const Effects& effects, double t, Eigen::VectorXd& tau) {
    tau.setZero();
    for (const JointTorque& torque : effects.torques) tau[torque.joint] += torque(t);
}

void addFrictionForces(const Effects& effects, const Eigen::VectorXd& qd, Eigen::VectorXd& Q) {
    for (const ViscousFriction& f : effects.viscous) Q[f.joint] -= f.coefficient * qd[f.joint];
    for (const CoulombFriction& f : effects.coulomb) Q[f.joint] -= f.force * std::tanh(qd[f.joint] / f.smoothing);
}

void computeGeneralizedForces(const Effects& effects, double t, const Eigen::VectorXd& qd, Eigen::VectorXd& Q) {
    computeExternalTorques(effects, t, Q);
    addFrictionForces(effects, qd, Q);
}

}  // namespace ll
