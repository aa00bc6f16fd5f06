#pragma once
// Step 0 of the notes, done by their rules: the DH frames and table of a serial robot
// found from its joint axes. The robot is given as it stands at home (q = 0): each joint's
// axis as a line in the world frame (a point and a direction; a prismatic joint's line is
// only a direction) and the tool frame. The frames follow the textbook:
//   - z along the joint axes (standard: z_{i-1} on joint i's axis; modified: z_i on it),
//     in the axis' own direction, so q turns or slides the way the description says;
//   - x along the common normal of two neighbouring axes, from the earlier to the later,
//     the origin at its foot;
//   - y completing a right-handed frame;
// and say which case each pair of axes was (dh_from_axes.cpp has the choices):
//   skew          the common normal is unique;
//   intersecting  x = z_prev × z_next (the normal's sign is a choice: +), origin where they meet;
//   parallel      the normal slides along the axes: the one through the previous origin, so d = 0;
//   coincident    one line: x kept from the previous frame, a = 0, α = 0 or π.
// Antiparallel axes (α = π) are kept so, never flipped: flipping z would turn q around.
// A prismatic joint's line is only a direction; where it lies is kept as described (a
// URDF's joint origin), which decides its frame's origin as the textbook's figures do
// (the SCARA's slide at the end of link 2).
// The θ and d the frames have at home are the rows' offsets, so q = 0 is the home pose.
// What DH cannot say stays outside the table: the base transform (world → frame 0) and
// the tool transform (frame n → tool). Forward kinematics of the result equals the
// axes' own (dh_from_axes tests: ≤ 1e-12 at random q in both conventions).
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/model/dh_row.hpp"

namespace ll {

struct JointAxis {
    JointType type = JointType::Revolute;
    Eigen::Vector3d point = Eigen::Vector3d::Zero();       // a point of the axis at home, world frame
    Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // positive q turns about / slides along it (any length but 0)
};

struct AxesDescription {
    std::vector<JointAxis> axes;                             // joint 1 first
    Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();  // the tool frame at home, world frame
};

// How a frame's z line met the next joint's line (the rule that placed it).
enum class AxisPair { Skew, Intersecting, Parallel, Coincident, Last };

// One DH frame as the rules placed it at home, in the world frame, and why.
struct DhFrameRule {
    AxisPair pair = AxisPair::Skew;  // the case of the two lines its origin and x came from
    bool antiparallel = false;       // the two lines point opposite ways (α = π)
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    Eigen::Vector3d x = Eigen::Vector3d::UnitX(), z = Eigen::Vector3d::UnitZ();

    Eigen::Isometry3d transform() const;  // the frame in the world: axes x, z × x, z at origin
};

// The point of the line through `point` along `direction` (any length but 0) nearest `p`:
// the foot of the perpendicular from p.
Eigen::Vector3d footOn(const Eigen::Vector3d& point, const Eigen::Vector3d& direction, const Eigen::Vector3d& p);

struct DhFromAxes {
    DhConvention convention = DhConvention::Standard;
    std::vector<DhRow> rows;          // one per joint, as robot_model.hpp reads them (modified: a_{i-1}, α_{i-1}, d_i, θ_i)
    std::vector<DhFrameRule> frames;  // frames 0..n
    Eigen::Isometry3d base = Eigen::Isometry3d::Identity();  // frame 0 in the world
    Eigen::Isometry3d tool = Eigen::Isometry3d::Identity();  // the tool in frame n
};

// The DH frames and table of `robot` in `convention`. Throws std::invalid_argument when an
// axis has no direction (zero or not finite) or there are no joints.
DhFromAxes dhFromAxes(const AxesDescription& robot, DhConvention convention);

// The tool pose at q by the axes themselves: each joint turns (slides) everything after
// it about (along) its line, applied from the last joint to the first (the product of
// exponentials). The independent route dhFromAxes is checked against.
Eigen::Isometry3d toolPoseFromAxes(const AxesDescription& robot, const Eigen::VectorXd& q);

}  // namespace ll
