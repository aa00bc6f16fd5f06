#include "core/dynamics/potential_gradient.hpp"

#include "core/model/argument_checks.hpp"

namespace ll {

void addGravityTorques(const RobotModel& model, const RobotData& data, const Eigen::Vector3d& g0, Eigen::VectorXd& out) {
    requireDataFor("addGravityTorques", model, data);
    requireSize("addGravityTorques", "out", out.size(), data.n);
    double mass = 0.0;                                      // of links j..n
    Eigen::Vector3d firstMoment = Eigen::Vector3d::Zero();  // Σ m_i p_ci over links j..n
    for (int j = data.n - 1; j >= 0; --j) {
        mass += model.joints[j].link.mass;
        firstMoment += model.joints[j].link.mass * data.p_ci[j];
        Vector6d wrench;  // gravity on links j..n, about the world origin
        wrench << firstMoment.cross(g0), mass * g0;
        out[j] -= data.S[j].dot(wrench);
    }
}

void addSpringTorques(const std::vector<JointSpring>& springs, const Eigen::VectorXd& q, Eigen::VectorXd& out) {
    requireSize("addSpringTorques", "out", out.size(), q.size(), "q", "entries");
    for (const JointSpring& spring : springs) {
        requireJointIndex("addSpringTorques", "a spring", spring.joint, q.size());
        out[spring.joint] += spring.stiffness * (q[spring.joint] - spring.rest);
    }
}

void computePotentialGradient(const RobotModel& model, RobotData& data, const Effects& effects, const Eigen::VectorXd& q) {
    requireSize("computePotentialGradient", "q", q.size(), data.n);
    data.g.setZero();
    if (effects.gravity) addGravityTorques(model, data, *effects.gravity, data.g);
    addSpringTorques(effects.springs, q, data.g);
}

}  // namespace ll
