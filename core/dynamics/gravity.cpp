#include "core/dynamics/gravity.hpp"

namespace ll {

void computeGravity(const RobotModel& model, RobotData& data, const Effects& effects,
                    const Eigen::VectorXd& q) {
    data.g.setZero();
    if (effects.gravity) {
        const Eigen::Vector3d& g0 = *effects.gravity;
        double mass = 0.0;                                  // of links j..n
        Eigen::Vector3d firstMoment = Eigen::Vector3d::Zero();  // Σ m_i p_ci over links j..n
        for (int j = data.n - 1; j >= 0; --j) {
            mass += model.joints[j].link.mass;
            firstMoment += model.joints[j].link.mass * data.p_ci[j];
            Vector6d wrench;  // gravity on links j..n, about the world origin
            wrench << firstMoment.cross(g0), mass * g0;
            data.g[j] = -data.S[j].dot(wrench);
        }
    }
    for (const JointSpring& spring : effects.springs)
        data.g[spring.joint] += spring.stiffness * (q[spring.joint] - spring.rest);
}

}  // namespace ll
