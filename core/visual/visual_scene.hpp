#pragma once
// The 3D picture of a scene, renderer-neutral (MuJoCo's abstract mjvScene idea): what
// to draw and where, as plain data. Built once from a Scene; `pose(q, t)` then moves
// every part with no allocation, and a renderer (ui/paint/osg_scene.hpp, for the window and
// the headless export alike) only copies poses into its transforms.
//
// A robot is drawn as the textbook's DH stick figure, solid (standard convention;
// modified: along x_{i-1} by a_{i-1}, then along z_i by d_i):
//   - link i: a rod from the origin o_{i-1} of frame i-1 along z_{i-1} by d_i, then a
//     rod along x_i by a_i to o_i (segments of zero length are left out);
//   - a revolute joint: a short cylinder on its axis; a prismatic joint: a square
//     sleeve fixed on its axis and a square bar sliding in it whose visible length is
//     d_i + q_i;
//   - the centre of mass of each link with mass: a sphere whose volume is proportional
//     to the mass; the end effector: a small sphere at o_n; a pedestal disc behind the
//     first joint; a triad per DH frame 0..n.
// A Lagrangian scene draws its own `bodies` (box, sphere, cylinder, rod), posed by
// their expressions of q and t compiled beforehand (core/pipeline/scene_visual.hpp: no
// GiNaC here), and the world triad.
// The ground grid lies at a robot's base (under its pedestal; the motion may reach
// below), below everything for a Lagrangian scene; a drop line hangs from each
// centre of mass to it.
// Sizes scale with the robot's reach, so a 5 cm pendulum and a 2 m arm both look right.
// Up is −gravity; with no gravity z, except a Lagrangian scene lying in the x–y plane
// (a pendulum typed by hand), which gets y up.
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/kinematics/body_poses.hpp"
#include "core/visual/dh_dimensions.hpp"
#include "core/model/scene.hpp"
#include "core/simulation/trajectory.hpp"
#include "core/visual/link_colors.hpp"

namespace ll {

// Solids in their own frame, centred on the frame's origin:
//   Box       edges `box` (x, y, z)
//   Sphere    `radius`
//   Cylinder  `radius`, `length` along z (a revolute joint, a Lagrangian disc)
//   Rod       round, `radius`, `length` along z: the length changes with the pose
//   Bar       square cross-section of side 2·`radius`, `length` along z: changes with q
//   Sleeve    square tube of outer side 2·`radius`, wall `radius`/4, `length` along z
//   Mesh      the file `mesh` (a renderer reads it; a relative path is the scene file's),
//             scaled by `box` along its own axes
enum class PartShape { Box, Sphere, Cylinder, Rod, Bar, Sleeve, Mesh };

// What a part stands for (a renderer may style or hide by role). Look: a shape of the
// robot's own description (core/model/link_visual.hpp), drawn instead of the DH links,
// joints and pedestal when a renderer shows the robot's look.
enum class PartRole { Link, Joint, CentreOfMass, EndEffector, Pedestal, Body, Look };

// True for the shapes whose `length` is set by every pose (a renderer draws them at
// unit length and scales z).
bool stretches(PartShape shape);

struct VisualPart {
    std::string name;  // "link 2", "joint 3", "COM 1", or a body's name
    PartShape shape = PartShape::Sphere;
    PartRole role = PartRole::Body;
    double radius = 0.0;                            // [m]
    double length = 0.0;                            // [m] along the part's z
    Eigen::Vector3d box = Eigen::Vector3d::Zero();  // [m] box edges; a mesh's scale
    std::string mesh;                               // a Mesh's file, as the scene gives it
    Rgba color;
    int coordinate = -1;  // the joint or coordinate (0-based) whose motion moves it
                          // last along the chain; -1: fixed in the world
    // --- pose(q, t) ---
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // part frame in the world
};

// A coordinate frame drawn as an x/y/z triad (red/green/blue).
struct VisualFrame {
    std::string label;                                       // "0".."n" for the DH frames ("4,5,6" on the first of frames
                                                             // whose origins always coincide, empty on the others), "world"
    double axisLength = 0.0;                                 // [m]
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // filled by pose(q, t)
    // Its label kept off the bodies in a picture (frame_labels.hpp): the world frame of a
    // typed system, which no body carries, would otherwise read as a body's name.
    bool labelOffBodies = false;
};

// The ground: a grid on the plane through `centre` perpendicular to `up`.
struct VisualGround {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double halfSize = 1.0;  // [m] the grid spans ±halfSize along its two axes
    double spacing = 0.1;   // [m] between grid lines
};

// An axis-aligned box in the world frame holding every part and triad.
struct VisualBounds {
    Eigen::Vector3d min = Eigen::Vector3d::Constant(1e300);
    Eigen::Vector3d max = Eigen::Vector3d::Constant(-1e300);

