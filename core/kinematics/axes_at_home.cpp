#include "core/kinematics/axes_at_home.hpp"

#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/robot_data.hpp"

namespace ll {

AxesDescription axesAtHome(const RobotModel& robot) {
    const int n = robot.dof();
    RobotData data(robot);
    forwardKinematics(robot, data, Eigen::VectorXd::Zero(n));
    AxesDescription axes;
    for (int i = 0; i < n; ++i) {
        const auto k = static_cast<std::size_t>(i);
        axes.axes.push_back({robot.joints[k].dh.type, data.axisPoint[k], data.axis[k]});
    }
    axes.tool = data.T_0i[static_cast<std::size_t>(n)];
    return axes;
}

}  // namespace ll
