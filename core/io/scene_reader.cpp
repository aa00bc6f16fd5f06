#include "core/io/scene_reader.hpp"
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

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "core/symbolic/expression.hpp"
#include "core/symbolic/lagrangian_fields.hpp"
#include "core/simulation/scene_validation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/angle_units.hpp"
#include "core/model/utf8_text.hpp"
#include "core/model/usable_number.hpp"
#include "core/io/window_view.hpp"
namespace ll {

namespace {

using namespace scene_json;

// Whether a numeric field is an angle: then it takes degrees ("90°", "90 deg") and a
// bare number beyond 2π is warned about (probably degrees typed as radians). `Maybe`:
// degrees are allowed, but the field may as well be a length (a Lagrangian's coordinate).
enum class Angle { No, Yes, Maybe };

class SceneReader {
public:
    explicit SceneReader(std::vector<Diagnostic> errors) : errors_(std::move(errors)) {}

    // Warnings found while reading (angles that look like degrees typed as radians).
    const std::vector<Diagnostic>& warnings() const { return warnings_; }

    Scene read(const Json& root) {
        readFormat(root);
        checkKeys(root, "",
                  {"format", "name", "description", "source", "parameters", "robot", "lagrangian", "effects", "initial", "simulation",
                   "exercise", "views"});
        const std::size_t errorsBefore = errors_.size();
        if (const Json* parameters = member(root, "parameters")) readParameters(*parameters);
        // Every later field may use the parameters: a broken one would echo everywhere.
        if (errors_.size() > errorsBefore) throwIfErrors();

        if (const Json* name = required(root, "", "name", MessageId::SceneTitleField)) readText(*name, "name", scene_.name);
        if (const Json* description = member(root, "description")) readText(*description, "description", scene_.description);
        if (const Json* source = member(root, "source")) readText(*source, "source", scene_.source);
        scene_.robot.name = scene_.name;
        // Exactly one of a robot (DH table) and a Lagrangian typed by hand.
        const Json* robot = member(root, "robot");
        const Json* lagrangian = member(root, "lagrangian");
        if (robot && lagrangian) error("lagrangian", MessageId::RobotAndLagrangianKeysBoth);
        else if (robot) readRobot(*robot);
        else if (lagrangian) readLagrangian(*lagrangian);
        else error("robot", message(MessageId::RequiredFieldMissing, Message(MessageId::RobotOrLagrangianField)));
        if (const Json* effects = member(root, "effects")) readEffects(*effects);
        readInitial(member(root, "initial"));
        if (const Json* simulation = member(root, "simulation")) readSimulation(*simulation);
        if (const Json* exercise = member(root, "exercise")) readExercise(*exercise);
        if (const Json* views = member(root, "views")) readViews(*views);
        throwIfErrors();
        return std::move(scene_);
    }

private:
    void error(const std::string& field, Message message) { errors_.push_back({Severity::Error, field, std::move(message)}); }

    [[noreturn]] void fail(const std::string& field, Message message) {
        error(field, std::move(message));
        throw InputError(errors_);
    }

    void throwIfErrors() const {
        if (!errors_.empty()) throw InputError(errors_);
    }

    static const Json* member(const Json& object, const std::string& key) {
        const auto found = object.find(key);
        return found == object.end() ? nullptr : &*found;
    }

    const Json* required(const Json& object, const std::string& path, const std::string& key, Message what) {
        const Json* value = member(object, key);
        if (!value) error(child(path, key), message(MessageId::RequiredFieldMissing, std::move(what)));
        return value;
    }

    // An object holding only `allowed` keys; false (and an error) when it is no object.
    bool checkObject(const Json& value, const std::string& path, const Keys& allowed) {
        if (!value.is_object()) {
            error(path, expectedGot(MessageId::WantedObject, value));
            return false;
        }
        checkKeys(value, path, allowed);
        return true;
    }

    // `owner`, if given, says whose keys they are ("a box", "a step torque").
    void checkKeys(const Json& object, const std::string& path, const Keys& allowed, const Message& owner = {}) {
        for (const auto& [key, value] : object.items())
            if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())  // "" is named as typed: ""
                error(child(path, key.empty() ? "\"\"" : key), owner.empty() ? message(MessageId::UnknownKey, joined(allowed))
                                                                             : message(MessageId::UnknownKeyFor, owner, joined(allowed)));
    }

    std::optional<double> number(const Json& value, const std::string& path, Angle angle = Angle::No) {
        if (value.is_number()) {
            const double number = value.get<double>();
            if (angle == Angle::Yes) warnIfDegrees(path, number);
            if (auto why = unusableNumber(number)) {
                error(path, *why);
                return std::nullopt;
            }
            return number;
        }
        if (value.is_string()) {
            const std::string text = value.get<std::string>();
            try {
                const double number = parameters_.evaluate(path, text, angle == Angle::No ? AngleUnits::Refused : AngleUnits::Allowed);
                scene_.expressions[path] = text;
                if (angle == Angle::Yes && isPlainNumber(text)) warnIfDegrees(path, number);
                return number;
            } catch (const InputError& e) {
                errors_.insert(errors_.end(), e.diagnostics().begin(), e.diagnostics().end());
                return std::nullopt;
            }
        }
        error(path, expectedGot(MessageId::WantedNumberOrExpression, value));
        return std::nullopt;
    }

    // "90" as a string is as bare as 90.
    static bool isPlainNumber(const std::string& text) {
        char* end = nullptr;
        std::strtod(text.c_str(), &end);
        return end != text.c_str() && text.find_first_not_of(" \t\n", static_cast<std::size_t>(end - text.c_str())) == std::string::npos;
    }

