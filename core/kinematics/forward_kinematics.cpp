#include "core/kinematics/forward_kinematics.hpp"

#include <cmath>

#include "core/kinematics/dh_transform.hpp"
#include "core/model/argument_checks.hpp"

namespace ll {

Eigen::Isometry3d linkTransform(const RobotModel& model, int i, double q_i) {
    requireJointIndex("linkTransform", "i", i, model.dof());
    const DhRow& row = model.joints[i].dh;
    const bool revolute = row.type == JointType::Revolute;
    const double theta = row.theta + (revolute ? q_i : 0.0);
    const double d = row.d + (revolute ? 0.0 : q_i);
    Eigen::Isometry3d A;
    dhTransform(model.convention, row.a, d, std::cos(theta), std::sin(theta), std::cos(row.alpha), std::sin(row.alpha), A.matrix());
    return A;
}

void forwardKinematics(const RobotModel& model, RobotData& data, const Eigen::VectorXd& q) {
    requireDataFor("forwardKinematics", model, data);
    requireSize("forwardKinematics", "q", q.size(), data.n);
    const bool standard = model.convention == DhConvention::Standard;
    data.T_0i[0] = model.base;
    Eigen::Isometry3d A;
    for (int i = 0; i < data.n; ++i) {
        const Joint& joint = model.joints[i];
        const bool revolute = joint.dh.type == JointType::Revolute;
        const double theta = joint.dh.theta + (revolute ? q[i] : 0.0);
        const double d = joint.dh.d + (revolute ? 0.0 : q[i]);
        dhTransform(model.convention, joint.dh.a, d, std::cos(theta), std::sin(theta), data.cosAlpha[i], data.sinAlpha[i], A.matrix());
        Eigen::Isometry3d& T = data.T_0i[i + 1];
        T = data.T_0i[i] * A;

        // Joint i moves about/along z_{i-1} (standard) or z_i (modified); neither
        // moves under q_i itself, which the Christoffel derivatives rely on.
        const Eigen::Isometry3d& jointFrame = standard ? data.T_0i[i] : T;
        data.axis[i] = jointFrame.linear().col(2);
        data.axisPoint[i] = jointFrame.translation();
        if (joint.dh.type == JointType::Revolute) {
            data.S[i] << data.axis[i], data.axisPoint[i].cross(data.axis[i]);
        } else {
            data.S[i] << Eigen::Vector3d::Zero(), data.axis[i];
        }

        const Eigen::Matrix3d& R = T.linear();
        data.p_ci[i] = T * joint.link.com;
        data.I_li0[i] = R * joint.link.inertia * R.transpose();
        data.I[i] = spatialInertiaAtOrigin(joint.link.mass, data.p_ci[i], data.I_li0[i]);
    }
}

}  // namespace ll
