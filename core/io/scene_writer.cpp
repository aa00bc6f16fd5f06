#include "core/io/scene_writer.hpp"
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#include <Eigen/Geometry>

#include "core/symbolic/expression.hpp"
#include "core/symbolic/lagrangian_fields.hpp"
#include "core/simulation/scene_validation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/angle_units.hpp"
#include "core/model/utf8_text.hpp"
#include "core/model/usable_number.hpp"
namespace ll {

namespace {

using namespace scene_json;

class SceneWriter {
public:
    explicit SceneWriter(const Scene& scene) : scene_(scene) {}

    Json write() const {
        Json root;
        root["format"] = kFormat;
        root["name"] = scene_.name;
        if (!scene_.description.empty()) root["description"] = scene_.description;
        if (!scene_.source.empty()) root["source"] = scene_.source;
        if (!scene_.parameters.empty()) {
            Json& parameters = root["parameters"] = Json::object();
            for (const auto& [name, value] : scene_.parameters) parameters[name] = number("parameters." + name, value);
        }
        if (scene_.lagrangian) root["lagrangian"] = lagrangian(*scene_.lagrangian);
        else root["robot"] = robot();
        if (Json e = effects(); !e.empty()) root["effects"] = std::move(e);
        Json& initial = root["initial"] = Json::object();
        if (scene_.initial.q.size() > 0) initial["q"] = vector("initial.q", scene_.initial.q);
        if (scene_.initial.qd.size() > 0) initial["qd"] = vector("initial.qd", scene_.initial.qd);
        if (initial.empty()) root.erase("initial");
        const SimulationSettings& s = scene_.simulation;
        root["simulation"] = {{"duration", number("simulation.duration", s.duration)},
                              {"integrator", s.integrator},
                              {"abs_tol", number("simulation.abs_tol", s.absTol)},
                              {"rel_tol", number("simulation.rel_tol", s.relTol)},
                              {"dt", number("simulation.dt", s.dt)},
                              {"output_rate", number("simulation.output_rate", s.outputRate)}};
        if (!scene_.exercise.empty()) {
            Json& exercise = root["exercise"] = Json::object();
            if (!scene_.exercise.entries.empty()) exercise["entries"] = scene_.exercise.entries;
            Json& answers = exercise["answers"] = Json::object();
            for (const auto& [entry, answer] : scene_.exercise.answers) answers[entry] = answer;
        }
        return root;
    }

private:
    // The expression text if the field came from one; integers without ".0".
    Json number(const std::string& path, double value) const {
        if (const auto text = scene_.expressions.find(path); text != scene_.expressions.end()) return text->second;
        if (std::isfinite(value) && std::floor(value) == value && std::abs(value) < 9.0e15) return static_cast<std::int64_t>(value);
        return value;
    }

    template <class Vector>
    Json vector(const std::string& path, const Vector& values) const {
        Json array = Json::array();
        for (Eigen::Index i = 0; i < values.size(); ++i) array.push_back(number(item(path, static_cast<std::size_t>(i)), values[i]));
        return array;
    }

    bool hasExpressionUnder(const std::string& prefix) const {
        const auto next = scene_.expressions.lower_bound(prefix);
        return next != scene_.expressions.end() && next->first.rfind(prefix, 0) == 0;
    }

    // The base keeps only its rotation, so the angles are recovered from it; rounding
    // to 1e-15 removes the recovery's noise and gives back the exact decimals written.
    // Angles written as expressions stay so when, with them, the rotation is the same
    // (not at pitch = ±π/2, where other roll/yaw pairs give it).
    Json rpy() const {
        const Eigen::Matrix3d R = scene_.robot.base.linear();
        Eigen::Vector3d angles = rpyFromRotation(R);
        for (double& angle : angles) {
            char text[64];
            std::snprintf(text, sizeof text, "%.15f", angle);
            angle = std::strtod(text, nullptr) + 0.0;  // + 0.0 turns -0 into 0
        }
        if (!hasExpressionUnder("robot.base.rpy")) return vector("robot.base.rpy", angles);
        Eigen::Vector3d mixed = angles;
        try {
            const ParameterTable parameters = parameterTable(scene_);
            for (std::size_t i = 0; i < 3; ++i) {
                const std::string field = item("robot.base.rpy", i);
                if (const auto text = scene_.expressions.find(field); text != scene_.expressions.end())
                    mixed[static_cast<Eigen::Index>(i)] = parameters.evaluate(field, text->second);
            }
        } catch (const InputError&) {
            mixed.setConstant(std::nan(""));
        }
        if ((rotationFromRpy(mixed) - R).cwiseAbs().maxCoeff() < 1e-12) return vector("robot.base.rpy", mixed);
        Json numbers = Json::array();
        for (double angle : angles) numbers.push_back(angle);
        return numbers;
    }

