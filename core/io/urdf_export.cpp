#include "core/io/urdf_export.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include <Eigen/Geometry>

#include "core/kinematics/dh_transform.hpp"
#include "core/model/diagnostics.hpp"

namespace ll {
namespace {

using Eigen::Isometry3d, Eigen::Matrix3d, Eigen::Vector3d;

std::string number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", v == 0.0 ? 0.0 : v);  // no "-0"
    return buffer;
}

std::string triple(const Vector3d& v) { return number(v.x()) + " " + number(v.y()) + " " + number(v.z()); }

// URDF's rpy: R = Rz(yaw) Ry(pitch) Rx(roll).
Vector3d rollPitchYaw(const Matrix3d& R) {
    const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
    if (std::abs(std::cos(pitch)) < 1e-12)  // gimbal lock: the yaw alone
        return {0.0, pitch, std::atan2(-R(0, 1), R(1, 1))};
    return {std::atan2(R(2, 1), R(2, 2)), pitch, std::atan2(R(1, 0), R(0, 0))};
}

std::string origin(const Isometry3d& T) {
    return "<origin xyz=\"" + triple(T.translation()) + "\" rpy=\"" + triple(rollPitchYaw(T.linear())) + "\"/>";
}

// The DH motions of one row with q = 0, split where the joint sits: standard DH turns about
// the row's start (Rot_z(θ) Trans_z(d) before, Trans_x(a) Rot_x(α) after), modified DH at
// its end (everything before).
Isometry3d beforeJoint(const DhRow& r, DhConvention convention) {
    Isometry3d T = Isometry3d::Identity();
    if (convention == DhConvention::Modified) {
        dhTransform(convention, r.a, r.d, std::cos(r.theta), std::sin(r.theta), std::cos(r.alpha), std::sin(r.alpha), T.matrix());
    } else {
        T = Eigen::AngleAxisd(r.theta, Vector3d::UnitZ()) * Eigen::Translation3d(0, 0, r.d);
    }
    return T;
}

Isometry3d afterJoint(const DhRow& r, DhConvention convention) {
    if (convention == DhConvention::Modified) return Isometry3d::Identity();
    return Isometry3d(Eigen::Translation3d(r.a, 0, 0) * Eigen::AngleAxisd(r.alpha, Vector3d::UnitX()));
}

std::string inertial(const LinkInertia& link, const Isometry3d& dhFrameInLink) {
    const Matrix3d& I = link.inertia;
    Isometry3d at = dhFrameInLink * Eigen::Translation3d(link.com);
    std::ostringstream s;
    s << "    <inertial>" << origin(at) << "<mass value=\"" << number(link.mass) << "\"/>\n"
      << "      <inertia ixx=\"" << number(I(0, 0)) << "\" ixy=\"" << number(I(0, 1)) << "\" ixz=\"" << number(I(0, 2)) << "\" iyy=\""
      << number(I(1, 1)) << "\" iyz=\"" << number(I(1, 2)) << "\" izz=\"" << number(I(2, 2)) << "\"/></inertial>\n";
    return s.str();
}

}  // namespace

UrdfExport exportUrdf(const Scene& scene) {
    if (scene.lagrangian) throw InputError("lagrangian", MessageId::UrdfExportNeedsRobot);
    UrdfExport out;
    const RobotModel& robot = scene.robot;
    const DhConvention convention = robot.convention;
    std::ostringstream x;
    x << "<?xml version=\"1.0\"?>\n<!-- " << scene.name << ": written by `lagrangelab export-urdf` from its "
      << (convention == DhConvention::Standard ? "standard" : "modified")
      << " DH table; a link per DH link, the inertials in the DH frames' axes. -->\n"
      << "<robot name=\"" << (robot.name.empty() ? scene.name : robot.name) << "\">\n";

    // URDF pulls along −z of the root: a "world" root turned so that the scene's gravity does.
    Isometry3d base = robot.base;
    std::string root = "base";
    if (scene.effects.gravity && scene.effects.gravity->norm() > 0) {
        const Vector3d g = *scene.effects.gravity;
        const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(g.normalized(), -Vector3d::UnitZ());
        if (std::abs(g.norm() - 9.81) > 1e-9) out.notes.push_back(message(MessageId::UrdfGravityMagnitude, g.norm()));
        if (!turn.toRotationMatrix().isApprox(Matrix3d::Identity(), 1e-15)) {
            x << "  <link name=\"world\"/>\n  <joint name=\"world_to_base\" type=\"fixed\"><parent link=\"world\"/><child link=\"base\"/>"
              << origin(Isometry3d(turn)) << "</joint>\n";
        }
    }
    x << "  <link name=\"" << root << "\"/>\n";
    for (int i = 0; i < robot.dof(); ++i) {
        const Joint& joint = robot.joints[static_cast<std::size_t>(i)];
        const std::string link = "link" + std::to_string(i + 1);
        const std::string parent = i == 0 ? root : "link" + std::to_string(i);
        // The parent link's frame is joint i−1's frame; DH frame i−1 sits after joint i−1's motion.
        const Isometry3d parentToDh = i == 0 ? base : afterJoint(robot.joints[static_cast<std::size_t>(i) - 1].dh, convention);
        const bool prismatic = joint.dh.type == JointType::Prismatic;
        if (joint.motor.armature() != 0.0) out.notes.push_back(message(MessageId::UrdfNoArmature, i + 1, joint.motor.armature()));
        x << "  <link name=\"" << link << "\">\n" << inertial(joint.link, afterJoint(joint.dh, convention)) << "  </link>\n";
        x << "  <joint name=\"joint" << i + 1 << "\" type=\"" << (prismatic ? "prismatic" : "continuous") << "\"><parent link=\"" << parent
          << "\"/><child link=\"" << link << "\"/>\n    " << origin(parentToDh * beforeJoint(joint.dh, convention))
          << "<axis xyz=\"0 0 1\"/>";
        if (prismatic)  // URDF requires limits of a prismatic joint; a scene has none
            x << "<limit lower=\"-1000\" upper=\"1000\" effort=\"1e9\" velocity=\"1e9\"/>";
        double damping = 0, friction = 0;
        for (const ViscousFriction& v : scene.effects.viscous)
            if (v.joint == i) damping += v.coefficient;
        for (const CoulombFriction& c : scene.effects.coulomb)
            if (c.joint == i) friction += c.force;
        if (damping > 0 || friction > 0) x << "<dynamics damping=\"" << number(damping) << "\" friction=\"" << number(friction) << "\"/>";
        x << "</joint>\n";
    }
    for (const JointSpring& spring : scene.effects.springs) out.notes.push_back(message(MessageId::UrdfNoSpring, spring.joint + 1));
    for (const JointTorque& torque : scene.effects.torques) out.notes.push_back(message(MessageId::UrdfNoTorque, torque.joint + 1));
    const std::string last = robot.dof() == 0 ? root : "link" + std::to_string(robot.dof());
    const Isometry3d lastToDh = robot.dof() == 0 ? base : afterJoint(robot.joints.back().dh, convention);
    x << "  <link name=\"tool\"/>\n  <joint name=\"tool_joint\" type=\"fixed\"><parent link=\"" << last << "\"/><child link=\"tool\"/>"
      << origin(lastToDh) << "</joint>\n</robot>\n";
    out.xml = x.str();
    return out;
}

}  // namespace ll
