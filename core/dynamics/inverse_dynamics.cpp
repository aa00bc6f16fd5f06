#include "core/dynamics/inverse_dynamics.hpp"

#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/argument_checks.hpp"

namespace ll {

const Eigen::VectorXd& rnea(const RobotModel& model, RobotData& data, const Effects& effects, const Eigen::VectorXd& q,
                            const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd) {
    requireDataFor("rnea", model, data);
    requireSize("rnea", "q", q.size(), data.n);
    requireSize("rnea", "qd", qd.size(), data.n);
    requireSize("rnea", "qdd", qdd.size(), data.n);
    requireEffectsFit("rnea", effects, data.n);
    const int n = data.n;
    // Gravity as an upward acceleration of the base (RBDA §5.3).
    Vector6d V = Vector6d::Zero();
    Vector6d A = Vector6d::Zero();
    if (effects.gravity) A.tail<3>() = -*effects.gravity;

    // Outward: velocities and accelerations; S_i moves with link i−1, so Ṡ_i = V_i × S_i.
    for (int i = 0; i < n; ++i) {
        V += data.S[i] * qd[i];
        A += crossMotion(V, data.S[i]) * qd[i] + data.S[i] * qdd[i];
        data.V[i] = V;
        data.A[i] = A;
        data.F[i] = data.I[i] * A + crossForce(V, data.I[i] * V);
    }
    // Inward: each joint carries the force of all links beyond it.
    // The motor's rotor adds its reflected inertia times the joint's own acceleration.
    for (int i = n - 1; i >= 0; --i) {
        data.tau[i] = data.S[i].dot(data.F[i]) + model.joints[i].motor.armature() * qdd[i];
        if (i > 0) data.F[i - 1] += data.F[i];
    }
    for (const JointSpring& spring : effects.springs) data.tau[spring.joint] += spring.stiffness * (q[spring.joint] - spring.rest);
    return data.tau;
}

const Eigen::VectorXd& inverseDynamics(const RobotModel& model, RobotData& data, const Effects& effects, const Eigen::VectorXd& q,
                                       const Eigen::VectorXd& qd, const Eigen::VectorXd& qdd) {
    forwardKinematics(model, data, q);
    return rnea(model, data, effects, q, qd, qdd);
}

}  // namespace ll