    // A bare number beyond 2π in an angle field is loaded as radians, with a warning.
    void warnIfDegrees(const std::string& path, double value) {
        if (!std::isfinite(value) || std::abs(value) <= 2 * std::numbers::pi) return;
        const DegreeReading reading = readAsDegrees(value);
        const std::string name = path.substr(path.rfind('.') + 1);
        std::ostringstream number;
        number.precision(10);
        number << value;
        warnings_.push_back(
            {Severity::Warning, path, message(MessageId::DegreesTypedAsRadians, name, number.str(), reading.degrees, reading.radians)});
    }

    // Degrees are for a revolute joint's angles; a prismatic joint's q is a length. A
    // Lagrangian's coordinates may be either.
    Angle jointAngle(int joint) const {
        if (scene_.lagrangian) return Angle::Maybe;
        if (joint < 0 || joint >= scene_.robot.dof()) return Angle::Maybe;  // validation names the joint
        return scene_.robot.joints[static_cast<std::size_t>(joint)].dh.type == JointType::Revolute ? Angle::Yes : Angle::No;
    }

    void readNumber(const Json& object, const std::string& path, const std::string& key, double& target, Angle angle = Angle::No) {
        if (const Json* value = member(object, key))
            if (auto n = number(*value, child(path, key), angle)) target = *n;
    }

    void readText(const Json& value, const std::string& path, std::string& target) {
        if (value.is_string()) target = value.get<std::string>();
        else error(path, expectedGot(MessageId::WantedString, value));
    }

    // A string that must be one of `choices`; the index of the match.
    std::optional<std::size_t> readChoice(const Json& value, const std::string& path, const Keys& choices) {
        if (value.is_string()) {
            const auto found = std::find(choices.begin(), choices.end(), value.get<std::string>());
            if (found != choices.end()) return static_cast<std::size_t>(found - choices.begin());
        }
        error(path, message(MessageId::JsonExpectedGot, alternatives(choices), describe(value)));
        return std::nullopt;
    }

    void readVector3(const Json& object, const std::string& path, const std::string& key, Eigen::Vector3d& target,
                     Angle angle = Angle::No) {
        const Json* value = member(object, key);
        if (!value) return;
        const std::string field = child(path, key);
        if (!value->is_array() || value->size() != 3) {
            error(field, expectedGot(MessageId::WantedVector3, *value));
            return;
        }
        for (std::size_t i = 0; i < 3; ++i)
            if (auto n = number((*value)[i], item(field, i), angle)) target[static_cast<Eigen::Index>(i)] = *n;
    }

    void readFormat(const Json& root) {
        const Json* format = member(root, "format");
        if (!format) {
            error("format", message(MessageId::RequiredFieldMissing, message(MessageId::JsonExpected, alternatives({kFormat}))));
            return;
        }
        // Another format (or version) would make every later message misleading.
        if (!format->is_string() || format->get<std::string>() != kFormat)
            fail("format", message(MessageId::JsonExpectedGot, alternatives({kFormat}), describe(*format)));
    }

    void readParameters(const Json& parameters) {
        if (!parameters.is_object()) {
            error("parameters", expectedGot(MessageId::WantedParameterObject, parameters));
            return;
        }
        for (const auto& [name, value] : parameters.items()) {
            const std::string field = child("parameters", name);
            try {
                if (value.is_number()) {
                    parameters_.define(field, name, value.get<double>());
                } else if (value.is_string()) {
                    parameters_.define(field, name, value.get<std::string>());
                    scene_.expressions[field] = value.get<std::string>();
                } else {
                    error(field, expectedGot(MessageId::WantedNumberOrExpression, value));
                    continue;
                }
                scene_.parameters.emplace_back(name, parameters_.value(name));
            } catch (const InputError& e) {
                errors_.insert(errors_.end(), e.diagnostics().begin(), e.diagnostics().end());
            }
        }
    }

    void readRobot(const Json& robot) {
        if (!checkObject(robot, "robot", {"convention", "base", "joints", "links"})) return;
        if (const Json* convention = required(robot, "robot", "convention", MessageId::DhConventionField))
            if (auto choice = readChoice(*convention, "robot.convention", {"standard", "modified"}))
                scene_.robot.convention = *choice == 0 ? DhConvention::Standard : DhConvention::Modified;
        if (const Json* base = member(robot, "base")) readBase(*base);
        const Json* joints = required(robot, "robot", "joints", MessageId::JointsField);
        if (!joints) return;
        if (!joints->is_array() || joints->empty()) {
            error("robot.joints", expectedGot(MessageId::WantedJointArray, *joints));
            return;
        }
        scene_.robot.joints.resize(joints->size());
        for (std::size_t i = 0; i < joints->size(); ++i)
            readJoint((*joints)[i], jointField(static_cast<int>(i), ""), scene_.robot.joints[i]);
        if (const Json* links = member(robot, "links")) readLinks(*links);
    }

    // "links": the robot as its own description draws it (core/model/link_visual.hpp).
    void readLinks(const Json& links) {
        if (!links.is_array()) {
            error("robot.links", expectedGot(MessageId::WantedObjectArray, links));
            return;
        }
        for (std::size_t i = 0; i < links.size(); ++i) {
            const Json& link = links[i];
            const std::string path = item("robot.links", i);
            if (!checkObject(link, path, {"name", "body", "position", "rpy", "shapes"})) continue;
            LinkVisual visual;
            if (const Json* name = member(link, "name")) readText(*name, child(path, "name"), visual.name);
            if (const Json* body = member(link, "body")) {
                const int n = scene_.robot.dof();
                if (body->is_number_integer() && body->get<long long>() >= 0 && body->get<long long>() <= n)
                    visual.body = static_cast<int>(body->get<long long>());
                else
                    error(child(path, "body"), message(MessageId::JsonExpectedGot, message(MessageId::WantedLinkBody, n), describe(*body)));
            }
            visual.frame = readPose(link, path);
            const Json* shapes = member(link, "shapes");
            if (shapes && !shapes->is_array()) error(child(path, "shapes"), expectedGot(MessageId::WantedObjectArray, *shapes));
            else if (shapes)
                for (std::size_t k = 0; k < shapes->size(); ++k) readShape((*shapes)[k], item(child(path, "shapes"), k), visual.shapes);
            scene_.robot.links.push_back(std::move(visual));
        }
    }

