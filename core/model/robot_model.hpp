#pragma once
// The immutable description of a serial manipulator: DH table, link inertials,
// base placement. Algorithms never write into it; they write into RobotData.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "core/model/dh_row.hpp"
#include "core/model/joint_motor.hpp"
#include "core/model/link_inertia.hpp"
#include "core/model/link_visual.hpp"

namespace ll {

struct Joint {
    DhRow dh;
    LinkInertia link;  // the link this joint moves (link i for joint i)
    JointMotor motor;  // its rotor inertia reflected to the joint (none by default)
    // Its travel [rad or m], when the scene gives one ("range": [lower, upper]): a
    // controller's reference must stay inside it. The simulation does not stop the joint.
    std::optional<std::pair<double, double>> range;
};

struct RobotModel {
    std::string name;
    DhConvention convention = DhConvention::Standard;
    // Pose of DH frame 0 in the world frame in which gravity is given. Identity
    // (the default) makes world = base frame, as in the course notes.
    Eigen::Isometry3d base = Eigen::Isometry3d::Identity();
    std::vector<Joint> joints;
    // How its own description draws it (a URDF's links and meshes); empty for a robot typed
    // as a DH table. Only the pictures read it.
    std::vector<LinkVisual> links;

    int dof() const { return static_cast<int>(joints.size()); }
};

}  // namespace ll