    // An expression as written; one that is a plain number is written as the number.
    static Json expression(const std::string& text) {
        try {
            const Json parsed = Json::parse(text);
            if (parsed.is_number()) return parsed;
        } catch (const Json::exception&) {
        }
        return text;
    }

    static Json expressions(const std::array<std::string, 3>& texts) {
        return Json::array({expression(texts[0]), expression(texts[1]), expression(texts[2])});
    }

    Json lagrangian(const LagrangianSpec& spec) const {
        Json out;
        out["coordinates"] = spec.coordinates;
        out["kinetic"] = expression(spec.kinetic);
        out["potential"] = expression(spec.potential);
        if (!spec.forces.empty()) {
            Json& forces = out["forces"] = Json::array();
            for (const std::string& force : spec.forces) forces.push_back(expression(force));
        }
        if (spec.bodies.empty()) return out;
        Json& bodies = out["bodies"] = Json::array();
        for (std::size_t i = 0; i < spec.bodies.size(); ++i) {
            const VisualBody& body = spec.bodies[i];
            const std::string path = item("lagrangian.bodies", i);
            Json entry;
            if (!body.name.empty()) entry["name"] = body.name;
            entry["shape"] = toString(body.shape);
            entry["size"] = vector(child(path, "size"),
                                   Eigen::Map<const Eigen::VectorXd>(body.size.data(), static_cast<Eigen::Index>(body.size.size())));
            entry["position"] = expressions(body.position);
            if (body.shape == BodyShape::Rod) {
                entry["end"] = expressions(body.end);
            } else {
                if (body.angle != "0") entry["angle"] = expression(body.angle);
                if (body.axis != Eigen::Vector3d::UnitZ() || hasExpressionUnder(child(path, "axis")))
                    entry["axis"] = vector(child(path, "axis"), body.axis);
            }
            if (!body.color.empty()) entry["color"] = body.color;
            bodies.push_back(std::move(entry));
        }
        return out;
    }

    Json robot() const {
        const RobotModel& robot = scene_.robot;
        Json out;
        out["convention"] = toString(robot.convention);
        if (!robot.base.matrix().isIdentity(0.0) || hasExpressionUnder("robot.base.")) {
            const Eigen::Vector3d position = robot.base.translation();
            out["base"] = {{"position", vector("robot.base.position", position)}, {"rpy", rpy()}};
        }
        Json& joints = out["joints"] = Json::array();
        for (int i = 0; i < robot.dof(); ++i) {
            const Joint& joint = robot.joints[static_cast<std::size_t>(i)];
            const auto field = [i](const std::string& name) { return jointField(i, name); };
            const Eigen::Matrix3d& I = joint.link.inertia;
            joints.push_back({{"type", toString(joint.dh.type)},
                              {"a", number(field("a"), joint.dh.a)},
                              {"alpha", number(field("alpha"), joint.dh.alpha)},
                              {"d", number(field("d"), joint.dh.d)},
                              {"theta", number(field("theta"), joint.dh.theta)},
                              {"mass", number(field("mass"), joint.link.mass)},
                              {"com", vector(field("com"), joint.link.com)},
                              {"inertia",
                               {{"xx", number(field("inertia.xx"), I(0, 0))},
                                {"yy", number(field("inertia.yy"), I(1, 1))},
                                {"zz", number(field("inertia.zz"), I(2, 2))},
                                {"xy", number(field("inertia.xy"), (I(0, 1) + I(1, 0)) / 2)},
                                {"xz", number(field("inertia.xz"), (I(0, 2) + I(2, 0)) / 2)},
                                {"yz", number(field("inertia.yz"), (I(1, 2) + I(2, 1)) / 2)}}}});
            Json& entry = joints.back();
            const JointMotor& motor = joint.motor;
            if (motor.fromMotor)
                entry["motor"] = {{"inertia", number(field("motor.inertia"), motor.inertia)},
                                  {"gear_ratio", number(field("motor.gear_ratio"), motor.gearRatio)}};
            else if (motor.inertia != 0.0 || hasExpressionUnder(field("armature")))
                entry["armature"] = number(field("armature"), motor.inertia);
            if (joint.range)
                entry["range"] = {number(item(field("range"), 0), joint.range->first), number(item(field("range"), 1), joint.range->second)};
        }
        if (!robot.links.empty()) out["links"] = links(robot.links);
        return out;
    }

