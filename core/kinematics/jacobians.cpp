#include "core/kinematics/jacobians.hpp"

#include "core/model/argument_checks.hpp"

namespace ll {

void pointJacobian(const RobotData& data, int link, const Eigen::Vector3d& p, Jacobian& J) {
    requireJointIndex("pointJacobian", "link", link, data.n);
    J.setZero(6, data.n);
    for (int j = 0; j <= link; ++j) {
        const bool revolute = !data.S[j].head<3>().isZero();
        if (revolute) {
            J.block<3, 1>(0, j) = data.axis[j].cross(p - data.axisPoint[j]);
            J.block<3, 1>(3, j) = data.axis[j];
        } else {
            J.block<3, 1>(0, j) = data.axis[j];
        }
    }
}

}  // namespace ll
