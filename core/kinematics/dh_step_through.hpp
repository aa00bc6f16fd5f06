#pragma once
// The DH step-through (step 0 of the notes, made visible): frame i−1 becomes frame i by
// the four elementary motions of row i, one at a time:
//   standard: rot_z(θ_i), trans_z(d_i), trans_x(a_i), rot_x(α_i)
//   modified: rot_x(α_{i−1}), trans_x(a_{i−1}), rot_z(θ_i), trans_z(d_i)
// θ_i and d_i include the joint variable (q_i adds to θ_i of a revolute joint, to d_i of
// a prismatic one). The frame after all four is frame i of forward kinematics.
#include <array>

#include <Eigen/Geometry>

#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// Which DH parameter a motion carries out: a column of the DH table.
enum class DhParameter { A, Alpha, D, Theta };

struct ElementaryMotion {
    enum class Kind { RotZ, TransZ, TransX, RotX };
    Kind kind = Kind::RotZ;
    DhParameter parameter = DhParameter::Theta;
    double amount = 0.0;  // [rad] for a rotation, [m] for a translation

    // The motion carried out to `fraction` (0..1) of its amount, in the moving frame.
    Eigen::Isometry3d transform(double fraction = 1.0) const;
    bool rotates() const { return kind == Kind::RotZ || kind == Kind::RotX; }
};

// The four motions of joint `joint` (0-based: row joint+1 of the table) at joint value q.
std::array<ElementaryMotion, 4> elementaryMotions(const RobotModel& robot, int joint, double q);

// Frame `joint` (the table's frame i−1, i = joint + 1) carried by the first `done`
// motions (0..4) and `fraction` of the next; `data` holds forward kinematics at the pose
// (its T_0i). done = 4 gives T_0i[joint + 1], frame i.
Eigen::Isometry3d steppedFrame(const RobotModel& robot, const RobotData& data, const Eigen::VectorXd& q, int joint, int done,
                               double fraction = 0.0);

}  // namespace ll
