#include "core/io/urdf_import.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <numeric>
#include <sstream>
#include <tuple>

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include "core/model/diagnostics.hpp"

namespace ll {
namespace {

using Eigen::Isometry3d, Eigen::Matrix3d, Eigen::Vector3d;

// liburdfdom says why it refused a file through console_bridge, a process-wide logger:
// its first error is kept for our message instead of printed.
class FirstError : public console_bridge::OutputHandler {
public:
    void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
        if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR && first.empty()) first = text;
    }
    std::string first;
};

urdf::ModelInterfaceSharedPtr parse(const std::string& xml, const std::string& path) {
    static std::mutex logger;  // the handler is global
    const std::lock_guard lock(logger);
    FirstError errors;
    console_bridge::useOutputHandler(&errors);
    urdf::ModelInterfaceSharedPtr model;
    try {
        model = urdf::parseURDF(xml);
    } catch (const std::exception& e) {
        if (errors.first.empty()) errors.first = e.what();
    }
    console_bridge::restorePreviousOutputHandler();
    if (model) return model;
    const bool xacro = xml.find("xmlns:xacro") != std::string::npos || xml.find("<xacro:") != std::string::npos;
    throw InputError(path, message(MessageId::UrdfUnreadable, errors.first.empty() ? std::string("no <robot> element") : errors.first),
                     xacro ? message(MessageId::UrdfXacroNotExpanded, path) : Message{});
}

Isometry3d toIsometry(const urdf::Pose& pose) {
    double x, y, z, w;
    pose.rotation.getQuaternion(x, y, z, w);
    Isometry3d T = Isometry3d::Identity();
    T.linear() = Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
    T.translation() = Vector3d(pose.position.x, pose.position.y, pose.position.z);
    return T;
}

bool moves(const urdf::Joint& joint) { return joint.type != urdf::Joint::FIXED; }

// What rounding left of a zero (−5.6·10⁻¹⁷ m of a COM on the axis) written as 0, so the
// scene reads as the textbook's and its checks see no absurdly small length. `scale`: the
// size of the quantity's own values (1 m, 1 rad, the largest inertia).
double cleaned(double v, double scale) { return std::abs(v) < 1e-12 * scale ? 0.0 : v; }

// An angle that is a multiple of π/12 as the scene files and the textbook write it
// ("-pi/2", "2*pi/3"), so the table and the derivation read α = −½π, not −1.5707963267949;
// empty for 0 and any other angle.
std::string angleText(double angle) {
    const double k = std::round(angle / (M_PI / 12));
    if (k == 0 || std::abs(angle - k * M_PI / 12) > 1e-12) return {};
    long numerator = static_cast<long>(k), denominator = 12;
    const long divisor = std::gcd(numerator, denominator);
    numerator /= divisor;
    denominator /= divisor;
    std::string text = numerator == 1 ? "pi" : numerator == -1 ? "-pi" : std::to_string(numerator) + "*pi";
    return denominator == 1 ? text : text + "/" + std::to_string(denominator);
}

// Whether anything below `link` moves (a branch the chain has to choose).
bool movesBelow(const urdf::Link& link) {
    for (const auto& joint : link.child_joints)
        if (moves(*joint)) return true;
    for (const auto& child : link.child_links)
        if (movesBelow(*child)) return true;
    return false;
}

std::string linkNames(const urdf::ModelInterface& model) {
    std::vector<urdf::LinkSharedPtr> links;
    model.getLinks(links);
    std::string names;
    for (const auto& link : links) names += (names.empty() ? "" : ", ") + link->name;
    return names;
}

urdf::LinkConstSharedPtr namedLink(const urdf::ModelInterface& model, const std::string& name, const std::string& option) {
    const urdf::LinkConstSharedPtr link = model.getLink(name);
    if (!link) throw InputError(option, message(MessageId::UrdfNoSuchLink, name, linkNames(model)));
    return link;
}

// The chain's last link when none is named: down the only branch that moves, then on
// through fixed links while there is one way on.
urdf::LinkConstSharedPtr defaultTip(urdf::LinkConstSharedPtr link, const std::string& path) {
    for (;;) {
        std::vector<urdf::LinkSharedPtr> moving;
        for (const auto& child : link->child_links)
            if (moves(*child->parent_joint) || movesBelow(*child)) moving.push_back(child);
        if (moving.size() > 1) {
            std::string names;
            for (const auto& child : moving) names += (names.empty() ? "" : ", ") + child->name;
            throw InputError(path, message(MessageId::UrdfBranches, link->name, names));
        }
        if (moving.size() == 1) link = moving.front();
        else if (link->child_links.size() == 1) link = link->child_links.front();
        else return link;
    }
}