    // "position" [m] and "rpy" [rad] of a frame in its parent.
    Eigen::Isometry3d readPose(const Json& object, const std::string& path) {
        Eigen::Vector3d position = Eigen::Vector3d::Zero(), rpy = Eigen::Vector3d::Zero();
        readVector3(object, path, "position", position);
        readVector3(object, path, "rpy", rpy, Angle::Yes);
        Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
        pose.linear() = rotationFromRpy(rpy);
        pose.translation() = position;
        return pose;
    }

    // One of {"mesh": FILE, "scale": [..]}, {"box": [x, y, z]}, {"cylinder": [radius, length]},
    // {"sphere": radius}, with "position", "rpy" and "rgba".
    void readShape(const Json& shape, const std::string& path, std::vector<LinkShape>& shapes) {
        if (!checkObject(shape, path, {"mesh", "scale", "box", "cylinder", "sphere", "position", "rpy", "rgba"})) return;
        int kinds = 0;
        LinkShape out;
        out.origin = readPose(shape, path);
        const auto positive = [&](double v, const std::string& field) {
            if (!(v > 0)) error(field, message(MessageId::JsonExpectedGot, Message(MessageId::WantedPositiveSize), describe(Json(v))));
        };
        if (const Json* mesh = member(shape, "mesh")) {
            ++kinds;
            out.kind = LinkShape::Kind::Mesh;
            readText(*mesh, child(path, "mesh"), out.mesh);
            readVector3(shape, path, "scale", out.size);
            for (Eigen::Index c = 0; c < 3; ++c) positive(out.size[c], item(child(path, "scale"), static_cast<std::size_t>(c)));
        }
        if (member(shape, "box")) {
            ++kinds;
            out.kind = LinkShape::Kind::Box;
            readVector3(shape, path, "box", out.size);
            for (Eigen::Index c = 0; c < 3; ++c) positive(out.size[c], item(child(path, "box"), static_cast<std::size_t>(c)));
        }
        if (const Json* cylinder = member(shape, "cylinder")) {
            ++kinds;
            out.kind = LinkShape::Kind::Cylinder;
            if (!cylinder->is_array() || cylinder->size() != 2) {
                error(child(path, "cylinder"), expectedGot(MessageId::WantedNumberArray, *cylinder));
            } else {
                const auto radius = number((*cylinder)[0], item(child(path, "cylinder"), 0));
                const auto length = number((*cylinder)[1], item(child(path, "cylinder"), 1));
                if (radius && length) {
                    out.size = {*radius, *radius, *length};
                    positive(*radius, item(child(path, "cylinder"), 0));
                    positive(*length, item(child(path, "cylinder"), 1));
                }
            }
        }
        if (member(shape, "sphere")) {
            ++kinds;
            out.kind = LinkShape::Kind::Sphere;
            double radius = 0;
            readNumber(shape, path, "sphere", radius);
            out.size = Eigen::Vector3d::Constant(radius);
            positive(radius, child(path, "sphere"));
        }
        if (kinds != 1) error(path, message(MessageId::JsonExpectedGot, Message(MessageId::WantedOneShape), describe(shape)));
        if (const Json* rgba = member(shape, "rgba")) {
            if (!rgba->is_array() || rgba->size() != 4) {
                error(child(path, "rgba"), expectedGot(MessageId::WantedNumberArray, *rgba));
            } else {
                for (std::size_t c = 0; c < 4; ++c) {
                    const auto v = number((*rgba)[c], item(child(path, "rgba"), c));
                    if (v && (*v < 0 || *v > 1)) error(item(child(path, "rgba"), c), message(MessageId::JsonExpectedGot, Message(MessageId::WantedUnitInterval), describe((*rgba)[c])));
                    else if (v) out.rgba[c] = *v;
                }
            }
        }
        shapes.push_back(std::move(out));
    }

