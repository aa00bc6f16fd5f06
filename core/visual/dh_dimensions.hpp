#pragma once
// The DH table drawn on the robot (the step-through's static view): every parameter of
// every row as a dimension, at the pose shown — a length (d_i, a_i) as an arrow from
// where its motion starts to where it ends, an angle (θ_i, α_i) as an arc about the
// motion's axis from the axis it turns (x for θ, z for α) to where that axis ends up.
// Built by carrying frame i−1 through the row's four elementary motions
// (core/kinematics/dh_step_through.hpp), so both conventions come out the same way;
// motions of zero amount are left out.
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/kinematics/dh_step_through.hpp"
#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

struct DhDimension {
    int joint = 0;  // 0-based: row joint+1
    DhParameter parameter = DhParameter::D;
    bool angle = false;
    double value = 0.0;                   // [m] or [rad], the joint variable included
    std::vector<Eigen::Vector3d> points;  // the arrow (2 points) or the arc (a polyline), world frame
    Eigen::Vector3d labelAt = Eigen::Vector3d::Zero();
    std::string label;  // "d1 = 0.672 m", "θ2 = 45.0°" (modified: a0, α0 for row 1)
};

// Every row's dimensions at the pose in `data` (forward kinematics at q); arcs of radius
// `arcRadius` [m].
std::vector<DhDimension> dhDimensions(const RobotModel& robot, const RobotData& data, const Eigen::VectorXd& q, double arcRadius);

}  // namespace ll
