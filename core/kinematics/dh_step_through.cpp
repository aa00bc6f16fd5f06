#include "core/kinematics/dh_step_through.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace ll {

Eigen::Isometry3d ElementaryMotion::transform(double fraction) const {
    const double x = amount * fraction;
    switch (kind) {
        case Kind::RotZ: return Eigen::Isometry3d(Eigen::AngleAxisd(x, Eigen::Vector3d::UnitZ()));
        case Kind::RotX: return Eigen::Isometry3d(Eigen::AngleAxisd(x, Eigen::Vector3d::UnitX()));
        case Kind::TransZ: return Eigen::Isometry3d(Eigen::Translation3d(0, 0, x));
        case Kind::TransX: return Eigen::Isometry3d(Eigen::Translation3d(x, 0, 0));
    }
    return Eigen::Isometry3d::Identity();
}

std::array<ElementaryMotion, 4> elementaryMotions(const RobotModel& robot, int joint, double q) {
    if (joint < 0 || joint >= robot.dof())
        throw std::out_of_range("elementaryMotions: joint " + std::to_string(joint + 1) + " of " + std::to_string(robot.dof()));
    using Kind = ElementaryMotion::Kind;
    const DhRow& row = robot.joints[static_cast<std::size_t>(joint)].dh;
    const bool revolute = row.type == JointType::Revolute;
    const ElementaryMotion theta{Kind::RotZ, DhParameter::Theta, row.theta + (revolute ? q : 0.0)};
    const ElementaryMotion d{Kind::TransZ, DhParameter::D, row.d + (revolute ? 0.0 : q)};
    const ElementaryMotion a{Kind::TransX, DhParameter::A, row.a};
    const ElementaryMotion alpha{Kind::RotX, DhParameter::Alpha, row.alpha};
    if (robot.convention == DhConvention::Standard) return {theta, d, a, alpha};
    return {alpha, a, theta, d};
}

Eigen::Isometry3d steppedFrame(const RobotModel& robot, const RobotData& data, const Eigen::VectorXd& q, int joint, int done,
                               double fraction) {
    const std::array<ElementaryMotion, 4> motions = elementaryMotions(robot, joint, q[joint]);
    done = std::clamp(done, 0, 4);
    Eigen::Isometry3d frame = data.T_0i[static_cast<std::size_t>(joint)];
    for (int k = 0; k < done; ++k) frame = frame * motions[static_cast<std::size_t>(k)].transform();
    if (done < 4 && fraction > 0) frame = frame * motions[static_cast<std::size_t>(done)].transform(std::min(fraction, 1.0));
    return frame;
}

}  // namespace ll