    // The "lagrangian" block (core/model/lagrangian_spec.hpp): every expression is parsed
    // here, so its errors name the field and the position when the file is read.
    void readLagrangian(const Json& value) {
        const std::string path = "lagrangian";
        if (!checkObject(value, path, {"coordinates", "kinetic", "potential", "forces", "bodies"})) return;
        LagrangianSpec spec;
        if (const Json* coordinates = required(value, path, "coordinates", MessageId::CoordinatesField)) {
            if (!coordinates->is_array() || coordinates->empty())
                error("lagrangian.coordinates", expectedGot(MessageId::WantedNameArray, *coordinates));
            else
                for (std::size_t i = 0; i < coordinates->size(); ++i) {
                    const Json& name = (*coordinates)[i];
                    if (name.is_string()) spec.coordinates.push_back(name.get<std::string>());
                    else error(item("lagrangian.coordinates", i), expectedGot(MessageId::WantedName, name));
                }
        }
        const std::size_t errorsBefore = errors_.size();
        for (const Diagnostic& d : checkCoordinateNames(spec.coordinates, parameters_)) errors_.push_back(d);
        // Without usable names every expression would echo the problem.
        const bool namesOk = errors_.size() == errorsBefore && !spec.coordinates.empty();
        const LagrangianSymbols symbols = lagrangianSymbols(spec.coordinates);
        const auto expression = [&](const Json& text, const std::string& field, LagrangianField kind) -> std::string {
            if (!text.is_string() && !text.is_number()) {
                error(field, expectedGot(MessageId::WantedExpressionOrNumber, text));
                return "0";
            }
            const std::string written = text.is_string() ? text.get<std::string>() : text.dump();
            if (namesOk) try {
                    (void)parseLagrangianField(parameters_, symbols, field, written, kind);
                } catch (const InputError& e) {
                    errors_.insert(errors_.end(), e.diagnostics().begin(), e.diagnostics().end());
                }
            return written;
        };
        if (const Json* kinetic = required(value, path, "kinetic", MessageId::KineticField))
            spec.kinetic = expression(*kinetic, "lagrangian.kinetic", LagrangianField::Kinetic);
        if (const Json* potential = member(value, "potential"))
            spec.potential = expression(*potential, "lagrangian.potential", LagrangianField::Potential);
        if (const Json* forces = member(value, "forces")) {
            if (!forces->is_array()) error("lagrangian.forces", expectedGot(MessageId::WantedForceArray, *forces));
            else
                for (std::size_t i = 0; i < forces->size(); ++i)
                    spec.forces.push_back(expression((*forces)[i], item("lagrangian.forces", i), LagrangianField::Force));
        }
        if (const Json* bodies = member(value, "bodies")) {
            if (!bodies->is_array()) error("lagrangian.bodies", expectedGot(MessageId::WantedObjectArray, *bodies));
            else
                for (std::size_t i = 0; i < bodies->size(); ++i) {
                    VisualBody body;
                    readBody((*bodies)[i], item("lagrangian.bodies", i), body, expression);
                    spec.bodies.push_back(std::move(body));
                }
        }
        scene_.lagrangian = std::move(spec);
    }

    template <class Expression>
    void readBody(const Json& body, const std::string& path, VisualBody& target, const Expression& expression) {
        if (!body.is_object()) {
            error(path, expectedGot(MessageId::WantedObject, body));
            return;
        }
        static const Keys shapes = {"box", "sphere", "cylinder", "rod"};
        std::optional<std::size_t> shape;
        if (const Json* value = required(body, path, "shape", alternatives(shapes)))
            shape = readChoice(*value, child(path, "shape"), shapes);
        if (shape) target.shape = static_cast<BodyShape>(*shape);
        const bool rod = shape && target.shape == BodyShape::Rod;
        if (shape)
            checkKeys(body, path,
                      rod ? Keys{"name", "shape", "size", "position", "end", "color"}
                          : Keys{"name", "shape", "size", "position", "angle", "axis", "color"},
                      message(MessageId::ShapeOfKind, shapes[*shape]));
        if (const Json* name = member(body, "name")) readText(*name, child(path, "name"), target.name);
        if (const Json* color = member(body, "color")) {
            readText(*color, child(path, "color"), target.color);
            static const std::regex hex("#[0-9A-Fa-f]{6}");
            if (color->is_string() && !std::regex_match(target.color, hex))
                error(child(path, "color"), expectedGot(MessageId::WantedColour, *color));
        }
        if (const Json* size = required(body, path, "size", MessageId::ShapeSizeField)) {
            const std::string field = child(path, "size");
            if (!size->is_array()) {
                error(field, expectedGot(MessageId::WantedNumberArray, *size));
            } else {
                target.size.assign(size->size(), 0.0);
                for (std::size_t k = 0; k < size->size(); ++k)
                    if (auto n = number((*size)[k], item(field, k))) target.size[k] = *n;
            }
        }
        const auto point = [&](const char* key, std::array<std::string, 3>& out) {
            const Json* value = member(body, key);
            if (!value) return;
            const std::string field = child(path, key);
            if (!value->is_array() || value->size() != 3) {
                error(field, expectedGot(MessageId::WantedPoint, *value));
                return;
            }
            for (std::size_t k = 0; k < 3; ++k) out[k] = expression((*value)[k], item(field, k), LagrangianField::Pose);
        };
        point("position", target.position);
        if (rod) point("end", target.end);
        if (const Json* angle = member(body, "angle")) target.angle = expression(*angle, child(path, "angle"), LagrangianField::Pose);
        readVector3(body, path, "axis", target.axis);
    }

    void readBase(const Json& base) {
        if (!checkObject(base, "robot.base", {"position", "rpy"})) return;
        Eigen::Vector3d position = Eigen::Vector3d::Zero(), rpy = Eigen::Vector3d::Zero();
        readVector3(base, "robot.base", "position", position);
        readVector3(base, "robot.base", "rpy", rpy, Angle::Yes);
        scene_.robot.base = Eigen::Isometry3d::Identity();
        scene_.robot.base.translation() = position;
        scene_.robot.base.linear() = rotationFromRpy(rpy);
    }

    void readJoint(const Json& joint, const std::string& path, Joint& target) {
        if (!checkObject(joint, path, {"type", "a", "alpha", "d", "theta", "mass", "com", "inertia", "armature", "motor", "range"})) return;
        if (const Json* type = member(joint, "type"))
            if (auto choice = readChoice(*type, child(path, "type"), {"revolute", "prismatic"}))
                target.dh.type = *choice == 0 ? JointType::Revolute : JointType::Prismatic;
        readNumber(joint, path, "a", target.dh.a);
        readNumber(joint, path, "alpha", target.dh.alpha, Angle::Yes);
        readNumber(joint, path, "d", target.dh.d);
        // θ is the revolute joint's offset angle; a prismatic joint's θ is a constant angle too.
        readNumber(joint, path, "theta", target.dh.theta, Angle::Yes);
        if (required(joint, path, "mass", MessageId::LinkMassField)) readNumber(joint, path, "mass", target.link.mass);
        readVector3(joint, path, "com", target.link.com);
        if (const Json* inertia = member(joint, "inertia")) readInertia(*inertia, child(path, "inertia"), target.link);
        readMotor(joint, path, target.motor);
        if (const Json* range = member(joint, "range")) readRange(*range, child(path, "range"), target);
    }

