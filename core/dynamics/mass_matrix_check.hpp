#pragma once
// B(q) must be positive definite wherever the robot may go. A joint that moves no mass
// or inertia not already moved by the joints before it makes B singular at (almost)
// every configuration; this finds it by factoring B at q0 and a few random
// configurations and names the joint.
#include <vector>

#include <Eigen/Core>

#include "core/model/diagnostics.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// Errors naming robot.joints[j] for each joint where B is singular at every trial,
// saying which kind (a joint that moves nothing, or B too ill-conditioned, with its
// condition number) and the likely cause: the first of `unitSlips` (unit-slip warnings
// of core/model/unit_slips), or advice to add the motor's armature.
std::vector<Diagnostic> checkMassMatrixRegular(const RobotModel& model, const Eigen::VectorXd& q0,
                                               const std::vector<Diagnostic>& unitSlips = {});

}  // namespace ll
