#include "core/io/scene_file.hpp"

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
#include <nlohmann/json.hpp>

#include "core/io/atomic_file.hpp"
#include "core/symbolic/expression.hpp"
#include "core/symbolic/lagrangian_fields.hpp"
#include "core/simulation/scene_validation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/angle_units.hpp"
#include "core/model/utf8_text.hpp"
#include "core/model/usable_number.hpp"

namespace ll {

namespace {

// ordered_json keeps the file's key order: parameters may use the ones before them.
using Json = nlohmann::ordered_json;
using Keys = std::vector<std::string>;

const char* const kFormat = "lagrangelab-scene/1";
// Field of problems with the whole text (JSON syntax) in parseScene; loadScene names the file instead.
const char* const kDocument = "scene";

std::string child(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

std::string item(const std::string& path, std::size_t index0) {
    return path + "[" + std::to_string(index0) + "]";
}

std::string joined(const Keys& keys) {
    std::string text;
    for (const std::string& key : keys) text += (text.empty() ? "" : ", ") + key;
    return text;
}

// The offending value as the student wrote it, with its type where the text does not show it.
std::string describe(const Json& value) {
    std::string text = value.dump();
    if (text.size() > 60) text = text.substr(0, 57) + "...";
    if (value.is_string()) return "a string " + text;
    if (value.is_number()) return "the number " + text;
    return text;
}

Eigen::Matrix3d rotationFromRpy(const Eigen::Vector3d& rpy) {
    return (Eigen::AngleAxisd(rpy[2], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy[1], Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(rpy[0], Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

// Inverse of rotationFromRpy; at pitch = ±π/2 only roll - yaw (or roll + yaw) is
// determined, and yaw = 0 is chosen.
Eigen::Vector3d rpyFromRotation(const Eigen::Matrix3d& R) {
    const double cosPitch = std::hypot(R(0, 0), R(1, 0));
    const double pitch = std::atan2(-R(2, 0), cosPitch);
    if (cosPitch < 1e-12) return {std::atan2(-R(1, 2), R(1, 1)), pitch, 0.0};
    return {std::atan2(R(2, 1), R(2, 2)), pitch, std::atan2(R(1, 0), R(0, 0))};
}

// ---------------------------------------------------------------------------
// Reading

// nlohmann keeps the last of two equal keys without a word; the parser callback sees
// every key, so it reports the duplicates (with their paths) instead.
class DuplicateKeyFinder {
public:
    explicit DuplicateKeyFinder(std::vector<Diagnostic>& out) : out_(out) {}

    bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed) {
        switch (event) {
            case Json::parse_event_t::object_start:
            case Json::parse_event_t::array_start:
                levels_.push_back({event == Json::parse_event_t::object_start, enterElement(), {}, {}, 0});
                break;
            case Json::parse_event_t::object_end:
            case Json::parse_event_t::array_end:
                levels_.pop_back();
                break;
            case Json::parse_event_t::key: {
                Level& level = levels_.back();
                level.key = parsed.get<std::string>();
                if (!level.keys.insert(level.key).second)
                    out_.push_back({Severity::Error, child(level.path, level.key),
                                    "key given twice (only one value may be given)"});
                break;
            }
            case Json::parse_event_t::value:
                enterElement();
                break;
        }
        return true;
    }

private:
    struct Level {
        bool object;
        std::string path;
        std::set<std::string> keys;
        std::string key;        // object: the key whose value comes next
        std::size_t count = 0;  // array: elements so far
    };

    std::string enterElement() {
        if (levels_.empty()) return "";
        Level& level = levels_.back();
        return level.object ? child(level.path, level.key) : item(level.path, level.count++);
    }

    std::vector<Diagnostic>& out_;
    std::vector<Level> levels_;
};

// Columns count characters, as an editor shows them.
std::pair<std::size_t, std::size_t> lineAndColumn(const std::string& text, std::size_t offset) {
    offset = std::min(offset, text.size());
    std::size_t line = 1, lineStart = 0;
    for (std::size_t i = 0; i < offset; ++i)
        if (text[i] == '\n') ++line, lineStart = i + 1;
    return {line, characterCount(std::string_view(text).substr(lineStart), offset - lineStart) + 1};
}

std::string at(const std::string& text, std::size_t offset) {
    const auto [line, column] = lineAndColumn(text, offset);
    return "at line " + std::to_string(line) + ", column " + std::to_string(column);
}

// Throws InputError naming kDocument: the text is not UTF-8 (named by the first byte
// that is not) or no JSON object.
Json parseJson(const std::string& text, std::vector<Diagnostic>& duplicates) {
    for (std::size_t i = 0; i < text.size();) {
        const Utf8Char c = decodeUtf8(text, i);
        if (!c.valid)
            throw InputError(kDocument, "the file is not UTF-8: " + describeCharacter(c, text, i) + " " + at(text, i) +
                                            " starts no character (save the file as UTF-8)");
        i += c.bytes;
    }
    Json root;
    try {
        root = Json::parse(text, DuplicateKeyFinder(duplicates));
    } catch (const Json::parse_error& e) {
        // what() is "[json.exception.parse_error.101] parse error at line L, column C:
        // syntax error while parsing value - <reason>"; keep <reason>, place it ourselves
        // (e.byte is 1-based: the character that could not be read).
        std::string reason = e.what();
        const std::size_t dash = reason.find(" - ");
        if (dash != std::string::npos) reason = reason.substr(dash + 3);
        // "last read: '<everything since the token began>'" can be a whole description:
        // keep its last 40 bytes (whole characters), so the message stays one short line.
        const std::size_t read = reason.find("last read: '");
        const std::size_t quoted = read == std::string::npos ? read : read + 12;
        if (quoted != std::string::npos && reason.size() > quoted + 60) {
            std::size_t from = reason.size() - 41;
            while (from < reason.size() && (static_cast<unsigned char>(reason[from]) & 0xC0) == 0x80) ++from;
            reason = reason.substr(0, quoted) + "..." + reason.substr(from);
        }
        throw InputError(kDocument, "JSON syntax error " + at(text, e.byte > 0 ? e.byte - 1 : 0) + ": " + reason);
    } catch (const Json::out_of_range& e) {
        // "number overflow parsing '1e400'" has no position; find the number.
        std::string what = e.what();
        const std::size_t open = what.find('\''), close = what.rfind('\'');
        if (open != std::string::npos && close > open) {
            const std::string number = what.substr(open + 1, close - open - 1);
            const std::size_t offset = text.find(number);
            throw InputError(kDocument, "JSON number out of range " + at(text, offset == std::string::npos ? 0 : offset) +
                                            ": " + number + " (the largest number is about 1.8e308)");
        }
        throw InputError(kDocument, std::string("JSON error: ") + e.what());
    } catch (const Json::exception& e) {
        throw InputError(kDocument, std::string("JSON error: ") + e.what());
    }
    if (!root.is_object()) throw InputError(kDocument, "expected a JSON object {...} at the top level, got " + describe(root));
    return root;
}

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
                  {"format", "name", "description", "source", "parameters", "robot", "lagrangian", "effects", "initial",
                   "simulation"});
        const std::size_t errorsBefore = errors_.size();
        if (const Json* parameters = member(root, "parameters")) readParameters(*parameters);
        // Every later field may use the parameters: a broken one would echo everywhere.
        if (errors_.size() > errorsBefore) throwIfErrors();

        if (const Json* name = required(root, "", "name", "the scene's title")) readText(*name, "name", scene_.name);
        if (const Json* description = member(root, "description"))
            readText(*description, "description", scene_.description);
        if (const Json* source = member(root, "source")) readText(*source, "source", scene_.source);
        scene_.robot.name = scene_.name;
        // Exactly one of a robot (DH table) and a Lagrangian typed by hand.
        const Json* robot = member(root, "robot");
        const Json* lagrangian = member(root, "lagrangian");
        if (robot && lagrangian)
            error("lagrangian", "a scene has either \"robot\" or \"lagrangian\", not both");
        else if (robot)
            readRobot(*robot);
        else if (lagrangian)
            readLagrangian(*lagrangian);
        else
            error("robot", "required field is missing (the DH table and links; or \"lagrangian\" for a system "
                           "given by its coordinates, E_kin and E_pot)");
        if (const Json* effects = member(root, "effects")) readEffects(*effects);
        readInitial(member(root, "initial"));
        if (const Json* simulation = member(root, "simulation")) readSimulation(*simulation);
        throwIfErrors();
        return std::move(scene_);
    }

private:
    void error(const std::string& field, const std::string& message) {
        errors_.push_back({Severity::Error, field, message});
    }

    [[noreturn]] void fail(const std::string& field, const std::string& message) {
        error(field, message);
        throw InputError(errors_);
    }

    void throwIfErrors() const {
        if (!errors_.empty()) throw InputError(errors_);
    }

    static const Json* member(const Json& object, const std::string& key) {
        const auto found = object.find(key);
        return found == object.end() ? nullptr : &*found;
    }

    const Json* required(const Json& object, const std::string& path, const std::string& key, const std::string& what) {
        const Json* value = member(object, key);
        if (!value) error(child(path, key), "required field is missing (" + what + ")");
        return value;
    }

    // An object holding only `allowed` keys; false (and an error) when it is no object.
    bool checkObject(const Json& value, const std::string& path, const Keys& allowed) {
        if (!value.is_object()) {
            error(path, "expected an object {...}, got " + describe(value));
            return false;
        }
        checkKeys(value, path, allowed);
        return true;
    }

    void checkKeys(const Json& object, const std::string& path, const Keys& allowed,
                   const std::string& context = "") {
        for (const auto& [key, value] : object.items())
            if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())  // "" is named as typed: ""
                error(child(path, key.empty() ? "\"\"" : key), "unknown key" + context + " (expected one of " + joined(allowed) + ")");
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
                const double number =
                    parameters_.evaluate(path, text, angle == Angle::No ? AngleUnits::Refused : AngleUnits::Allowed);
                scene_.expressions[path] = text;
                if (angle == Angle::Yes && isPlainNumber(text)) warnIfDegrees(path, number);
                return number;
            } catch (const InputError& e) {
                errors_.insert(errors_.end(), e.diagnostics().begin(), e.diagnostics().end());
                return std::nullopt;
            }
        }
        error(path, "expected a number or an expression, got " + describe(value));
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
        warnings_.push_back({Severity::Warning, path,
                             name + " " + number.str() + " rad — did you mean " + reading.degrees + "? write " +
                                 reading.degrees + " or " + reading.radians + " (loaded as " + number.str() + " rad)"});
    }

