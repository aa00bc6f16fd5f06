#pragma once
// A robot's joint axes at home (q = 0) as lines in the world frame, and its last DH
// frame as the tool: the description step 0 starts from (core/kinematics/dh_from_axes.hpp).
// Joint i's line is z_{i−1} through o_{i−1} (standard) or z_i through o_i (modified),
// as forward kinematics places them.
#include "core/kinematics/dh_from_axes.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

AxesDescription axesAtHome(const RobotModel& robot);

}  // namespace ll
