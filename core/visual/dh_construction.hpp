#pragma once
// Step 0 shown rule by rule: the DH frames of a robot found from its joint axes
// (core/kinematics/dh_from_axes.hpp) one rule at a time, as marks to draw over the robot
// at home. The steps, numbered 4k + r:
//   0          the joint axes as lines (q_i on joint i's line)
//   4k + 1     z_k placed on its joint's axis
//   4k + 2     o_k placed, with the normal it came from (the case: skew, intersecting, …)
//   4k + 3     x_k along that normal
//   4k + 4     y_k = z_k × x_k: frame k complete (and, k ≥ 1, row k of the table known)
// for frames k = 0..n. The marks are renderer-neutral (ui/paint/osg_scene draws them); the
// sentences are made by the window from the step's rule and the frame's case.
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "core/kinematics/dh_from_axes.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

enum class DhRule { Axes, Z, Origin, X, Y };

struct DhConstructionStep {
    int frame = 0;  // k (0..n); the axes step has frame 0
    DhRule rule = DhRule::Axes;
};

// What a mark stands for (a renderer colours by it).
enum class ConstructionMarkKind {
    Axis,       // a joint's line
    AxisInUse,  // a line the current frame is placed from
    Normal,     // the common normal (or the line) an origin came from
    Origin,     // a frame's origin (one point)
    FrameX,     // a frame's axes, as arrows
    FrameY,
    FrameZ,
    OverlayFrame,  // a frame of the robot's own description (a URDF link's), thin triad
};

struct ConstructionMark {
    ConstructionMarkKind kind = ConstructionMarkKind::Axis;
    std::vector<Eigen::Vector3d> points;  // a polyline (an arrow ends in its head), world frame
    std::string label;                    // "q₁", "z₀", "o₂", a URDF link's name; may be empty
    Eigen::Vector3d labelAt = Eigen::Vector3d::Zero();
};

class DhConstruction {
public:
    // The construction of `robot`'s frames in its own convention from its axes at home;
    // `overlay`: frames to draw throughout (a URDF's link frames, world frame at home).
    explicit DhConstruction(const RobotModel& robot, std::vector<std::pair<std::string, Eigen::Isometry3d>> overlay = {});

    int joints() const { return static_cast<int>(axes_.axes.size()); }
    int steps() const { return 4 * (joints() + 1) + 1; }  // indices 0..steps()−1
    static DhConstructionStep step(int index);
    static int index(int frame, int rulesDone) { return 4 * frame + rulesDone; }

    const AxesDescription& axes() const { return axes_; }
    const DhFromAxes& found() const { return found_; }
    // Rows of the table known after step `index` (row k once x_k is placed).
    int rowsFound(int index) const;
    // The 1-based rows where the robot's own table differs from the one the rules found
    // (a free choice: both describe the same robot when base and tool differ to match).
    std::vector<int> rowsDiffering() const;
    // Joints (1-based) whose lines the frame of step `index` is placed from.
    std::vector<int> linesInUse(int index) const;
    // What is drawn after step `index`.
    std::vector<ConstructionMark> marks(int index) const;

private:
    RobotModel robot_;
    AxesDescription axes_;
    DhFromAxes found_;
    std::vector<std::pair<std::string, Eigen::Isometry3d>> overlay_;
    double scale_ = 1.0;  // [m] the robot's size: lines and arrows in proportion
};

}  // namespace ll
