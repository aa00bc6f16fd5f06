#include "core/dynamics/energy.hpp"

#include "core/model/argument_checks.hpp"

namespace ll {

double kineticEnergy(const RobotData& data, const Eigen::VectorXd& qd) {
    requireSize("kineticEnergy", "qd", qd.size(), data.n);
    return 0.5 * qd.dot(data.B.selfadjointView<Eigen::Upper>() * qd);
}

double potentialEnergy(const RobotModel& model, const RobotData& data, const Effects& effects, const Eigen::VectorXd& q) {
    requireDataFor("potentialEnergy", model, data);
    requireSize("potentialEnergy", "q", q.size(), data.n);
    requireEffectsFit("potentialEnergy", effects, data.n);
    double E = 0.0;
    if (effects.gravity)
        for (int i = 0; i < data.n; ++i) E -= model.joints[i].link.mass * effects.gravity->dot(data.p_ci[i]);
    for (const JointSpring& spring : effects.springs) {
        const double stretch = q[spring.joint] - spring.rest;
        E += 0.5 * spring.stiffness * stretch * stretch;
    }
    return E;
}

}  // namespace ll