    // "range": [lower, upper], radians (or degrees as the scene's angles) or metres.
    void readRange(const Json& value, const std::string& path, Joint& target) {
        if (!value.is_array() || value.size() != 2) {
            error(path, expectedGot(MessageId::WantedJointRange, value));
            return;
        }
        const Angle angle = target.dh.type == JointType::Revolute ? Angle::Yes : Angle::No;
        const auto lower = number(value[0], item(path, 0), angle), upper = number(value[1], item(path, 1), angle);
        if (!lower || !upper) return;
        if (!(*lower < *upper)) {
            error(path, expectedGot(MessageId::WantedJointRange, value));
            return;
        }
        target.range = std::pair{*lower, *upper};
    }

    // "armature": Jm G² as one number, or "motor": {"inertia": Jm, "gear_ratio": G}.
    void readMotor(const Json& joint, const std::string& path, JointMotor& motor) {
        const Json* armature = member(joint, "armature");
        const Json* rotor = member(joint, "motor");
        if (armature && rotor) {
            error(child(path, "motor"), MessageId::ArmatureAndMotorBoth);
            return;
        }
        if (armature) readNumber(joint, path, "armature", motor.inertia);
        if (!rotor) return;
        const std::string field = child(path, "motor");
        if (!checkObject(*rotor, field, {"inertia", "gear_ratio"})) return;
        motor.fromMotor = true;
        if (required(*rotor, field, "inertia", MessageId::RotorInertiaField)) readNumber(*rotor, field, "inertia", motor.inertia);
        if (required(*rotor, field, "gear_ratio", MessageId::GearRatioField)) readNumber(*rotor, field, "gear_ratio", motor.gearRatio);
    }

    void readInertia(const Json& inertia, const std::string& path, LinkInertia& link) {
        if (!checkObject(inertia, path, {"xx", "yy", "zz", "xy", "xz", "yz"})) return;
        const std::pair<const char*, std::pair<int, int>> entries[] = {{"xx", {0, 0}}, {"yy", {1, 1}}, {"zz", {2, 2}},
                                                                       {"xy", {0, 1}}, {"xz", {0, 2}}, {"yz", {1, 2}}};
        for (const auto& [key, index] : entries) {
            double value = 0.0;
            readNumber(inertia, path, key, value);
            link.inertia(index.first, index.second) = link.inertia(index.second, index.first) = value;
        }
    }

    // Effects number joints from 1; the structs from 0.
    std::optional<int> readJointNumber(const Json& entry, const std::string& path) {
        const Json* value = required(entry, path, "joint", MessageId::EffectJointField);
        if (!value) return std::nullopt;
        const std::string field = child(path, "joint");
        const bool integral = value->is_number() && std::floor(value->get<double>()) == value->get<double>();
        if (!integral || std::abs(value->get<double>()) > 1e6) {
            error(field, expectedGot(MessageId::WantedJointNumber, *value));
            return std::nullopt;
        }
        const int joint = static_cast<int>(value->get<double>());
        if (joint < 1) {
            error(field, message(MessageId::JointsNumberedFromOne, value->dump()));
            return std::nullopt;
        }
        return joint - 1;
    }

    template <class Entry>
    void readList(const Json& effects, const std::string& key, std::vector<Entry>& target,
                  const std::function<void(const Json&, const std::string&, Entry&)>& readEntry) {
        const Json* list = member(effects, key);
        if (!list) return;
        const std::string path = child("effects", key);
        if (!list->is_array()) {
            error(path, expectedGot(MessageId::WantedObjectArray, *list));
            return;
        }
        for (std::size_t i = 0; i < list->size(); ++i) {
            const Json& entry = (*list)[i];
            const std::string field = item(path, i);
            if (!entry.is_object()) {
                error(field, expectedGot(MessageId::WantedObject, entry));
                continue;
            }
            Entry parsed;
            if (auto joint = readJointNumber(entry, field)) parsed.joint = *joint;
            readEntry(entry, field, parsed);
            target.push_back(parsed);
        }
    }

    void readEffects(const Json& effects) {
        if (!checkObject(effects, "effects", {"gravity", "springs", "viscous", "coulomb", "torques", "control"})) return;
        if (member(effects, "gravity")) {
            Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
            readVector3(effects, "effects", "gravity", gravity);
            scene_.effects.gravity = gravity;
        }
        Effects& e = scene_.effects;
        readList<JointSpring>(effects, "springs", e.springs, [this](const Json& j, const std::string& p, JointSpring& s) {
            checkKeys(j, p, {"joint", "stiffness", "rest"});
            readNumber(j, p, "stiffness", s.stiffness);
            readNumber(j, p, "rest", s.rest, jointAngle(s.joint));
        });
        readList<ViscousFriction>(effects, "viscous", e.viscous, [this](const Json& j, const std::string& p, ViscousFriction& v) {
            checkKeys(j, p, {"joint", "coefficient"});
            readNumber(j, p, "coefficient", v.coefficient);
        });
        readList<CoulombFriction>(effects, "coulomb", e.coulomb, [this](const Json& j, const std::string& p, CoulombFriction& c) {
            checkKeys(j, p, {"joint", "force", "smoothing", "model"});
            readNumber(j, p, "force", c.force);
            readNumber(j, p, "smoothing", c.smoothing);
            if (const Json* model = member(j, "model"))
                if (auto choice = readChoice(*model, child(p, "model"), {"tanh", "stick"})) c.model = static_cast<CoulombModel>(*choice);
        });
        readList<JointTorque>(effects, "torques", e.torques,
                              [this](const Json& j, const std::string& p, JointTorque& t) { readTorque(j, p, t); });
        if (const Json* control = member(effects, "control")) readControl(*control);
    }

