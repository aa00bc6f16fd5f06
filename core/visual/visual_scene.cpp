#include "core/visual/visual_scene.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "core/kinematics/dh_step_through.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/robot_data.hpp"

namespace ll {
namespace {

// Proportions of the stick figure, in units of the robot's reach.
constexpr double kLinkRadius = 0.02;
constexpr double kJointRadius = 0.034, kJointLength = 0.1;
constexpr double kSleeveHalfSide = 0.04, kSleeveLength = 0.2, kBarHalfSide = 0.022;
constexpr double kComRadius = 0.055;  // of the heaviest link; others by (m / m_max)^(1/3)
constexpr double kEndEffectorRadius = 0.03;
constexpr double kTriadLength = 0.12;
constexpr double kPedestalRadius = 0.12, kPedestalThickness = 0.04;
constexpr double kZero = 1e-9;  // [m] a DH length below this draws no segment

Rgba rgb(int r, int g, int b) { return {r / 255.0f, g / 255.0f, b / 255.0f, 1.0f}; }

const Rgba kJointColor = rgb(105, 112, 124);
const Rgba kComColor = rgb(240, 200, 40);
const Rgba kEndEffectorColor = rgb(200, 30, 40);
const Rgba kPedestalColor = rgb(120, 124, 130);

// "#rrggbb" (validated by the scene loader), or the palette's i-th colour.
Rgba parseColor(const std::string& text, int i) {
    if (text.size() != 7 || text[0] != '#') return linkColor(i);
    const auto hex = [&](int k) { return std::stoi(text.substr(k, 2), nullptr, 16); };
    return rgb(hex(1), hex(3), hex(5));
}

// A part along the segment from a to b: centred between them, z along b − a.
void placeAlong(VisualPart& part, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d along = b - a;
    part.length = along.norm();
    part.pose.setIdentity();
    part.pose.translation() = (a + b) / 2;
    if (part.length > 0) part.pose.linear() = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), along).toRotationMatrix();
}

// 1, 2 or 5 times a power of ten, the nearest at or above x.
double niceStep(double x) {
    const double decade = std::pow(10.0, std::floor(std::log10(x)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * decade >= x * 0.999) return m * decade;
    return 10 * decade;
}

}  // namespace

bool stretches(PartShape shape) { return shape == PartShape::Rod || shape == PartShape::Bar; }

void VisualBounds::add(const Eigen::Vector3d& point, double radius) {
    min = min.cwiseMin((point.array() - radius).matrix());
    max = max.cwiseMax((point.array() + radius).matrix());
}

// How each part moves. Robot: forward kinematics into RobotData, then one rule per part.
// Lagrangian: the compiled body poses.
struct VisualScene::Rig {
    enum class Rule { Fixed, JointMarker, Sleeve, FirstSegment, SecondSegment, Com, EndEffector, Body, Look };
    struct PartRule {
        Rule rule = Rule::Fixed;
        int index = 0;     // joint (robot) or body (Lagrangian); a look's DH frame
        bool bar = false;  // a segment drawn as the prismatic joint's bar
        Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();  // a look's pose in its DH frame
    };

    RobotModel robot;
    std::optional<RobotData> data;
    std::optional<BodyPoses> bodies;
    std::vector<BodyPose> bodyPoses;
    std::vector<PartRule> rules;  // one per part
    int n = 0;
    Eigen::VectorXd q;  // the current pose (robot)

    // The point where link i turns from its first segment to its second: standard
    // o_{i-1} + d_i z_{i-1} = o_i − a_i x_i; modified o_{i-1} + a_{i-1} x_{i-1}.
    Eigen::Vector3d elbow(int i) const {
        const Eigen::Isometry3d& from = data->T_0i[i];
        const Eigen::Isometry3d& to = data->T_0i[i + 1];
        const double a = robot.joints[i].dh.a;
        if (robot.convention == DhConvention::Standard) return to.translation() - a * to.linear().col(0);
        return from.translation() + a * from.linear().col(0);
    }
    // The frame whose z is joint i's axis: z_{i-1} (standard) or z_i (modified).
    const Eigen::Isometry3d& jointFrame(int i) const {
        return robot.convention == DhConvention::Standard ? data->T_0i[i] : data->T_0i[i + 1];
    }
    // Whether the d segment (along the joint axis) is link i's first segment.
    bool dFirst() const { return robot.convention == DhConvention::Standard; }
};