    // Degrees are for a revolute joint's angles; a prismatic joint's q is a length. A
    // Lagrangian's coordinates may be either.
    Angle jointAngle(int joint) const {
        if (scene_.lagrangian) return Angle::Maybe;
        if (joint < 0 || joint >= scene_.robot.dof()) return Angle::Maybe;  // validation names the joint
        return scene_.robot.joints[static_cast<std::size_t>(joint)].dh.type == JointType::Revolute ? Angle::Yes : Angle::No;
    }

    void readNumber(const Json& object, const std::string& path, const std::string& key, double& target,
                    Angle angle = Angle::No) {
        if (const Json* value = member(object, key))
            if (auto n = number(*value, child(path, key), angle)) target = *n;
    }

    void readText(const Json& value, const std::string& path, std::string& target) {
        if (value.is_string())
            target = value.get<std::string>();
        else
            error(path, "expected a string \"...\", got " + describe(value));
    }

    // A string that must be one of `choices`; the index of the match.
    std::optional<std::size_t> readChoice(const Json& value, const std::string& path, const Keys& choices) {
        if (value.is_string()) {
            const auto found = std::find(choices.begin(), choices.end(), value.get<std::string>());
            if (found != choices.end()) return static_cast<std::size_t>(found - choices.begin());
        }
        std::string expected;
        for (std::size_t i = 0; i < choices.size(); ++i)
            expected += (i == 0 ? "\"" : i + 1 == choices.size() ? " or \"" : ", \"") + choices[i] + "\"";
        error(path, "expected " + expected + ", got " + describe(value));
        return std::nullopt;
    }