    // "position" and "rpy" of a frame, rounded to 1e-15 as the base's angles are.
    static void pose(Json& out, const Eigen::Isometry3d& T) {
        const auto rounded = [](double v) { return std::abs(v) < 1e-15 ? 0.0 : std::round(v * 1e15) / 1e15; };
        const Eigen::Vector3d p = T.translation(), rpy = rpyFromRotation(T.linear());
        if (!p.isZero(0.0)) out["position"] = {rounded(p.x()), rounded(p.y()), rounded(p.z())};
        if (!rpy.isZero(1e-15)) out["rpy"] = {rounded(rpy.x()), rounded(rpy.y()), rounded(rpy.z())};
    }

    static Json links(const std::vector<LinkVisual>& links) {
        Json out = Json::array();
        for (const LinkVisual& link : links) {
            Json entry;
            if (!link.name.empty()) entry["name"] = link.name;
            entry["body"] = link.body;
            pose(entry, link.frame);
            Json& shapes = entry["shapes"] = Json::array();
            for (const LinkShape& shape : link.shapes) {
                Json s;
                const Eigen::Vector3d& v = shape.size;
                switch (shape.kind) {
                    case LinkShape::Kind::Mesh:
                        s["mesh"] = shape.mesh;
                        if (v != Eigen::Vector3d::Ones()) s["scale"] = {v.x(), v.y(), v.z()};
                        break;
                    case LinkShape::Kind::Box: s["box"] = {v.x(), v.y(), v.z()}; break;
                    case LinkShape::Kind::Cylinder: s["cylinder"] = {v.x(), v.z()}; break;
                    case LinkShape::Kind::Sphere: s["sphere"] = v.x(); break;
                }
                pose(s, shape.origin);
                if (shape.coloured()) s["rgba"] = shape.rgba;
                shapes.push_back(std::move(s));
            }
            out.push_back(std::move(entry));
        }
        return out;
    }

    // One list of effect entries; `fields` adds the entry's own numbers after "joint".
    template <class Entry, class Fields>
    void list(Json& effects, const std::string& key, const std::vector<Entry>& entries, Fields fields) const {
        if (entries.empty()) return;
        Json& array = effects[key] = Json::array();
        for (std::size_t i = 0; i < entries.size(); ++i) {
            const std::string path = item("effects." + key, i);
            Json entry;
            entry["joint"] = entries[i].joint + 1;
            fields(entry, entries[i], [&](const std::string& name, double value) { entry[name] = number(child(path, name), value); });
            array.push_back(std::move(entry));
        }
    }

    Json effects() const {
        const Effects& e = scene_.effects;
        Json out = Json::object();
        if (e.gravity) out["gravity"] = vector("effects.gravity", *e.gravity);
        list(out, "springs", e.springs, [](Json&, const JointSpring& s, auto put) {
            put("stiffness", s.stiffness);
            put("rest", s.rest);
        });
        list(out, "viscous", e.viscous, [](Json&, const ViscousFriction& v, auto put) { put("coefficient", v.coefficient); });
        list(out, "coulomb", e.coulomb, [](Json& entry, const CoulombFriction& c, auto put) {
            put("force", c.force);
            put("smoothing", c.smoothing);
            if (c.model != CoulombModel::Tanh) entry["model"] = toString(c.model);
        });
        list(out, "torques", e.torques, [](Json& entry, const JointTorque& t, auto put) {
            entry["kind"] = toString(t.kind);
            switch (t.kind) {
                case TorqueKind::Constant: put("value", t.value); break;
                case TorqueKind::Step:
                    put("value", t.value);
                    put("at", t.at);
                    break;
                case TorqueKind::Sine:
                    put("amplitude", t.amplitude);
                    put("frequency", t.frequency);
                    put("phase", t.phase);
                    break;
                case TorqueKind::Ramp:
                    put("slope", t.slope);
                    put("start", t.start);
                    break;
            }
        });
        if (e.control) out["control"] = control(*e.control);
        return out;
    }