    // One number per joint at `key` of `object` (revolute positions as angles when
    // `angles`); `positive`: each > 0, else ≥ 0 when `nonNegative`. Empty when absent.
    Eigen::VectorXd readPerJoint(const Json& object, const std::string& path, const std::string& key, bool angles = false,
                                 bool positive = false, bool nonNegative = false) {
        const Json* value = member(object, key);
        const int n = scene_.dof();
        if (!value) return {};
        const std::string field = child(path, key);
        if (!value->is_array() || static_cast<int>(value->size()) != n) {
            error(field, message(MessageId::JsonExpectedGot, message(MessageId::WantedPerJoint, n), describe(*value)));
            return {};
        }
        Eigen::VectorXd out = Eigen::VectorXd::Zero(n);
        for (int i = 0; i < n; ++i) {
            const std::string at = item(field, static_cast<std::size_t>(i));
            const auto x = number((*value)[static_cast<std::size_t>(i)], at, angles ? jointAngle(i) : Angle::No);
            if (!x) continue;
            if ((positive && !(*x > 0)) || (nonNegative && !(*x >= 0)))
                error(at, message(MessageId::JsonExpectedGot, Message(positive ? MessageId::WantedPositiveSize : MessageId::WantedNonNegative),
                                  describe((*value)[static_cast<std::size_t>(i)])));
            out[i] = *x;
        }
        return out;
    }

    // "control": a joint-space controller (core/model/control.hpp).
    void readControl(const Json& value) {
        const std::string path = "effects.control";
        if (!checkObject(value, path, {"law", "kp", "kd", "wn", "zeta", "reference", "model", "limits", "joints"})) return;
        if (scene_.lagrangian) {
            error(path, MessageId::ControlNeedsRobot);
            return;
        }
        const int n = scene_.dof();
        Control control;
        if (const Json* law = required(value, path, "law", MessageId::ControlLawField))
            if (auto choice = readChoice(*law, child(path, "law"), {"pd", "pd_gravity", "computed_torque", "feedforward"}))
                control.law = static_cast<ControlLaw>(*choice);
        // The gains as kp, kd, or as a natural frequency and damping ratio (zeta 1 unless given).
        const bool byFrequency = member(value, "wn") || member(value, "zeta");
        if (byFrequency && (member(value, "kp") || member(value, "kd"))) error(child(path, "wn"), MessageId::ControlGainsTwice);
        else if (byFrequency) {
            if (required(value, path, "wn", MessageId::ControlGainsField)) control.wn = readPerJoint(value, path, "wn", false, false, true);
            control.zeta = member(value, "zeta") ? readPerJoint(value, path, "zeta", false, false, true) : Eigen::VectorXd::Ones(n);
        } else
            for (const char* key : {"kp", "kd"}) {
                if (!required(value, path, key, MessageId::ControlGainsField)) continue;
                Eigen::VectorXd gains = readPerJoint(value, path, key, false, false, true);
                (std::string(key) == "kp" ? control.kp : control.kd) = gains;
            }
        if (const Json* joints = member(value, "joints")) {
            const std::string field = child(path, "joints");
            if (!joints->is_array()) error(field, expectedGot(MessageId::WantedNumberArray, *joints));
            else
                for (std::size_t k = 0; k < joints->size(); ++k) {
                    const Json& j = (*joints)[k];
                    if (j.is_number_integer() && j.get<long long>() >= 1 && j.get<long long>() <= n) control.joints.push_back(static_cast<int>(j.get<long long>()) - 1);
                    else error(item(field, k), expectedGot(MessageId::WantedJointNumber, j));
                }
            if (const Message why = lawImpossible(control, n); !why.empty()) error(field, why);
        }
        // A controlled joint needs K_p > 0 (K_d may be 0).
        for (int i = 0; i < control.wn.size(); ++i)
            if (control.drives(i) && !(control.wn[i] > 0))
                error(item(child(path, "wn"), static_cast<std::size_t>(i)), message(MessageId::ControlledJointWithoutFrequency, i + 1));
        for (int i = 0; i < control.kp.size(); ++i)
            if (control.drives(i) && !(control.kp[i] > 0))
                error(item(child(path, "kp"), static_cast<std::size_t>(i)), message(MessageId::ControlledJointWithoutGain, i + 1));
        if (const Json* reference = required(value, path, "reference", MessageId::ControlReferenceField))
            readReference(*reference, child(path, "reference"), control.reference);
        if (const Json* model = member(value, "model")) readControllerModel(*model, child(path, "model"), control.model);
        if (const Json* limits = member(value, "limits"))
            if (checkObject(*limits, child(path, "limits"), {"torque"})) control.torqueLimit = readPerJoint(*limits, child(path, "limits"), "torque", false, true);
        scene_.effects.control = std::move(control);
    }