    void readVector3(const Json& object, const std::string& path, const std::string& key, Eigen::Vector3d& target,
                     Angle angle = Angle::No) {
        const Json* value = member(object, key);
        if (!value) return;
        const std::string field = child(path, key);
        if (!value->is_array() || value->size() != 3) {
            error(field, "expected an array of 3 numbers or expressions [x, y, z], got " + describe(*value));
            return;
        }
        for (std::size_t i = 0; i < 3; ++i)
            if (auto n = number((*value)[i], item(field, i), angle)) target[static_cast<Eigen::Index>(i)] = *n;
    }

    void readFormat(const Json& root) {
        const Json* format = member(root, "format");
        if (!format) {
            error("format", std::string("required field is missing (expected \"") + kFormat + "\")");
            return;
        }
        // Another format (or version) would make every later message misleading.
        if (!format->is_string() || format->get<std::string>() != kFormat)
            fail("format", std::string("expected \"") + kFormat + "\", got " + describe(*format));
    }

    void readParameters(const Json& parameters) {
        if (!parameters.is_object()) {
            error("parameters", "expected an object {\"name\": value, ...}, got " + describe(parameters));
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
                    error(field, "expected a number or an expression, got " + describe(value));
                    continue;
                }
                scene_.parameters.emplace_back(name, parameters_.value(name));
            } catch (const InputError& e) {
                errors_.insert(errors_.end(), e.diagnostics().begin(), e.diagnostics().end());
            }
        }
    }

    void readRobot(const Json& robot) {
        if (!checkObject(robot, "robot", {"convention", "base", "joints"})) return;
        if (const Json* convention = required(robot, "robot", "convention", "\"standard\" or \"modified\" DH"))
            if (auto choice = readChoice(*convention, "robot.convention", {"standard", "modified"}))
                scene_.robot.convention = *choice == 0 ? DhConvention::Standard : DhConvention::Modified;
        if (const Json* base = member(robot, "base")) readBase(*base);
        const Json* joints = required(robot, "robot", "joints", "one entry per joint, base to tip");
        if (!joints) return;
        if (!joints->is_array() || joints->empty()) {
            error("robot.joints", "expected an array of at least one joint [{...}, ...], got " + describe(*joints));
            return;
        }
        scene_.robot.joints.resize(joints->size());
        for (std::size_t i = 0; i < joints->size(); ++i)
            readJoint((*joints)[i], jointField(static_cast<int>(i), ""), scene_.robot.joints[i]);
    }

    // The "lagrangian" block (core/model/lagrangian_spec.hpp): every expression is parsed
    // here, so its errors name the field and the position when the file is read.
    void readLagrangian(const Json& value) {
        const std::string path = "lagrangian";
        if (!checkObject(value, path, {"coordinates", "kinetic", "potential", "forces", "bodies"})) return;
        LagrangianSpec spec;
        if (const Json* coordinates =
                required(value, path, "coordinates", "the generalized coordinates by name, e.g. [\"theta1\", \"theta2\"]")) {
            if (!coordinates->is_array() || coordinates->empty())
                error("lagrangian.coordinates", "expected an array of names [\"x\", ...], got " + describe(*coordinates));
            else
                for (std::size_t i = 0; i < coordinates->size(); ++i) {
                    const Json& name = (*coordinates)[i];
                    if (name.is_string())
                        spec.coordinates.push_back(name.get<std::string>());
                    else
                        error(item("lagrangian.coordinates", i), "expected a name \"...\", got " + describe(name));
                }
        }
        const std::size_t errorsBefore = errors_.size();
        for (const Diagnostic& d : checkCoordinateNames(spec.coordinates, parameters_)) errors_.push_back(d);
        // Without usable names every expression would echo the problem.
        const bool namesOk = errors_.size() == errorsBefore && !spec.coordinates.empty();
        const LagrangianSymbols symbols = lagrangianSymbols(spec.coordinates);
        const auto expression = [&](const Json& text, const std::string& field, LagrangianField kind) -> std::string {
            if (!text.is_string() && !text.is_number()) {
                error(field, "expected an expression \"...\" or a number, got " + describe(text));
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
        if (const Json* kinetic = required(value, path, "kinetic", "E_kin in the coordinates and velocities <name>_dot"))
            spec.kinetic = expression(*kinetic, "lagrangian.kinetic", LagrangianField::Kinetic);
        if (const Json* potential = member(value, "potential"))
            spec.potential = expression(*potential, "lagrangian.potential", LagrangianField::Potential);
        if (const Json* forces = member(value, "forces")) {
            if (!forces->is_array())
                error("lagrangian.forces", "expected an array of expressions, one per coordinate, got " + describe(*forces));
            else
                for (std::size_t i = 0; i < forces->size(); ++i)
                    spec.forces.push_back(expression((*forces)[i], item("lagrangian.forces", i), LagrangianField::Force));
        }
        if (const Json* bodies = member(value, "bodies")) {
            if (!bodies->is_array())
                error("lagrangian.bodies", "expected an array of objects [{...}, ...], got " + describe(*bodies));
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
            error(path, "expected an object {...}, got " + describe(body));
            return;
        }
        static const Keys shapes = {"box", "sphere", "cylinder", "rod"};
        std::optional<std::size_t> shape;
        if (const Json* value = required(body, path, "shape", "\"box\", \"sphere\", \"cylinder\" or \"rod\""))
            shape = readChoice(*value, child(path, "shape"), shapes);
        if (shape) target.shape = static_cast<BodyShape>(*shape);
        const bool rod = shape && target.shape == BodyShape::Rod;
        if (shape)
            checkKeys(body, path,
                      rod ? Keys{"name", "shape", "size", "position", "end", "color"}
                          : Keys{"name", "shape", "size", "position", "angle", "axis", "color"},
                      " for a " + shapes[*shape]);
        if (const Json* name = member(body, "name")) readText(*name, child(path, "name"), target.name);
        if (const Json* color = member(body, "color")) {
            readText(*color, child(path, "color"), target.color);
            static const std::regex hex("#[0-9A-Fa-f]{6}");
            if (color->is_string() && !std::regex_match(target.color, hex))
                error(child(path, "color"), "expected a colour \"#rrggbb\", got " + describe(*color));
        }
        if (const Json* size = required(body, path, "size", "the shape's dimensions")) {
            const std::string field = child(path, "size");
            if (!size->is_array()) {
                error(field, "expected an array of numbers or expressions [...], got " + describe(*size));
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
                error(field, "expected an array of 3 expressions of the coordinates [x, y, z], got " + describe(*value));
                return;
            }
            for (std::size_t k = 0; k < 3; ++k) out[k] = expression((*value)[k], item(field, k), LagrangianField::Pose);
        };
        point("position", target.position);
        if (rod) point("end", target.end);
        if (const Json* angle = member(body, "angle"))
            target.angle = expression(*angle, child(path, "angle"), LagrangianField::Pose);
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
        if (!checkObject(joint, path, {"type", "a", "alpha", "d", "theta", "mass", "com", "inertia", "armature", "motor"}))
            return;
        if (const Json* type = member(joint, "type"))
            if (auto choice = readChoice(*type, child(path, "type"), {"revolute", "prismatic"}))
                target.dh.type = *choice == 0 ? JointType::Revolute : JointType::Prismatic;
        readNumber(joint, path, "a", target.dh.a);
        readNumber(joint, path, "alpha", target.dh.alpha, Angle::Yes);
        readNumber(joint, path, "d", target.dh.d);
        // θ is the revolute joint's offset angle; a prismatic joint's θ is a constant angle too.
        readNumber(joint, path, "theta", target.dh.theta, Angle::Yes);
        if (required(joint, path, "mass", "the link's mass in kg; 0 for a massless link"))
            readNumber(joint, path, "mass", target.link.mass);
        readVector3(joint, path, "com", target.link.com);
        if (const Json* inertia = member(joint, "inertia")) readInertia(*inertia, child(path, "inertia"), target.link);
        readMotor(joint, path, target.motor);
    }

    // "armature": Jm G² as one number, or "motor": {"inertia": Jm, "gear_ratio": G}.
    void readMotor(const Json& joint, const std::string& path, JointMotor& motor) {
        const Json* armature = member(joint, "armature");
        const Json* rotor = member(joint, "motor");
        if (armature && rotor) {
            error(child(path, "motor"), "give either \"armature\" (Jm*G^2, the reflected inertia) or \"motor\" "
                                        "{\"inertia\": Jm, \"gear_ratio\": G}, not both");
            return;
        }
        if (armature) readNumber(joint, path, "armature", motor.inertia);
        if (!rotor) return;
        const std::string field = child(path, "motor");
        if (!checkObject(*rotor, field, {"inertia", "gear_ratio"})) return;
        motor.fromMotor = true;
        if (required(*rotor, field, "inertia", "the rotor's inertia Jm in kg m²"))
            readNumber(*rotor, field, "inertia", motor.inertia);
        if (required(*rotor, field, "gear_ratio", "G, motor turns per joint turn"))
            readNumber(*rotor, field, "gear_ratio", motor.gearRatio);
    }

    void readInertia(const Json& inertia, const std::string& path, LinkInertia& link) {
        if (!checkObject(inertia, path, {"xx", "yy", "zz", "xy", "xz", "yz"})) return;
        const std::pair<const char*, std::pair<int, int>> entries[] = {
            {"xx", {0, 0}}, {"yy", {1, 1}}, {"zz", {2, 2}}, {"xy", {0, 1}}, {"xz", {0, 2}}, {"yz", {1, 2}}};
        for (const auto& [key, index] : entries) {
            double value = 0.0;
            readNumber(inertia, path, key, value);
            link.inertia(index.first, index.second) = link.inertia(index.second, index.first) = value;
        }
    }

    // Effects number joints from 1; the structs from 0.
    std::optional<int> readJointNumber(const Json& entry, const std::string& path) {
        const Json* value = required(entry, path, "joint", "the joint's number, from 1");
        if (!value) return std::nullopt;
        const std::string field = child(path, "joint");
        const bool integral = value->is_number() && std::floor(value->get<double>()) == value->get<double>();
        if (!integral || std::abs(value->get<double>()) > 1e6) {
            error(field, "expected a joint number (an integer from 1), got " + describe(*value));
            return std::nullopt;
        }
        const int joint = static_cast<int>(value->get<double>());
        if (joint < 1) {
            error(field, "joints are numbered from 1 as in the textbook, got " + value->dump());
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
            error(path, "expected an array of objects [{...}, ...], got " + describe(*list));
            return;
        }
        for (std::size_t i = 0; i < list->size(); ++i) {
            const Json& entry = (*list)[i];
            const std::string field = item(path, i);
            if (!entry.is_object()) {
                error(field, "expected an object {...}, got " + describe(entry));
                continue;
            }
            Entry parsed;
            if (auto joint = readJointNumber(entry, field)) parsed.joint = *joint;
            readEntry(entry, field, parsed);
            target.push_back(parsed);
        }
    }

    void readEffects(const Json& effects) {
        if (!checkObject(effects, "effects", {"gravity", "springs", "viscous", "coulomb", "torques"})) return;
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
        readList<ViscousFriction>(effects, "viscous", e.viscous,
                                  [this](const Json& j, const std::string& p, ViscousFriction& v) {
                                      checkKeys(j, p, {"joint", "coefficient"});
                                      readNumber(j, p, "coefficient", v.coefficient);
                                  });
        readList<CoulombFriction>(effects, "coulomb", e.coulomb,
                                  [this](const Json& j, const std::string& p, CoulombFriction& c) {
                                      checkKeys(j, p, {"joint", "force", "smoothing", "model"});
                                      readNumber(j, p, "force", c.force);
                                      readNumber(j, p, "smoothing", c.smoothing);
                                      if (const Json* model = member(j, "model"))
                                          if (auto choice = readChoice(*model, child(p, "model"), {"tanh", "stick"}))
                                              c.model = static_cast<CoulombModel>(*choice);
                                  });
        readList<JointTorque>(effects, "torques", e.torques,
                              [this](const Json& j, const std::string& p, JointTorque& t) { readTorque(j, p, t); });
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
        checkKeys(entry, path, allowed, " for a " + kinds[*kind] + " torque");
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
            error(field, "expected an array of numbers or expressions [...], got " + describe(*value));
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
        if (!checkObject(simulation, "simulation",
                         {"duration", "integrator", "abs_tol", "rel_tol", "dt", "output_rate"}))
            return;
        SimulationSettings& s = scene_.simulation;
        readNumber(simulation, "simulation", "duration", s.duration);
        if (const Json* integrator = member(simulation, "integrator"))
            readText(*integrator, "simulation.integrator", s.integrator);
        readNumber(simulation, "simulation", "abs_tol", s.absTol);
        readNumber(simulation, "simulation", "rel_tol", s.relTol);
        readNumber(simulation, "simulation", "dt", s.dt);
        readNumber(simulation, "simulation", "output_rate", s.outputRate);
    }

    std::vector<Diagnostic> errors_;
    std::vector<Diagnostic> warnings_;
    ParameterTable parameters_;
    Scene scene_;
};

// ---------------------------------------------------------------------------
// Writing

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
        if (scene_.lagrangian)
            root["lagrangian"] = lagrangian(*scene_.lagrangian);
        else
            root["robot"] = robot();
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
        return root;
    }