// Mass, centre of mass and inertia about it, all in the base link's frame.
struct Body {
    double mass = 0;
    Vector3d com = Vector3d::Zero();
    Matrix3d inertia = Matrix3d::Zero();
};

Body bodyOf(const urdf::Link& link, const Isometry3d& pose) {
    Body b;
    if (!link.inertial) return b;
    const urdf::Inertial& in = *link.inertial;
    const Isometry3d frame = pose * toIsometry(in.origin);
    Matrix3d I;
    I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
    b.mass = in.mass;
    b.com = frame.translation();
    b.inertia = frame.linear() * I * frame.linear().transpose();
    return b;
}

// Two bodies as one: masses added, the centre of mass combined, each inertia moved to it
// (parallel-axis theorem, I + m (|r|² E − r rᵀ)).
Body lumped(const Body& a, const Body& b) {
    Body s;
    s.mass = a.mass + b.mass;
    if (s.mass > 0) s.com = (a.mass * a.com + b.mass * b.com) / s.mass;
    for (const Body* p : {&a, &b}) {
        const Vector3d r = p->com - s.com;
        s.inertia += p->inertia + p->mass * (r.squaredNorm() * Matrix3d::Identity() - r * r.transpose());
    }
    return s;
}

// A <mesh filename> as a path to read: package://NAME/rest from the folder NAME above the
// file (or beside one above it), file:// and relative paths from the file's folder.
// A package not found keeps its URL (the window then shows the DH drawing) and is noted.
std::string meshPath(const std::string& url, const std::string& urdfPath, std::set<std::string>& missing) {
    namespace fs = std::filesystem;
    const fs::path folder = fs::absolute(fs::path(urdfPath)).parent_path();
    const std::string package = "package://";
    if (url.rfind(package, 0) == 0) {
        const std::string rest = url.substr(package.size());
        const std::string name = rest.substr(0, rest.find('/'));
        const std::string inside = rest.find('/') == std::string::npos ? std::string() : rest.substr(rest.find('/') + 1);
        std::error_code error;
        for (fs::path at = folder; !at.empty(); at = at.parent_path()) {
            if (at.filename() == name) return (at / inside).lexically_normal().string();
            if (fs::is_directory(at / name, error)) return (at / name / inside).lexically_normal().string();
            if (at == at.parent_path()) break;
        }
        missing.insert(name);
        return url;
    }
    const std::string file = url.rfind("file://", 0) == 0 ? url.substr(7) : url;
    const fs::path given(file);
    return (given.is_absolute() ? given : folder / given).lexically_normal().string();
}

LinkShape shapeOf(const urdf::Visual& visual, const urdf::ModelInterface& model, const std::string& path, std::set<std::string>& missing) {
    LinkShape shape;
    shape.origin = toIsometry(visual.origin);
    const urdf::Geometry& g = *visual.geometry;
    switch (g.type) {
        case urdf::Geometry::SPHERE: {
            shape.kind = LinkShape::Kind::Sphere;
            shape.size = Vector3d::Constant(static_cast<const urdf::Sphere&>(g).radius);
            break;
        }
        case urdf::Geometry::BOX: {
            const urdf::Vector3& d = static_cast<const urdf::Box&>(g).dim;
            shape.kind = LinkShape::Kind::Box;
            shape.size = {d.x, d.y, d.z};
            break;
        }
        case urdf::Geometry::CYLINDER: {
            const auto& c = static_cast<const urdf::Cylinder&>(g);
            shape.kind = LinkShape::Kind::Cylinder;
            shape.size = {c.radius, c.radius, c.length};
            break;
        }
        default: {
            const auto& m = static_cast<const urdf::Mesh&>(g);
            shape.kind = LinkShape::Kind::Mesh;
            shape.mesh = meshPath(m.filename, path, missing);
            shape.size = {m.scale.x, m.scale.y, m.scale.z};
            break;
        }
    }
    // The colour given in the visual, or by its material's name at the robot's top level.
    urdf::MaterialSharedPtr material = visual.material;
    if (material && material->color.r == 0 && material->color.g == 0 && material->color.b == 0 && material->color.a == 1 &&
        !material->name.empty())
        if (const urdf::MaterialSharedPtr named = model.getMaterial(material->name)) material = named;
    if (material && material->texture_filename.empty()) {
        const urdf::Color& c = material->color;
        const float values[] = {c.r, c.g, c.b, c.a};
        const bool inRange = std::all_of(std::begin(values), std::end(values), [](float v) { return v >= 0 && v <= 1; });
        if (inRange && (c.r + c.g + c.b > 0 || c.a < 1))  // urdfdom's black, opaque default is "no colour given"
            for (std::size_t k = 0; k < 4; ++k)       // URDF's floats as the decimals written (0.55, not 0.550000011920929)
                shape.rgba[k] = std::round(double(values[k]) * 1e6) / 1e6;
    }
    return shape;
}