    void readReference(const Json& value, const std::string& path, ControlReference& r) {
        static const Keys kinds = {"hold", "step", "quintic", "trapezoidal", "sine", "waypoints"};
        static const Keys keysOf[] = {{"q"}, {"q0", "q1", "at"},
                                      {"q0", "q1", "t0", "duration"}, {"q0", "q1", "t0", "velocity", "acceleration"},
                                      {"q0", "amplitude", "frequency", "phase"}, {"points"}};
        if (!value.is_object()) {
            error(path, expectedGot(MessageId::WantedObject, value));
            return;
        }
        std::optional<std::size_t> kind;
        if (const Json* k = required(value, path, "kind", MessageId::ControlReferenceField)) kind = readChoice(*k, child(path, "kind"), kinds);
        if (!kind) return;
        r.kind = static_cast<ControlReference::Kind>(*kind);
        Keys allowed = {"kind"};
        allowed.insert(allowed.end(), keysOf[*kind].begin(), keysOf[*kind].end());
        checkKeys(value, path, allowed);
        const int n = scene_.dof();
        const auto joints = [&](const char* key, bool angles, bool positive = false) {
            if (!required(value, path, key, message(MessageId::WantedPerJoint, n))) return Eigen::VectorXd(Eigen::VectorXd::Zero(n));
            Eigen::VectorXd v = readPerJoint(value, path, key, angles, positive);
            return v.size() == n ? v : Eigen::VectorXd(Eigen::VectorXd::Zero(n));
        };
        switch (r.kind) {
            case ControlReference::Kind::Hold: r.q0 = joints("q", true); break;
            case ControlReference::Kind::Step:
                r.q0 = joints("q0", true), r.q1 = joints("q1", true);
                readNumber(value, path, "at", r.t0);
                break;
            case ControlReference::Kind::Quintic:
                r.q0 = joints("q0", true), r.q1 = joints("q1", true);
                readNumber(value, path, "t0", r.t0);
                readNumber(value, path, "duration", r.duration);
                if (!(r.duration > 0)) error(child(path, "duration"), message(MessageId::JsonExpectedGot, Message(MessageId::WantedPositiveSize), describe(Json(r.duration))));
                break;
            case ControlReference::Kind::Trapezoidal:
                r.q0 = joints("q0", true), r.q1 = joints("q1", true);
                readNumber(value, path, "t0", r.t0);
                r.velocity = joints("velocity", false, true), r.acceleration = joints("acceleration", false, true);
                break;
            case ControlReference::Kind::Sine:
                r.q0 = joints("q0", true), r.amplitude = joints("amplitude", false);
                readNumber(value, path, "frequency", r.frequency);
                readNumber(value, path, "phase", r.phase, Angle::Yes);
                break;
            case ControlReference::Kind::Waypoints: readWaypoints(value, path, r); break;
        }
    }

    // "points": [{"t": 0, "q": [...]}, ...]: at least two, their times increasing.
    void readWaypoints(const Json& value, const std::string& path, ControlReference& r) {
        const Json* points = required(value, path, "points", MessageId::WantedWaypoints);
        if (!points) return;
        const std::string field = child(path, "points");
        if (!points->is_array() || points->size() < 2) {
            error(field, expectedGot(MessageId::WantedWaypoints, *points));
            return;
        }
        for (std::size_t k = 0; k < points->size(); ++k) {
            const std::string at = item(field, k);
            const Json& point = (*points)[k];
            if (!checkObject(point, at, {"t", "q"})) return;
            double t = 0.0;
            if (required(point, at, "t", MessageId::WantedWaypoints)) readNumber(point, at, "t", t);
            if (!r.times.empty() && !(t > r.times.back()))
                error(child(at, "t"), message(MessageId::WaypointTimesNotIncreasing, formatValue(t), formatValue(r.times.back())));
            Eigen::VectorXd q = Eigen::VectorXd::Zero(scene_.dof());
            if (required(point, at, "q", message(MessageId::WantedPerJoint, scene_.dof())))
                if (Eigen::VectorXd v = readPerJoint(point, at, "q", true); v.size() == scene_.dof()) q = v;
            r.times.push_back(t);
            r.points.push_back(q);
        }
    }

    // The controller's own robot: a payload on the last link, links scaled.
    void readControllerModel(const Json& value, const std::string& path, ControllerModel& m) {
        if (!checkObject(value, path, {"links", "payload", "scale"})) return;
        if (const Json* links = member(value, "links")) {
            const std::string field = child(path, "links");
            if (!links->is_array()) error(field, expectedGot(MessageId::WantedObjectArray, *links));
            else
                for (std::size_t k = 0; k < links->size(); ++k) {
                    const Json& entry = (*links)[k];
                    const std::string at = item(field, k);
                    if (!checkObject(entry, at, {"joint", "mass", "com", "inertia"})) continue;
                    ControllerLink own;
                    const std::optional<int> joint = readJointNumber(entry, at);
                    if (!joint) continue;
                    if (*joint >= scene_.dof()) {
                        error(child(at, "joint"), expectedGot(MessageId::WantedJointNumber, entry["joint"]));
                        continue;
                    }
                    own.joint = *joint;
                    if (required(entry, at, "mass", MessageId::LinkMassField)) readNumber(entry, at, "mass", own.link.mass);
                    if (!(own.link.mass >= 0)) error(child(at, "mass"), message(MessageId::JsonExpectedGot, Message(MessageId::WantedNonNegative), describe(Json(own.link.mass))));
                    readVector3(entry, at, "com", own.link.com);
                    if (const Json* inertia = member(entry, "inertia")) readInertia(*inertia, child(at, "inertia"), own.link);
                    m.links.push_back(own);
                }
        }
        if (const Json* payload = member(value, "payload")) {
            const std::string field = child(path, "payload");
            if (checkObject(*payload, field, {"mass", "com", "inertia"})) {
                readNumber(*payload, field, "mass", m.payloadMass);
                if (!(m.payloadMass >= 0)) error(child(field, "mass"), message(MessageId::JsonExpectedGot, Message(MessageId::WantedNonNegative), describe(Json(m.payloadMass))));
                readVector3(*payload, field, "com", m.payloadCom);
                if (const Json* inertia = member(*payload, "inertia")) {
                    LinkInertia link;
                    readInertia(*inertia, child(field, "inertia"), link);
                    m.payloadInertia = link.inertia;
                    // Physical: principal moments ≥ 0, each at most the sum of the other two.
                    const Eigen::Vector3d p = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(link.inertia).eigenvalues();
                    const double tolerance = 1e-12 * std::max(1.0, p.cwiseAbs().maxCoeff());
                    if (p.minCoeff() < -tolerance || p[2] > p[0] + p[1] + tolerance)
                        error(child(field, "inertia"), message(MessageId::PayloadInertiaImpossible, p[0], p[1], p[2]));
                }
            }
        }
        m.scale = readPerJoint(value, path, "scale", false, false, true);
    }