    bool empty() const { return min.x() > max.x(); }
    void add(const Eigen::Vector3d& point, double radius);
    Eigen::Vector3d centre() const { return (min + max) / 2; }
    double radius() const { return empty() ? 0.0 : (max - min).norm() / 2; }  // bounding sphere
};

class VisualScene {
public:
    // Builds the parts of `scene` and poses them at its initial state. A Lagrangian
    // scene's bodies move by `bodies`, their pose expressions compiled (throws
    // std::invalid_argument when a Lagrangian scene comes without them, or with another
    // count); a robot's by its DH table.
    explicit VisualScene(const Scene& scene, std::optional<BodyPoses> bodies = std::nullopt);
    ~VisualScene();
    VisualScene(VisualScene&&) noexcept;
    VisualScene& operator=(VisualScene&&) noexcept;

    std::string name;                               // the scene's name
    Eigen::Vector3d up = Eigen::Vector3d::UnitZ();  // unit, world frame
    double scale = 1.0;                             // characteristic length [m]: the reach of a robot
    std::vector<VisualPart> parts;
    std::vector<VisualFrame> frames;  // DH frames 0..n, or the world frame
    int endEffector = -1;             // the part whose path the trail draws; -1: none
    VisualGround ground;
    // Depth cues: a drop line from each centre of mass straight down (along −up) to the
    // ground, its foot where the mass stands over the ground. One pair (centre, foot) per
    // COM part, in `parts` order; updated by pose().
    std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> dropLines;
    VisualBounds bounds;  // of the initial pose, then of the motion (fitToMotion)
    // Spheres (centre x, y, z, radius [m]) that hold every part and triad at the initial
    // pose, then at every pose fitToMotion sampled: what a camera must keep in view.
    // Tighter than the corners of `bounds`, so a fitted camera frames the robot, not its box.
    std::vector<Eigen::Vector4d> keepInView;

    int dof() const;
    // Moves every part and frame to the configuration q (one value per coordinate) at
    // time t. No allocation.
    void pose(const Eigen::VectorXd& q, double t);
    // Extends `bounds` over the poses of up to `maxSamples` samples of the trajectory
    // (evenly spread, first and last included) and lays the ground below everything,
    // so a camera fitted to `bounds` keeps the scene in view the whole time. Leaves
    // the parts posed at the trajectory's last sample used.
    void fitToMotion(const Trajectory& trajectory, int maxSamples = 400);
    // The bounds of the current pose alone.
    VisualBounds currentBounds() const;
    // Spheres (centre x, y, z, radius [m]) that hold every part and triad at the current
    // pose: what a camera must show of the robot as it stands now. Into `spheres`
    // (cleared first; no allocation once it has grown to size).
    void currentExtent(std::vector<Eigen::Vector4d>& spheres) const;
    // The DH step-through's moving frame at the current pose (core/kinematics/
    // dh_step_through.hpp): frame `joint` (0-based; the table's i−1) carried by `done`
    // of row joint+1's four motions and `fraction` of the next. False for a Lagrangian
    // scene or a joint out of range.
    bool steppedFrame(int joint, int done, double fraction, Eigen::Isometry3d& frame) const;
    // Every DH parameter as a dimension on the robot at the current pose
    // (core/visual/dh_dimensions.hpp), arcs `arcShare` of the reach; empty for a
    // Lagrangian scene.
    std::vector<DhDimension> dhDimensions(double arcShare = 0.06) const;
    // Position of the end effector part at the current pose (zero if there is none).
    Eigen::Vector3d endEffectorPosition() const;
    // The end effector at every sample of `trajectory` (a trail's points); empty when there
    // is none. Leaves the scene posed at the last sample.
    std::vector<Eigen::Vector3d> endEffectorPath(const Trajectory& trajectory);

private:
    struct Rig;
    std::unique_ptr<Rig> rig_;

    void placeGround();
    void placeDropLines();
    // A robot's ground stays at its base (under its pedestal) whatever the motion
    // reaches; NaN: below everything (a Lagrangian scene's own bodies).
    double baseHeight_ = std::numeric_limits<double>::quiet_NaN();
    void labelCoincidentFrames(const Eigen::VectorXd& q0);
    // Calls add(centre, radius) for spheres that hold each part and triad at the current pose.
    template <class Add>
    void forEachExtent(Add add) const;
};

}  // namespace ll