    Json control(const Control& c) const {
        const std::string path = "effects.control";
        const auto perJoint = [&](const std::string& at, const Eigen::VectorXd& v) { return vector(at, v); };
        Json out;
        out["law"] = toString(c.law);
        if (c.wn.size() > 0) {  // as they were given
            out["wn"] = perJoint(child(path, "wn"), c.wn);
            out["zeta"] = perJoint(child(path, "zeta"), c.zeta);
        } else {
            out["kp"] = perJoint(child(path, "kp"), c.kp);
            out["kd"] = perJoint(child(path, "kd"), c.kd);
        }
        if (!c.joints.empty()) {
            Json& joints = out["joints"] = Json::array();
            for (const int j : c.joints) joints.push_back(j + 1);
        }
        const ControlReference& r = c.reference;
        const std::string ref = child(path, "reference");
        Json reference;
        reference["kind"] = toString(r.kind);
        const auto joints = [&](const char* key, const Eigen::VectorXd& v) { reference[key] = perJoint(child(ref, key), v); };
        const auto scalar = [&](const char* key, double v) { reference[key] = number(child(ref, key), v); };
        const bool move = r.kind == ControlReference::Kind::Step || r.kind == ControlReference::Kind::Quintic ||
                          r.kind == ControlReference::Kind::Trapezoidal;  // from q0 to q1
        if (move) joints("q0", r.q0), joints("q1", r.q1);
        switch (r.kind) {
            case ControlReference::Kind::Hold: joints("q", r.q0); break;
            case ControlReference::Kind::Step: scalar("at", r.t0); break;
            case ControlReference::Kind::Quintic: scalar("t0", r.t0), scalar("duration", r.duration); break;
            case ControlReference::Kind::Trapezoidal:
                scalar("t0", r.t0), joints("velocity", r.velocity), joints("acceleration", r.acceleration);
                break;
            case ControlReference::Kind::Waypoints:
                for (std::size_t k = 0; k < r.times.size(); ++k) {
                    const std::string at = child(ref, "points") + "[" + std::to_string(k) + "]";
                    reference["points"].push_back({{"t", number(child(at, "t"), r.times[k])}, {"q", perJoint(child(at, "q"), r.points[k])}});
                }
                break;
            case ControlReference::Kind::Sine:
                joints("q0", r.q0), joints("amplitude", r.amplitude), scalar("frequency", r.frequency), scalar("phase", r.phase);
                break;
        }
        out["reference"] = reference;
        const ControllerModel& m = c.model;
        if (m.payloadMass > 0 || m.scale.size() > 0 || !m.links.empty()) {
            const std::string at = child(path, "model");
            Json model;
            for (std::size_t k = 0; k < m.links.size(); ++k) {
                const std::string l = child(at, "links") + "[" + std::to_string(k) + "]";
                const LinkInertia& own = m.links[k].link;
                const Eigen::Matrix3d& I = own.inertia;
                model["links"].push_back({{"joint", m.links[k].joint + 1},
                                          {"mass", number(child(l, "mass"), own.mass)},
                                          {"com", vector(child(l, "com"), own.com)},
                                          {"inertia", {{"xx", I(0, 0)}, {"yy", I(1, 1)}, {"zz", I(2, 2)}, {"xy", I(0, 1)}, {"xz", I(0, 2)}, {"yz", I(1, 2)}}}});
            }
            if (m.payloadMass > 0) {
                const std::string p = child(at, "payload");
                const Eigen::Matrix3d& I = m.payloadInertia;
                model["payload"] = {{"mass", number(child(p, "mass"), m.payloadMass)},
                                    {"com", vector(child(p, "com"), m.payloadCom)},
                                    {"inertia", {{"xx", I(0, 0)}, {"yy", I(1, 1)}, {"zz", I(2, 2)}, {"xy", I(0, 1)}, {"xz", I(0, 2)}, {"yz", I(1, 2)}}}};
            }
            if (m.scale.size() > 0) model["scale"] = perJoint(child(at, "scale"), m.scale);
            out["model"] = model;
        }
        if (c.torqueLimit.size() > 0) out["limits"] = {{"torque", perJoint(child(path, "limits.torque"), c.torqueLimit)}};
        return out;
    }

    const Scene& scene_;
};

}  // namespace

scene_json::Json writeScene(const Scene& scene) { return SceneWriter(scene).write(); }

}  // namespace ll