    void readTorque(const Json& entry, const std::string& path, JointTorque& torque) {
        static const Keys kinds = {"constant", "step", "sine", "ramp"};
        static const Keys keysOf[] = {{"value"}, {"value", "at"}, {"amplitude", "frequency", "phase"}, {"slope", "start"}};
        std::optional<std::size_t> kind = 0;  // constant unless said otherwise
        if (const Json* kindValue = member(entry, "kind")) kind = readChoice(*kindValue, child(path, "kind"), kinds);
        if (!kind) {  // the keys cannot be judged without the kind
            checkKeys(entry, path, {"joint", "kind", "value", "at", "amplitude", "frequency", "phase", "slope", "start"});
            return;
        }
        torque.kind = static_cast<TorqueKind>(*kind);
        Keys allowed = {"joint", "kind"};
        allowed.insert(allowed.end(), keysOf[*kind].begin(), keysOf[*kind].end());
        checkKeys(entry, path, allowed, message(MessageId::TorqueOfKind, kinds[*kind]));
        readNumber(entry, path, "value", torque.value);
        readNumber(entry, path, "at", torque.at);
        readNumber(entry, path, "amplitude", torque.amplitude);
        readNumber(entry, path, "frequency", torque.frequency);
        readNumber(entry, path, "phase", torque.phase, Angle::Yes);
        readNumber(entry, path, "slope", torque.slope);
        readNumber(entry, path, "start", torque.start);
    }

    Eigen::VectorXd readVector(const Json* object, const std::string& key, Eigen::Index n) {
        const Json* value = object ? member(*object, key) : nullptr;
        if (!value) return Eigen::VectorXd::Zero(n);
        const std::string field = child("initial", key);
        if (!value->is_array()) {
            error(field, expectedGot(MessageId::WantedNumberArray, *value));
            return Eigen::VectorXd::Zero(n);
        }
        // Any length: whether it matches the joints is validation's call. Positions of
        // revolute joints are angles; velocities are not (no deg/s).
        Eigen::VectorXd vector = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(value->size()));
        for (std::size_t i = 0; i < value->size(); ++i) {
            const Angle angle = key == "q" ? jointAngle(static_cast<int>(i)) : Angle::No;
            if (auto x = number((*value)[i], item(field, i), angle)) vector[static_cast<Eigen::Index>(i)] = *x;
        }
        return vector;
    }

    void readInitial(const Json* initial) {
        if (initial && !checkObject(*initial, "initial", {"q", "qd"})) initial = nullptr;
        const Eigen::Index n = scene_.dof();
        scene_.initial.q = readVector(initial, "q", n);
        scene_.initial.qd = readVector(initial, "qd", n);
    }

    void readSimulation(const Json& simulation) {
        if (!checkObject(simulation, "simulation", {"duration", "integrator", "abs_tol", "rel_tol", "dt", "output_rate"})) return;
        SimulationSettings& s = scene_.simulation;
        readNumber(simulation, "simulation", "duration", s.duration);
        if (const Json* integrator = member(simulation, "integrator")) readText(*integrator, "simulation.integrator", s.integrator);
        readNumber(simulation, "simulation", "abs_tol", s.absTol);
        readNumber(simulation, "simulation", "rel_tol", s.relTol);
        readNumber(simulation, "simulation", "dt", s.dt);
        readNumber(simulation, "simulation", "output_rate", s.outputRate);
    }

    // Named views of the scene (core/io/window_view.hpp): checked here, kept by the
    // document as written, restored by the window. A broken view is a warning: the scene
    // opens whatever its views say (opening that view says what is wrong with it).
    void readViews(const Json& views) {
        if (!views.is_object()) {
            warnings_.push_back({Severity::Warning, "views", expectedGot(MessageId::WantedObject, views)});
            return;
        }
        for (const auto& [name, view] : views.items()) {
            try {
                readWindowView(view, child("views", name));
            } catch (const InputError& e) {
                for (Diagnostic d : e.diagnostics()) {
                    d.severity = Severity::Warning;
                    warnings_.push_back(std::move(d));
                }
            }
        }
    }

    // The entries asked and the answers typed (core/model/exercise.hpp). Entry names are
    // the answer key's to judge (they need the derivation): here only their shape.
    void readExercise(const Json& exercise) {
        if (!checkObject(exercise, "exercise", {"entries", "answers"})) return;
        Exercise& e = scene_.exercise;
        if (const Json* entries = member(exercise, "entries")) {
            if (!entries->is_array()) error("exercise.entries", expectedGot(MessageId::WantedNameArray, *entries));
            else
                for (std::size_t k = 0; k < entries->size(); ++k) {
                    std::string name;
                    readText((*entries)[k], "exercise.entries[" + std::to_string(k) + "]", name);
                    e.entries.push_back(std::move(name));
                }
        }
        if (const Json* answers = member(exercise, "answers")) {
            if (!answers->is_object()) error("exercise.answers", expectedGot(MessageId::WantedObject, *answers));
            else
                for (const auto& [entry, answer] : answers->items()) {
                    std::string text;
                    readText(answer, child("exercise.answers", entry), text);
                    e.answers.emplace_back(entry, std::move(text));
                }
        }
    }

    std::vector<Diagnostic> errors_;
    std::vector<Diagnostic> warnings_;
    ParameterTable parameters_;
    Scene scene_;
};

}  // namespace

Scene readScene(const scene_json::Json& root, std::vector<Diagnostic> duplicates, std::vector<Diagnostic>* warnings) {
    SceneReader reader(std::move(duplicates));
    Scene scene = reader.read(root);
    if (warnings) *warnings = reader.warnings();
    return scene;
}

}  // namespace ll