private:
    // The expression text if the field came from one; integers without ".0".
    Json number(const std::string& path, double value) const {
        if (const auto text = scene_.expressions.find(path); text != scene_.expressions.end()) return text->second;
        if (std::isfinite(value) && std::floor(value) == value && std::abs(value) < 9.0e15)
            return static_cast<std::int64_t>(value);
        return value;
    }

    template <class Vector>
    Json vector(const std::string& path, const Vector& values) const {
        Json array = Json::array();
        for (Eigen::Index i = 0; i < values.size(); ++i)
            array.push_back(number(item(path, static_cast<std::size_t>(i)), values[i]));
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
            entry["size"] = vector(child(path, "size"), Eigen::Map<const Eigen::VectorXd>(
                                                            body.size.data(), static_cast<Eigen::Index>(body.size.size())));
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
            fields(entry, entries[i], [&](const std::string& name, double value) {
                entry[name] = number(child(path, name), value);
            });
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
        list(out, "viscous", e.viscous,
             [](Json&, const ViscousFriction& v, auto put) { put("coefficient", v.coefficient); });
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
        return out;
    }

    const Scene& scene_;
};

// nlohmann's dump(2) gives every array element its own line; [x, y, z] and small
// entries such as {"joint": 1, "coefficient": 0.1} read better on one.
void writePretty(std::string& out, const Json& value, std::size_t indent) {
    if (!value.is_structured()) {
        out += value.dump();
        return;
    }
    const bool object = value.is_object();
    const std::string open = object ? "{" : "[", close = object ? "}" : "]";
    if (value.empty()) {
        out += open + close;
        return;
    }
    bool flat = true;
    for (const auto& element : value) flat = flat && !element.is_structured();
    if (flat) {
        std::string line = open;
        for (auto element = value.begin(); element != value.end(); ++element) {
            if (element != value.begin()) line += ", ";
            if (object) line += Json(element.key()).dump() + ": ";
            line += element->dump();
        }
        line += close;
        if (indent + line.size() <= 90) {
            out += line;
            return;
        }
    }
    out += open;
    for (auto element = value.begin(); element != value.end(); ++element) {
        out += (element == value.begin() ? "\n" : ",\n") + std::string(indent + 2, ' ');
        if (object) out += Json(element.key()).dump() + ": ";
        writePretty(out, *element, indent + 2);
    }
    out += "\n" + std::string(indent, ' ') + close;
}

