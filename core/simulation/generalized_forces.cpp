#include "core/simulation/generalized_forces.hpp"

#include "core/model/argument_checks.hpp"
#include "core/model/friction_law.hpp"
#include "core/simulation/controller.hpp"

namespace ll {

void computeExternalTorques(const Effects& effects, double t, Eigen::VectorXd& tau) {
    requireEffectsFit("computeExternalTorques", effects, tau.size());
    tau.setZero();
    for (const JointTorque& torque : effects.torques) tau[torque.joint] += torque(t);
}

void addFrictionForces(const Effects& effects, const Eigen::VectorXd& qd, Eigen::VectorXd& Q) {
    requireSize("addFrictionForces", "Q", Q.size(), qd.size(), "qd", "entries");
    requireEffectsFit("addFrictionForces", effects, qd.size());
    for (const ViscousFriction& f : effects.viscous) Q[f.joint] += viscousFrictionForce(f.coefficient, qd[f.joint]);
    for (const CoulombFriction& f : effects.coulomb) {
        const double v = qd[f.joint];
        // The stick model's force at q̇ = 0 is the holding force, which depends on the
        // other forces; on its own it is reported as 0.
        Q[f.joint] += f.model == CoulombModel::Tanh ? tanhCoulombForce(f.force, v, f.smoothing) : -f.force * ((v > 0) - (v < 0));
    }
}

void computeGeneralizedForces(const Effects& effects, double t, const Eigen::VectorXd& qd, Eigen::VectorXd& Q) {
    requireSize("computeGeneralizedForces", "Q", Q.size(), qd.size(), "qd", "entries");
    computeExternalTorques(effects, t, Q);
    addFrictionForces(effects, qd, Q);
}

void addControlTorques(const RobotModel& robot, const Effects& effects, double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                       Eigen::VectorXd& Q) {
    if (!effects.control) return;
    Controller controller(robot, effects);
    Q += controller.torque(t, q, qd);
}

}  // namespace ll