VisualScene::~VisualScene() = default;
VisualScene::VisualScene(VisualScene&&) noexcept = default;
VisualScene& VisualScene::operator=(VisualScene&&) noexcept = default;

int VisualScene::dof() const { return rig_->n; }

VisualScene::VisualScene(const Scene& scene, std::optional<BodyPoses> compiledBodies) : rig_(std::make_unique<Rig>()) {
    using Rule = Rig::Rule;
    Rig& rig = *rig_;
    name = scene.name;
    rig.n = scene.dof();
    const auto add = [&](VisualPart part, Rig::PartRule rule) {
        parts.push_back(std::move(part));
        rig.rules.push_back(rule);
    };

    if (scene.lagrangian) {
        const std::vector<VisualBody>& bodies = scene.lagrangian->bodies;
        if (!compiledBodies || compiledBodies->count() != static_cast<int>(bodies.size()))
            throw std::invalid_argument("VisualScene: a Lagrangian scene needs its bodies' compiled poses, one per body");
        rig.bodies = std::move(compiledBodies);
        rig.bodyPoses.resize(rig.bodies->count());
        for (int b = 0; b < static_cast<int>(bodies.size()); ++b) {
            const VisualBody& body = bodies[b];
            VisualPart part;
            part.name = body.name.empty() ? "body " + std::to_string(b + 1) : body.name;
            part.role = PartRole::Body;
            part.color = parseColor(body.color, b);
            const std::vector<double>& s = body.size;
            switch (body.shape) {
                case BodyShape::Box:
                    part.shape = PartShape::Box;
                    part.box = Eigen::Vector3d(s.at(0), s.at(1), s.at(2));
                    break;
                case BodyShape::Sphere:
                    part.shape = PartShape::Sphere;
                    part.radius = s.at(0);
                    endEffector = static_cast<int>(parts.size());  // the trail follows the last sphere (a bob)
                    break;
                case BodyShape::Cylinder:
                    part.shape = PartShape::Cylinder;
                    part.radius = s.at(0);
                    part.length = s.at(1);
                    break;
                case BodyShape::Rod:
                    part.shape = PartShape::Rod;
                    part.radius = s.at(0);
                    break;
            }
            add(part, {Rule::Body, b, false});
        }
        frames.push_back({"world", 0.0, Eigen::Isometry3d::Identity(), true});
        pose(scene.initial.q, 0.0);
        // Sizes come from the bodies: the scale is the extent of the initial pose.
        const VisualBounds initial = currentBounds();
        const Eigen::Vector3d extent = initial.empty() ? Eigen::Vector3d::Ones() : Eigen::Vector3d(initial.max - initial.min);
        scale = std::max(extent.maxCoeff(), 1e-3);
        frames[0].axisLength = kTriadLength * scale;
        // A system drawn in the x–y plane (a pendulum typed by hand) is seen with y up.
        if (extent.z() < 0.35 * std::max(extent.x(), extent.y())) up = Eigen::Vector3d::UnitY();
    } else {
        rig.robot = scene.robot;
        rig.data.emplace(rig.robot);
        const int n = rig.n;
        const bool standard = rig.dFirst();
        // Reach: the stick figure's length at the initial state (prismatic joints at q0).
        double reach = 0.0, heaviest = 0.0;
        for (int i = 0; i < n; ++i) {
            const DhRow& dh = rig.robot.joints[i].dh;
            const double q0 = dh.type == JointType::Prismatic && i < scene.initial.q.size() ? scene.initial.q[i] : 0.0;
            reach += std::abs(dh.a) + std::abs(dh.d + q0);
            heaviest = std::max(heaviest, rig.robot.joints[i].link.mass);
        }
        scale = reach > kZero ? reach : 0.5;
        const double R = scale;
        if (scene.effects.gravity && scene.effects.gravity->norm() > 0) up = -scene.effects.gravity->normalized();

        // Pedestal: a disc behind the first joint, on its axis (fixed in the world).
        if (n > 0) {
            forwardKinematics(rig.robot, *rig.data, Eigen::VectorXd::Zero(n));
            VisualPart pedestal;
            pedestal.name = "pedestal";
            pedestal.shape = PartShape::Cylinder;
            pedestal.role = PartRole::Pedestal;
            pedestal.radius = kPedestalRadius * R;
            pedestal.length = kPedestalThickness * R;
            pedestal.color = kPedestalColor;
            pedestal.pose = rig.jointFrame(0);
            const double behind =
                (rig.robot.joints[0].dh.type == JointType::Revolute ? kJointLength : kSleeveLength) / 2 + kPedestalThickness / 2;
            // Under the start of link 1 on the joint's axis: o_0 (standard), o_0 + a_0 x_0
            // (modified, where d_1 runs from there up to o_1: the Panda's base column).
            const Eigen::Vector3d start = standard ? rig.data->axisPoint[0] : rig.elbow(0);
            pedestal.pose.translation() = start - behind * R * rig.data->axis[0];
            add(pedestal, {Rule::Fixed, 0, false});
        }
        for (int i = 0; i < n; ++i) {
            const Joint& joint = rig.robot.joints[i];
            const bool prismatic = joint.dh.type == JointType::Prismatic;
            const std::string number = std::to_string(i + 1);
            VisualPart marker;
            marker.name = "joint " + number;
            marker.role = PartRole::Joint;
            marker.color = kJointColor;
            marker.coordinate = i;
            if (prismatic) {
                marker.shape = PartShape::Sleeve;
                marker.radius = kSleeveHalfSide * R;
                marker.length = kSleeveLength * R;
                add(marker, {Rule::Sleeve, i, false});
            } else {
                marker.shape = PartShape::Cylinder;
                marker.radius = kJointRadius * R;
                marker.length = kJointLength * R;
                add(marker, {Rule::JointMarker, i, false});
            }
            // The two segments of link i; the one along the joint axis is the bar of a
            // prismatic joint.
            const double dLength = std::abs(joint.dh.d), aLength = std::abs(joint.dh.a);
            for (int segment = 0; segment < 2; ++segment) {
                const bool isD = (segment == 0) == standard;
                if (!(isD ? (prismatic || dLength > kZero) : aLength > kZero)) continue;
                VisualPart link;
                link.name = "link " + number;
                link.role = PartRole::Link;
                link.color = linkColor(i);
                link.coordinate = i;
                const bool bar = isD && prismatic;
                link.shape = bar ? PartShape::Bar : PartShape::Rod;
                link.radius = (bar ? kBarHalfSide : kLinkRadius) * R;
                add(link, {segment == 0 ? Rule::FirstSegment : Rule::SecondSegment, i, bar});
            }
            if (joint.link.mass > 0) {
                VisualPart com;
                com.name = "COM " + number;
                com.shape = PartShape::Sphere;
                com.role = PartRole::CentreOfMass;
                com.radius = kComRadius * R * std::cbrt(joint.link.mass / heaviest);
                com.color = kComColor;
                com.coordinate = i;
                add(com, {Rule::Com, i, false});
            }
        }
        if (n > 0) {
            VisualPart tip;
            tip.name = "end effector";
            tip.shape = PartShape::Sphere;
            tip.role = PartRole::EndEffector;
            tip.radius = kEndEffectorRadius * R;
            tip.color = kEndEffectorColor;
            tip.coordinate = n - 1;
            endEffector = static_cast<int>(parts.size());
            add(tip, {Rule::EndEffector, n - 1, false});
        }
        // The robot's own look: each shape on its link's frame (body 0 fixed in the world).
        for (const LinkVisual& link : scene.robot.links) {
            if (link.body < 0 || link.body > n) continue;
            for (const LinkShape& shape : link.shapes) {
                VisualPart look;
                look.name = link.name;
                look.role = PartRole::Look;
                look.coordinate = link.body - 1;
                look.color = shape.coloured() ? Rgba{float(shape.rgba[0]), float(shape.rgba[1]), float(shape.rgba[2]), float(shape.rgba[3])}
                             : link.body > 0 ? linkColor(link.body - 1)
                                             : kPedestalColor;
                switch (shape.kind) {
                    case LinkShape::Kind::Mesh: look.shape = PartShape::Mesh, look.mesh = shape.mesh, look.box = shape.size; break;
                    case LinkShape::Kind::Box: look.shape = PartShape::Box, look.box = shape.size; break;
                    case LinkShape::Kind::Cylinder: look.shape = PartShape::Cylinder, look.radius = shape.size.x(), look.length = shape.size.z(); break;
                    case LinkShape::Kind::Sphere: look.shape = PartShape::Sphere, look.radius = shape.size.x(); break;
                }
                add(look, {Rule::Look, link.body, false, link.frame * shape.origin});
            }
        }
        for (int k = 0; k <= n; ++k) frames.push_back({std::to_string(k), kTriadLength * R, Eigen::Isometry3d::Identity()});
        labelCoincidentFrames(scene.initial.q);
        pose(scene.initial.q, 0.0);
    }
    bounds = currentBounds();
    forEachExtent(
        [this](const Eigen::Vector3d& point, double radius) { keepInView.emplace_back(point.x(), point.y(), point.z(), radius); });
    if (!scene.lagrangian && !parts.empty() && parts.front().role == PartRole::Pedestal) {  // the floor the pedestal stands on
        const VisualPart& pedestal = parts.front();
        const Eigen::Vector3d axis = pedestal.pose.linear().col(2);
        // The lowest point of the disc: its lower rim's end, whichever way its axis leans.
        const double rim = pedestal.radius * std::sqrt(std::max(0.0, 1.0 - std::pow(axis.dot(up), 2)));
        baseHeight_ = up.dot(pedestal.pose.translation()) - std::abs(axis.dot(up)) * pedestal.length / 2 - rim;
    }
    placeGround();
    for (const VisualPart& part : parts)
        if (part.role == PartRole::CentreOfMass) dropLines.emplace_back(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    placeDropLines();
}

void VisualScene::placeDropLines() {
    std::size_t k = 0;
    const double groundHeight = up.dot(ground.centre);
    for (const VisualPart& part : parts) {
        if (part.role != PartRole::CentreOfMass || k >= dropLines.size()) continue;
        const Eigen::Vector3d c = part.pose.translation();
        dropLines[k++] = {c, c - (up.dot(c) - groundHeight) * up};
    }
}

void VisualScene::labelCoincidentFrames(const Eigen::VectorXd& q0) {
    // Frames whose origins coincide at every pose (the PUMA's wrist: 4, 5 and 6) share
    // one label, "4,5,6", on the first of them; their own labels would print on top of
    // each other. Coincidence is checked at the initial state and at two poses no
    // robot is built around, so frames that only meet at q0 keep their own labels.
    const int n = rig_->n;
    std::vector<bool> together(static_cast<std::size_t>(n), true);  // frame k+1 on frame k
    for (int probe = 0; probe < 3; ++probe) {
        Eigen::VectorXd q = q0;
        if (probe > 0)
            for (int i = 0; i < n; ++i) q[i] = 0.3 + 0.7 * probe + 0.53 * i;  // [rad] or [m]
        forwardKinematics(rig_->robot, *rig_->data, q);
        for (int k = 0; k < n; ++k) {
            const double gap = (rig_->data->T_0i[k + 1].translation() - rig_->data->T_0i[k].translation()).norm();
            if (gap > 1e-9 * scale) together[k] = false;
        }
    }
    for (int k = 0; k < n; ++k) {
        if (!together[k]) continue;
        int first = k;
        while (first > 0 && frames[first].label.empty()) --first;
        frames[first].label += "," + frames[k + 1].label;
        frames[k + 1].label.clear();
    }
}

void VisualScene::pose(const Eigen::VectorXd& q, double t) {
    using Rule = Rig::Rule;
    Rig& rig = *rig_;
    if (rig.bodies) {
        rig.bodies->evaluate(q, t, rig.bodyPoses);
        for (std::size_t p = 0; p < parts.size(); ++p) {
            const BodyPose& body = rig.bodyPoses[rig.rules[p].index];
            parts[p].pose = body.pose;
            if (parts[p].shape == PartShape::Rod) parts[p].length = body.length;
        }
        return;
    }
    if (rig.n == 0) return;
    RobotData& data = *rig.data;
    forwardKinematics(rig.robot, data, q);
    rig.q = q;
    for (std::size_t p = 0; p < parts.size(); ++p) {
        const Rig::PartRule& r = rig.rules[p];
        VisualPart& part = parts[p];
        const int i = r.index;
        switch (r.rule) {
            case Rule::Fixed:
            case Rule::Body: break;
            case Rule::JointMarker:
                part.pose = rig.jointFrame(i);
                part.pose.translation() = data.axisPoint[i];
                break;
            case Rule::Sleeve:
                // Fixed to the previous link, at the bar's start.
                part.pose = rig.jointFrame(i);
                part.pose.translation() = rig.dFirst() ? data.T_0i[i].translation() : rig.elbow(i);
                break;
            case Rule::FirstSegment:
            case Rule::SecondSegment: {
                const bool first = r.rule == Rule::FirstSegment;
                const Eigen::Vector3d a = first ? data.T_0i[i].translation() : rig.elbow(i);
                const Eigen::Vector3d b = first ? rig.elbow(i) : data.T_0i[i + 1].translation();
                placeAlong(part, a, b);
                if (r.bar) part.pose.linear() = rig.jointFrame(i).linear();  // square faces follow the sleeve
                break;
            }
            case Rule::Com:
                part.pose = data.T_0i[i + 1];
                part.pose.translation() = data.p_ci[i];
                break;
            case Rule::EndEffector: part.pose = data.T_0i[i + 1]; break;
            case Rule::Look: part.pose = i == 0 ? r.offset : data.T_0i[i] * r.offset; break;
        }
    }
    for (std::size_t k = 0; k < frames.size(); ++k) frames[k].pose = data.T_0i[k];
    placeDropLines();
}

template <class Add>
void VisualScene::forEachExtent(Add add) const {
    for (const VisualPart& part : parts) {
        // Tight enough that a flat mechanism stays flat: shapes along z by their two
        // ends, boxes by their corners.
        const Eigen::Vector3d c = part.pose.translation(), z = part.pose.linear().col(2);
        switch (part.shape) {
            case PartShape::Sphere: add(c, part.radius); break;
            case PartShape::Box:
                for (int k = 0; k < 8; ++k)
                    add(part.pose * Eigen::Vector3d((k & 1 ? 0.5 : -0.5) * part.box.x(), (k & 2 ? 0.5 : -0.5) * part.box.y(),
                                                    (k & 4 ? 0.5 : -0.5) * part.box.z()),
                        0.0);
                break;
            default: {
                const double across =
                    part.shape == PartShape::Bar || part.shape == PartShape::Sleeve ? std::sqrt(2.0) * part.radius : part.radius;
                add(c - z * part.length / 2, across);
                add(c + z * part.length / 2, across);
            }
        }
    }
    for (const VisualFrame& frame : frames) add(frame.pose.translation(), frame.axisLength);
}

VisualBounds VisualScene::currentBounds() const {
    VisualBounds b;
    forEachExtent([&b](const Eigen::Vector3d& point, double radius) { b.add(point, radius); });
    return b;
}

void VisualScene::currentExtent(std::vector<Eigen::Vector4d>& spheres) const {
    spheres.clear();
    forEachExtent(
        [&spheres](const Eigen::Vector3d& point, double radius) { spheres.emplace_back(point.x(), point.y(), point.z(), radius); });
}

bool VisualScene::steppedFrame(int joint, int done, double fraction, Eigen::Isometry3d& frame) const {
    const Rig& rig = *rig_;
    if (rig.bodies || !rig.data || joint < 0 || joint >= rig.n || rig.q.size() != rig.n) return false;
    frame = ll::steppedFrame(rig.robot, *rig.data, rig.q, joint, done, fraction);
    return true;
}

std::vector<DhDimension> VisualScene::dhDimensions(double arcShare) const {
    const Rig& rig = *rig_;
    if (rig.bodies || !rig.data || rig.q.size() != rig.n) return {};
    return ll::dhDimensions(rig.robot, *rig.data, rig.q, arcShare * scale);
}

std::vector<Eigen::Vector3d> VisualScene::endEffectorPath(const Trajectory& trajectory) {
    std::vector<Eigen::Vector3d> path;
    if (endEffector < 0) return path;
    path.reserve(trajectory.size());
    for (std::size_t k = 0; k < trajectory.size(); ++k) {
        pose(trajectory.q[k], trajectory.t[k]);
        path.push_back(endEffectorPosition());
    }
    return path;
}

Eigen::Vector3d VisualScene::endEffectorPosition() const {
    return endEffector >= 0 ? Eigen::Vector3d(parts[endEffector].pose.translation()) : Eigen::Vector3d::Zero();
}

void VisualScene::fitToMotion(const Trajectory& trajectory, int maxSamples) {
    const int count = static_cast<int>(trajectory.size());
    if (count == 0) return;
    const int used = std::clamp(maxSamples, 2, std::max(2, count));
    for (int k = 0; k < used; ++k) {
        const int s = count == 1 ? 0 : static_cast<int>(std::lround(static_cast<double>(k) * (count - 1) / (used - 1)));
        pose(trajectory.q[s], trajectory.t[s]);
        forEachExtent([this](const Eigen::Vector3d& point, double radius) {
            bounds.add(point, radius);
            keepInView.emplace_back(point.x(), point.y(), point.z(), radius);
        });
    }
    placeGround();
}

void VisualScene::placeGround() {
    // The plane just below the lowest point of the bounds along `up`.
    double lowest = 1e300;
    for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d p((corner & 1) ? bounds.max.x() : bounds.min.x(), (corner & 2) ? bounds.max.y() : bounds.min.y(),
                                (corner & 4) ? bounds.max.z() : bounds.min.z());
        lowest = std::min(lowest, up.dot(p));
    }
    if (bounds.empty()) lowest = 0.0;
    // At the base, unless most of what is drawn hangs below it (the Stanford arm's link-3
    // centre of mass 6.4 m down): a floor above the middle would be seen from underneath.
    if (!std::isnan(baseHeight_) && !bounds.empty() && baseHeight_ <= up.dot(bounds.centre())) lowest = baseHeight_;
    lowest -= 0.01 * scale;
    const Eigen::Vector3d c = bounds.empty() ? Eigen::Vector3d::Zero() : bounds.centre();
    ground.centre = c - (up.dot(c) - lowest) * up;
    ground.spacing = niceStep(scale / 8);
    ground.halfSize = ground.spacing * std::ceil(1.25 * std::max(bounds.radius(), scale / 2) / ground.spacing);
    placeDropLines();
}

}  // namespace ll