std::string typeName(int type) {
    switch (type) {
        case urdf::Joint::FLOATING: return "floating";
        case urdf::Joint::PLANAR: return "planar";
        default: return "of an unknown type";
    }
}

}  // namespace

UrdfImport importUrdf(const std::string& xml, const std::string& path, const UrdfImportOptions& options) {
    const urdf::ModelInterfaceSharedPtr model = parse(xml, path);
    const urdf::LinkConstSharedPtr base = options.base.empty() ? model->getRoot() : namedLink(*model, options.base, "--base");
    const urdf::LinkConstSharedPtr tip = options.tip.empty() ? defaultTip(base, path) : namedLink(*model, options.tip, "--tip");

    // The chain, tip up to base.
    std::vector<urdf::LinkConstSharedPtr> chain{tip};
    while (chain.back() != base) {
        const urdf::LinkConstSharedPtr parent = chain.back()->getParent();
        if (!parent) throw InputError("--tip", message(MessageId::UrdfTipNotBelowBase, tip->name, base->name));
        chain.push_back(parent);
    }
    std::reverse(chain.begin(), chain.end());

    UrdfImport out;
    out.baseLink = base->name;
    out.tipLink = tip->name;
    std::map<std::string, Isometry3d> pose{{base->name, Isometry3d::Identity()}};
    AxesDescription axes;
    std::vector<std::string> chainLinks;  // the child link of each moving joint
    out.linkFrames.emplace_back(base->name, Isometry3d::Identity());
    for (std::size_t k = 1; k < chain.size(); ++k) {
        const urdf::Joint& joint = *chain[k]->parent_joint;
        if (joint.type == urdf::Joint::FLOATING || joint.type == urdf::Joint::PLANAR || joint.type == urdf::Joint::UNKNOWN)
            throw InputError(path, message(MessageId::UrdfJointNotSerial, joint.name, typeName(joint.type)));
        if (moves(joint) && joint.mimic) throw InputError(path, message(MessageId::UrdfMimicJoint, joint.name, joint.mimic->joint_name));
        const Isometry3d T = pose[chain[k - 1]->name] * toIsometry(joint.parent_to_joint_origin_transform);
        if (!T.matrix().allFinite()) {  // "nan", "inf" or numbers whose product overflows
            const urdf::Vector3& xyz = joint.parent_to_joint_origin_transform.position;
            std::ostringstream written;
            written << xyz.x << " " << xyz.y << " " << xyz.z;
            throw InputError(path + ": <joint name=\"" + joint.name + "\"> <origin>", message(MessageId::ValueNotFinite, written.str()));
        }
        pose[chain[k]->name] = T;
        out.linkFrames.emplace_back(chain[k]->name, T);
        if (!moves(joint)) continue;
        const Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
        if (!(axis.norm() > 1e-12) || !axis.allFinite()) {
            std::ostringstream written;
            written << joint.axis.x << " " << joint.axis.y << " " << joint.axis.z;
            throw InputError(path, message(MessageId::UrdfJointWithoutAxis, joint.name, written.str()));
        }
        axes.axes.push_back({joint.type == urdf::Joint::PRISMATIC ? JointType::Prismatic : JointType::Revolute, T.translation(),
                             T.linear() * axis.normalized()});
        out.jointNames.push_back(joint.name);
        chainLinks.push_back(chain[k]->name);
    }
    if (axes.axes.empty()) throw InputError(path, message(MessageId::UrdfNoMovingJoint, base->name, tip->name));
    axes.tool = pose[tip->name];
    out.dh = dhFromAxes(axes, options.convention);

    // Each moving joint's body: its child link and every link fixed to it, on the chain
    // or off it; moving branches off the chain are left out (said once).
    std::vector<Body> bodies(axes.axes.size());
    std::vector<std::string> leftOut;
    std::vector<std::tuple<const urdf::Link*, Isometry3d, int>> visited;  // every link kept, where it is at home, its body (−1: the base)
    std::function<void(const urdf::Link&, const Isometry3d&, int)> collect = [&](const urdf::Link& link, const Isometry3d& T, int body) {
        visited.emplace_back(&link, T, body);
        if (body >= 0) bodies[static_cast<std::size_t>(body)] = lumped(bodies[static_cast<std::size_t>(body)], bodyOf(link, T));
        for (const auto& child : link.child_links) {
            const urdf::Joint& joint = *child->parent_joint;
            const Isometry3d childPose = T * toIsometry(joint.parent_to_joint_origin_transform);
            const auto next = std::find(chainLinks.begin(), chainLinks.end(), child->name);
            if (!moves(joint)) collect(*child, childPose, body);  // fixed to this body (to the base: it does not move)
            else if (next != chainLinks.end()) collect(*child, childPose, static_cast<int>(next - chainLinks.begin()));
            else leftOut.push_back(child->name);
        }
    };
    collect(*base, Isometry3d::Identity(), -1);
    if (!leftOut.empty()) {
        std::string names;
        for (const std::string& name : leftOut) names += (names.empty() ? "" : ", ") + name;
        out.notes.push_back(message(MessageId::UrdfLeftOut, base->name, tip->name, names));
    }

    Scene& scene = out.scene;
    scene.name = model->getName();
    scene.description = message(MessageId::UrdfImportedFrom, path).english();
    scene.source = path;
    scene.robot.name = model->getName();
    scene.robot.convention = options.convention;
    scene.robot.base = out.dh.base;
    for (double& v : scene.robot.base.matrix().reshaped()) v = cleaned(v, 1.0);
    for (std::size_t i = 0; i < axes.axes.size(); ++i) {
        const Isometry3d frame = out.dh.frames[i + 1].transform();
        Joint joint;
        joint.dh = out.dh.rows[i];
        for (double* v : {&joint.dh.a, &joint.dh.alpha, &joint.dh.d, &joint.dh.theta}) *v = cleaned(*v, 1.0);
        for (const auto& [name, angle] : {std::pair{"alpha", joint.dh.alpha}, std::pair{"theta", joint.dh.theta}})
            if (const std::string text = angleText(angle); !text.empty())
                scene.expressions["robot.joints[" + std::to_string(i) + "]." + name] = text;
        joint.link.mass = bodies[i].mass;
        joint.link.com = frame.inverse() * bodies[i].com;
        joint.link.inertia = frame.linear().transpose() * bodies[i].inertia * frame.linear();
        joint.link.inertia = 0.5 * (joint.link.inertia + joint.link.inertia.transpose()).eval();
        const double largest = joint.link.inertia.cwiseAbs().maxCoeff();
        for (double& v : joint.link.inertia.reshaped()) v = cleaned(v, largest);
        for (double& v : joint.link.com) v = cleaned(v, 1.0);
        scene.robot.joints.push_back(joint);
        const urdf::Joint& urdfJoint = *model->getJoint(out.jointNames[i]);
        if (urdfJoint.dynamics && urdfJoint.dynamics->damping > 0)
            scene.effects.viscous.push_back({static_cast<int>(i), urdfJoint.dynamics->damping});
        if (urdfJoint.dynamics && urdfJoint.dynamics->friction > 0) {
            CoulombFriction friction;
            friction.joint = static_cast<int>(i);
            friction.force = urdfJoint.dynamics->friction;
            scene.effects.coulomb.push_back(friction);
        }
    }
    // Each link as the URDF draws it, on the DH frame of the body it belongs to.
    std::set<std::string> missingPackages;
    for (const auto& [link, T, body] : visited) {
        LinkVisual visual;
        visual.name = link->name;
        visual.body = body + 1;
        visual.frame = body < 0 ? T : out.dh.frames[static_cast<std::size_t>(body + 1)].transform().inverse() * T;
        for (const auto& v : link->visual_array)
            if (v && v->geometry) visual.shapes.push_back(shapeOf(*v, *model, path, missingPackages));
        scene.robot.links.push_back(std::move(visual));
    }
    for (const std::string& package : missingPackages) out.notes.push_back(message(MessageId::UrdfPackageNotFound, path, package));
    // URDF robots feel gravity along −z of the root link; the scene's world is the base link.
    Isometry3d rootToBase = Isometry3d::Identity();
    for (urdf::LinkConstSharedPtr link = base; link->parent_joint; link = link->getParent())
        rootToBase = toIsometry(link->parent_joint->parent_to_joint_origin_transform) * rootToBase;
    Vector3d gravity = rootToBase.linear().transpose() * Vector3d(0, 0, -9.81);
    for (double& v : gravity) v = cleaned(v, 9.81);
    scene.effects.gravity = gravity;
    scene.initial.q = Eigen::VectorXd::Zero(scene.dof());
    scene.initial.qd = Eigen::VectorXd::Zero(scene.dof());
    return out;
}

UrdfImport importUrdfFile(const std::string& path, const UrdfImportOptions& options) {
    std::ifstream file(path);
    if (!file) throw InputError(path, message(MessageId::CannotReadSceneFile, std::strerror(errno)));
    std::stringstream text;
    text << file.rdbuf();
    return importUrdf(text.str(), path, options);
}

}  // namespace ll