// ---------------------------------------------------------------------------
// Files

std::optional<std::string> readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream content;
    content << in.rdbuf();
    if (in.bad()) return std::nullopt;
    return content.str();
}

// loadScene's diagnostics name the file: "<path>: <field>".
std::vector<Diagnostic> inFile(std::vector<Diagnostic> diagnostics, const std::string& path) {
    for (Diagnostic& d : diagnostics) d.field = path + ": " + d.field;
    return diagnostics;
}

}  // namespace

Scene parseScene(const std::string& jsonText) {
    const auto lock = symbolic::lockGinac();  // expressions are parsed with GiNaC
    std::vector<Diagnostic> duplicates;
    const Json root = parseJson(jsonText, duplicates);
    return SceneReader(std::move(duplicates)).read(root);
}

LoadedScene loadScene(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw InputError(path, "is a directory, not a scene file");
    const std::optional<std::string> text = readWholeFile(path);
    if (!text) throw InputError(path, std::string("cannot read the file: ") + std::strerror(errno));
    std::vector<Diagnostic> duplicates;
    Json root;
    try {
        root = parseJson(*text, duplicates);
    } catch (const InputError& e) {  // about the whole text: the file is the field
        throw InputError(path, e.diagnostics().front().message);
    }
    try {
        const auto lock = symbolic::lockGinac();  // expressions are parsed with GiNaC
        LoadedScene loaded;
        SceneReader reader(std::move(duplicates));
        loaded.scene = reader.read(root);
        loaded.warnings = reader.warnings();
        const std::vector<Diagnostic> validation = requireValidScene(loaded.scene);
        loaded.warnings.insert(loaded.warnings.end(), validation.begin(), validation.end());
        loaded.warnings = inFile(std::move(loaded.warnings), path);
        return loaded;
    } catch (const InputError& e) {
        throw InputError(inFile(e.diagnostics(), path));
    }
}

std::string serializeScene(const Scene& scene) {
    const auto lock = symbolic::lockGinac();  // expressions are re-checked with GiNaC
    std::string text;
    writePretty(text, SceneWriter(scene).write(), 0);
    return text + "\n";
}

void saveScene(const Scene& scene, const std::string& path) {
    saveFileAtomically(path, serializeScene(scene), Backup::Keep);
}

}  // namespace ll
