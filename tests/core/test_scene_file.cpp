// Scene files: parsing, error messages that name the field, round trips, atomic saving.
#include "test_registry.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "core/io/scene_file.hpp"
#include "core/model/diagnostics.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_scene_file {

using namespace ll;
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

const char* const kFullScene = R"({
  "format": "lagrangelab-scene/1",
  "name": "Planar 2R arm",
  "description": "Two links; the second one slides",
  "source": "Siciliano et al., Robotics, 2009, §7.3.2",
  "parameters": {"l1": 1.0, "l2": 0.8, "m1": 2, "m2": 1.5, "lc1": "l1/2", "lc2": "l2/2"},
  "robot": {
    "convention": "modified",
    "base": {"position": [0.1, 0, "l1/4"], "rpy": [0, 0.3, "pi/4"]},
    "joints": [
      {"type": "revolute", "a": "l1", "alpha": 0, "d": 0, "theta": 0,
       "mass": "m1", "com": ["-l1+lc1", 0, 0],
       "inertia": {"xx": 0.01, "yy": "m1*l1^2/12", "zz": "m1*l1^2/12", "xy": 0, "xz": 0, "yz": 0}},
      {"type": "prismatic", "a": "l2", "alpha": "pi/2", "d": 0.05, "theta": "-pi/2",
       "mass": "m2", "com": ["-lc2", 0.01, -0.02],
       "inertia": {"xx": 0.02, "yy": 0.08, "zz": 0.09, "xy": -0.001, "xz": 0.002, "yz": "-0.003"}}
    ]
  },
  "effects": {
    "gravity": [0, -9.81, 0],
    "springs": [{"joint": 2, "stiffness": 40, "rest": 0.1}],
    "viscous": [{"joint": 1, "coefficient": 0.1}],
    "coulomb": [{"joint": 1, "force": 0.5, "smoothing": 0.001}],
    "torques": [
      {"joint": 2, "kind": "sine", "amplitude": 1, "frequency": 0.5, "phase": "pi/3"},
      {"joint": 1, "kind": "constant", "value": -2},
      {"joint": 2, "kind": "step", "value": 3, "at": 1.5},
      {"joint": 1, "kind": "ramp", "slope": 0.2, "start": 0.5}
    ]
  },
  "initial": {"q": [0.1, "pi/6"], "qd": [0, -0.5]},
  "simulation": {"duration": 10, "integrator": "rk4", "abs_tol": 1e-9, "rel_tol": 1e-7, "dt": 0.002, "output_rate": 50}
})";

// One revolute joint; the smallest valid scene.
const char* const kMinimalScene = R"({
  "format": "lagrangelab-scene/1",
  "name": "Pendulum",
  "robot": {"convention": "standard", "joints": [{"type": "revolute", "a": 1, "mass": 1}]}
})";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The InputError's diagnostics, or nothing when the call did not throw one.
template <class Call>
std::optional<std::vector<Diagnostic>> diagnosticsOf(Call call) {
    try {
        call();
    } catch (const InputError& e) {
        return e.diagnostics();
    }
    return std::nullopt;
}

// "" if some error names `field` and its message holds every part; otherwise what was found.
std::string findError(const std::optional<std::vector<Diagnostic>>& diagnostics, const std::string& field,
                      const std::vector<std::string>& parts) {
    if (!diagnostics) return "no InputError was thrown";
    std::string seen;
    for (const Diagnostic& d : *diagnostics) {
        bool all = d.severity == Severity::Error && d.field == field;
        for (const std::string& part : parts) all = all && contains(d.message.english(), part);
        if (all) return "";
        seen += "\n  " + d.toString();
    }
    return "no error on " + field + " with the expected text; got:" + seen;
}

#define EXPECT_ERROR(call, field, ...)                                                                                              \
    do {                                                                                                                            \
        const std::string problem_ = findError(diagnosticsOf([&] { (void)(call); }), field, std::vector<std::string>{__VA_ARGS__}); \
        QVERIFY2(problem_.empty(), problem_.c_str());                                                                               \
    } while (false)

// The minimal scene with `edit` applied to its JSON.
template <class Edit>
std::string minimalWith(Edit edit) {
    Json json = Json::parse(kMinimalScene);
    edit(json);
    return json.dump();
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream content;
    content << in.rdbuf();
    return content.str();
}

void writeFile(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

// "" if the two scenes hold the same numbers (the base up to baseTolerance) and texts.
std::string differences(const Scene& a, const Scene& b, double baseTolerance = 0.0) {
    std::ostringstream out;
    const auto same = [&](const std::string& what, double x, double y) {
        if (x != y) out << what << ": " << x << " != " << y << "\n";
    };
    if (a.name != b.name || a.description != b.description || a.source != b.source) out << "texts differ\n";
    if (a.parameters != b.parameters) out << "parameters differ\n";
    if (a.expressions != b.expressions) out << "expressions differ\n";
    if (a.robot.convention != b.robot.convention) out << "convention differs\n";
    if ((a.robot.base.matrix() - b.robot.base.matrix()).cwiseAbs().maxCoeff() > baseTolerance) out << "base differs\n";
    if (a.robot.dof() != b.robot.dof()) return out.str() + "joint counts differ\n";
    for (int i = 0; i < a.robot.dof(); ++i) {
        const Joint& x = a.robot.joints[i];
        const Joint& y = b.robot.joints[i];
        if (x.dh.type != y.dh.type) out << jointField(i, "type") << " differs\n";
        same(jointField(i, "a"), x.dh.a, y.dh.a);
        same(jointField(i, "alpha"), x.dh.alpha, y.dh.alpha);
        same(jointField(i, "d"), x.dh.d, y.dh.d);
        same(jointField(i, "theta"), x.dh.theta, y.dh.theta);
        same(jointField(i, "mass"), x.link.mass, y.link.mass);
        if (x.link.com != y.link.com) out << jointField(i, "com") << " differs\n";
        if (x.link.inertia != y.link.inertia) out << jointField(i, "inertia") << " differs\n";
    }
    const Effects& e = a.effects;
    const Effects& f = b.effects;
    if (e.gravity.has_value() != f.gravity.has_value() || (e.gravity && *e.gravity != *f.gravity)) out << "gravity differs\n";
    if (e.springs.size() != f.springs.size() || e.viscous.size() != f.viscous.size() || e.coulomb.size() != f.coulomb.size() ||
        e.torques.size() != f.torques.size())
        return out.str() + "effect counts differ\n";
    for (std::size_t i = 0; i < e.springs.size(); ++i) {
        same("spring joint", e.springs[i].joint, f.springs[i].joint);
        same("spring stiffness", e.springs[i].stiffness, f.springs[i].stiffness);
        same("spring rest", e.springs[i].rest, f.springs[i].rest);
    }
    for (std::size_t i = 0; i < e.viscous.size(); ++i) {
        same("viscous joint", e.viscous[i].joint, f.viscous[i].joint);
        same("viscous coefficient", e.viscous[i].coefficient, f.viscous[i].coefficient);
    }
    for (std::size_t i = 0; i < e.coulomb.size(); ++i) {
        same("coulomb joint", e.coulomb[i].joint, f.coulomb[i].joint);
        same("coulomb force", e.coulomb[i].force, f.coulomb[i].force);
        same("coulomb smoothing", e.coulomb[i].smoothing, f.coulomb[i].smoothing);
    }
    for (std::size_t i = 0; i < e.torques.size(); ++i) {
        const JointTorque& s = e.torques[i];
        const JointTorque& t = f.torques[i];
        if (s.kind != t.kind) out << "torque kind differs\n";
        same("torque joint", s.joint, t.joint);
        for (auto [x, y] : {std::pair{s.value, t.value},
                            {s.at, t.at},
                            {s.amplitude, t.amplitude},
                            {s.frequency, t.frequency},
                            {s.phase, t.phase},
                            {s.slope, t.slope},
                            {s.start, t.start}})
            same("torque", x, y);
    }
    if (a.initial.q != b.initial.q || a.initial.qd != b.initial.qd) out << "initial state differs\n";
    const SimulationSettings& s = a.simulation;
    const SimulationSettings& t = b.simulation;
    if (s.integrator != t.integrator) out << "integrator differs\n";
    same("duration", s.duration, t.duration);
    same("abs_tol", s.absTol, t.absTol);
    same("rel_tol", s.relTol, t.relTol);
    same("dt", s.dt, t.dt);
    same("output_rate", s.outputRate, t.outputRate);
    return out.str();
}

Eigen::Matrix3d rpyRotation(double roll, double pitch, double yaw) {
    return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
            Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

}  // namespace

class TestSceneFile : public QObject {
    Q_OBJECT

private slots:
    void parsesEveryField() {
        const Scene scene = parseScene(kFullScene);
        QCOMPARE(scene.name, std::string("Planar 2R arm"));
        QCOMPARE(scene.robot.name, scene.name);
        QCOMPARE(scene.source, std::string("Siciliano et al., Robotics, 2009, §7.3.2"));
        QCOMPARE(scene.parameters.size(), std::size_t(6));
        QCOMPARE(scene.parameters[4], (std::pair<std::string, double>{"lc1", 0.5}));  // file order kept
        QCOMPARE(scene.parameters[5], (std::pair<std::string, double>{"lc2", 0.4}));
        QCOMPARE(scene.robot.convention, DhConvention::Modified);
        QCOMPARE(scene.robot.dof(), 2);

        const Joint& j1 = scene.robot.joints[0];
        const Joint& j2 = scene.robot.joints[1];
        QCOMPARE(j1.dh.type, JointType::Revolute);
        QCOMPARE(j2.dh.type, JointType::Prismatic);
        QCOMPARE(j1.dh.a, 1.0);
        QCOMPARE(j2.dh.alpha, std::numbers::pi / 2);
        QCOMPARE(j2.dh.theta, -std::numbers::pi / 2);
        QCOMPARE(j2.dh.d, 0.05);
        QCOMPARE(j1.link.mass, 2.0);
        QCOMPARE(j1.link.com, Eigen::Vector3d(-0.5, 0, 0));
        QCOMPARE(j2.link.com, Eigen::Vector3d(-0.4, 0.01, -0.02));
        QCOMPARE(j1.link.inertia(2, 2), 2.0 / 12.0);
        Eigen::Matrix3d I2;
        I2 << 0.02, -0.001, 0.002, -0.001, 0.08, -0.003, 0.002, -0.003, 0.09;
        QCOMPARE(j2.link.inertia, I2);  // symmetric from the six entries

        const Eigen::Vector3d position = scene.robot.base.translation();
        QCOMPARE(position, Eigen::Vector3d(0.1, 0, 0.25));
        QVERIFY((scene.robot.base.linear() - rpyRotation(0, 0.3, std::numbers::pi / 4)).norm() < 1e-15);

        QCOMPARE(scene.initial.q.size(), Eigen::Index(2));
        QCOMPARE(scene.initial.q[0], 0.1);
        QCOMPARE(scene.initial.q[1], std::numbers::pi / 6);  // fuzzy: GiNaC rounds π/6 once, C++ twice
        QCOMPARE(scene.initial.qd, Eigen::Vector2d(0, -0.5).eval());
        const SimulationSettings& s = scene.simulation;
        QCOMPARE(s.duration, 10.0);
        QCOMPARE(s.integrator, std::string("rk4"));
        QCOMPARE(s.absTol, 1e-9);
        QCOMPARE(s.relTol, 1e-7);
        QCOMPARE(s.dt, 0.002);
        QCOMPARE(s.outputRate, 50.0);

        // Every field written as a string is kept as text, under its 1-based path.
        const std::map<std::string, std::string> expected = {
            {"parameters.lc1", "l1/2"},
            {"parameters.lc2", "l2/2"},
            {"robot.base.position[2]", "l1/4"},
            {"robot.base.rpy[2]", "pi/4"},
            {"robot.joints[0].a", "l1"},
            {"robot.joints[0].mass", "m1"},
            {"robot.joints[0].com[0]", "-l1+lc1"},
            {"robot.joints[0].inertia.yy", "m1*l1^2/12"},
            {"robot.joints[0].inertia.zz", "m1*l1^2/12"},
            {"robot.joints[1].a", "l2"},
            {"robot.joints[1].alpha", "pi/2"},
            {"robot.joints[1].theta", "-pi/2"},
            {"robot.joints[1].mass", "m2"},
            {"robot.joints[1].com[0]", "-lc2"},
            {"robot.joints[1].inertia.yz", "-0.003"},
            {"effects.torques[0].phase", "pi/3"},
            {"initial.q[1]", "pi/6"},
        };
        QCOMPARE(scene.expressions, expected);
    }

    void everyEffectWithZeroBasedJoints() {
        const Effects e = parseScene(kFullScene).effects;
        QVERIFY(e.gravity.has_value());
        QCOMPARE(*e.gravity, Eigen::Vector3d(0, -9.81, 0));
        QCOMPARE(e.springs.size(), std::size_t(1));
        QCOMPARE(e.springs[0].joint, 1);
        QCOMPARE(e.springs[0].stiffness, 40.0);
        QCOMPARE(e.springs[0].rest, 0.1);
        QCOMPARE(e.viscous.size(), std::size_t(1));
        QCOMPARE(e.viscous[0].joint, 0);
        QCOMPARE(e.viscous[0].coefficient, 0.1);
        QCOMPARE(e.coulomb.size(), std::size_t(1));
        QCOMPARE(e.coulomb[0].joint, 0);
        QCOMPARE(e.coulomb[0].force, 0.5);
        QCOMPARE(e.coulomb[0].smoothing, 0.001);
        QCOMPARE(e.torques.size(), std::size_t(4));
        const JointTorque& sine = e.torques[0];
        QCOMPARE(sine.joint, 1);
        QCOMPARE(sine.kind, TorqueKind::Sine);
        QCOMPARE(sine.amplitude, 1.0);
        QCOMPARE(sine.frequency, 0.5);
        QCOMPARE(sine.phase, std::numbers::pi / 3);
        QCOMPARE(e.torques[1].joint, 0);
        QCOMPARE(e.torques[1].kind, TorqueKind::Constant);
        QCOMPARE(e.torques[1].value, -2.0);
        QCOMPARE(e.torques[2].kind, TorqueKind::Step);
        QCOMPARE(e.torques[2].value, 3.0);
        QCOMPARE(e.torques[2].at, 1.5);
        QCOMPARE(e.torques[3].kind, TorqueKind::Ramp);
        QCOMPARE(e.torques[3].slope, 0.2);
        QCOMPARE(e.torques[3].start, 0.5);
        QCOMPARE(e.torques[3](1.5), 0.2);
    }

    void defaults() {
        const Scene scene = parseScene(kMinimalScene);
        QVERIFY(!scene.effects.gravity.has_value());  // absent gravity means none
        QVERIFY(scene.effects.springs.empty() && scene.effects.torques.empty() && !scene.effects.hasFriction());
        QCOMPARE(scene.initial.q, Eigen::VectorXd::Zero(1).eval());
        QCOMPARE(scene.initial.qd, Eigen::VectorXd::Zero(1).eval());
        QVERIFY(scene.robot.base.matrix().isIdentity(0.0));
        const Joint& joint = scene.robot.joints[0];
        QCOMPARE(joint.dh.alpha, 0.0);
        QCOMPARE(joint.link.com, Eigen::Vector3d::Zero().eval());
        QCOMPARE(joint.link.inertia, Eigen::Matrix3d::Zero().eval());
        const SimulationSettings defaults;
        QCOMPARE(scene.simulation.duration, defaults.duration);
        QCOMPARE(scene.simulation.integrator, defaults.integrator);
        QCOMPARE(scene.simulation.dt, defaults.dt);
        QVERIFY(scene.expressions.empty() && scene.parameters.empty());

        // An effects object without gravity still declares none; a torque's kind defaults to constant.
        const Scene withTorque = parseScene(minimalWith([](Json& j) {
            j["effects"] = Json::parse(R"({"torques": [{"joint": 1, "value": 2}], "coulomb": [{"joint": 1, "force": 1}]})");
            j["robot"]["joints"][0].erase("type");
        }));
        QVERIFY(!withTorque.effects.gravity.has_value());
        QCOMPARE(withTorque.effects.torques[0].kind, TorqueKind::Constant);
        QCOMPARE(withTorque.effects.torques[0].value, 2.0);
        QCOMPARE(withTorque.effects.coulomb[0].smoothing, CoulombFriction{}.smoothing);
        QCOMPARE(withTorque.robot.joints[0].dh.type, JointType::Revolute);
    }

    void roundTrip() {
        const Scene first = parseScene(kFullScene);
        const std::string text = serializeScene(first);
        const Scene second = parseScene(text);
        const std::string diff = differences(first, second);
        QVERIFY2(diff.empty(), (diff + text).c_str());
        QCOMPARE(serializeScene(second), text);  // a fixed point

        // Expressions are written back as text, effect joints 1-based, 2-space indent.
        QVERIFY(contains(text, "\"lc1\": \"l1/2\""));
        QVERIFY(contains(text, "\"zz\": \"m1*l1^2/12\""));
        QVERIFY(contains(text, "\n  \"robot\": {\n    \"convention\": \"modified\""));
        const Json json = Json::parse(text);
        QCOMPARE(json["effects"]["springs"][0]["joint"].get<int>(), 2);
        QVERIFY(!json["effects"]["torques"][1].contains("amplitude"));  // only the kind's keys
        // Keys in the format's order.
        std::vector<std::string> keys;
        for (const auto& [key, value] : json.items()) keys.push_back(key);
        QCOMPARE(keys, (std::vector<std::string>{"format", "name", "description", "source", "parameters", "robot", "effects", "initial",
                                                 "simulation"}));
    }

    void roundTripOfSceneBuiltInCode() {
        std::mt19937 rng(7);
        Scene scene;
        scene.name = "random";
        scene.robot = test::randomRobot(rng, 5, DhConvention::Standard);
        scene.effects.gravity = Eigen::Vector3d(0.1, -0.2, -9.81);
        scene.effects.torques.push_back({3, TorqueKind::Step, 1.25, 0.75});
        scene.initial.q = test::randomVector(rng, 5, 2.0);
        scene.initial.qd = test::randomVector(rng, 5, 1.0);
        const Scene back = parseScene(serializeScene(scene));
        scene.robot.name = back.robot.name;
        // The file holds the six entries of a symmetric tensor.
        for (Joint& joint : scene.robot.joints) joint.link.inertia = ((joint.link.inertia + joint.link.inertia.transpose()) / 2).eval();
        const std::string diff = differences(scene, back, 1e-14);
        QVERIFY2(diff.empty(), diff.c_str());
    }

    void baseAtGimbalLock() {
        // pitch = -π/2: only roll + yaw is determined; the rotation must survive anyway,
        // even though the yaw was an expression.
        const Scene scene = parseScene(
            minimalWith([](Json& j) { j["robot"]["base"] = Json::parse(R"({"position": [1, 2, 3], "rpy": [0.4, "-pi/2", "pi/4"]})"); }));
        const Scene back = parseScene(serializeScene(scene));
        QVERIFY((back.robot.base.matrix() - scene.robot.base.matrix()).cwiseAbs().maxCoeff() < 1e-14);
        QVERIFY((scene.robot.base.linear() - rpyRotation(0.4, -std::numbers::pi / 2, std::numbers::pi / 4)).norm() < 1e-15);
    }

    void unknownKeys() {
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["effects"] = Json::parse(R"({"viscus": []})"); })), "effects.viscus",
                     "unknown key (expected one of gravity, springs, viscous, coulomb, torques, control)");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["titel"] = "x"; })), "titel", "unknown key", "name");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"]["joint"] = Json::array(); })), "robot.joint", "unknown key", "joints");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"]["joints"][0]["mas"] = 1; })), "robot.joints[0].mas", "unknown key",
                     "mass");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["robot"]["joints"][0]["inertia"] = {{"zx", 1}};
                     })),
                     "robot.joints[0].inertia.zx", "unknown key", "xz");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["effects"] = Json::parse(R"({"springs": [{"joint": 1, "stiffness": 1}, {"joint": 1, "k": 2}]})");
                     })),
                     "effects.springs[1].k", "unknown key", "stiffness");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["simulation"] = {{"step", 0.1}}; })), "simulation.step", "unknown key", "dt");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["robot"]["base"] = {{"orientation", 1}};
                     })),
                     "robot.base.orientation", "unknown key", "rpy");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["initial"] = {{"q0", Json::array({1})}}; })), "initial.q0", "unknown key");
        // All problems are reported at once.
        const auto all = diagnosticsOf([] {
            parseScene(minimalWith([](Json& j) {
                j["a"] = 1;
                j["robot"]["b"] = 1;
                j["robot"]["joints"][0]["c"] = 1;
            }));
        });
        QVERIFY(all.has_value());
        QCOMPARE(all->size(), std::size_t(3));
    }

    void torqueKindWithForeignKey() {
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["effects"] = Json::parse(R"({"torques": [{"joint": 1, "kind": "constant", "value": 1, "amplitude": 2}]})");
                     })),
                     "effects.torques[0].amplitude", "unknown key for a constant torque", "joint, kind, value");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["effects"] = Json::parse(R"({"torques": [{"joint": 1, "kind": "sine", "amplitude": 1, "value": 2}]})");
                     })),
                     "effects.torques[0].value", "unknown key for a sine torque", "amplitude, frequency, phase");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["effects"] = Json::parse(R"({"torques": [{"joint": 1, "kind": "ramp", "slope": 1, "at": 2}]})");
                     })),
                     "effects.torques[0].at", "unknown key for a ramp torque");
        EXPECT_ERROR(parseScene(minimalWith(
                         [](Json& j) { j["effects"] = Json::parse(R"({"torques": [{"joint": 1, "kind": "square", "value": 1}]})"); })),
                     "effects.torques[0].kind", "\"constant\", \"step\", \"sine\" or \"ramp\"", "\"square\"");
    }

    void wrongTypes() {
        Json json = Json::parse(kFullScene);
        json["robot"]["joints"].push_back(json["robot"]["joints"][0]);
        json["robot"]["joints"][2]["mass"] = Json::array({1, 2});
        EXPECT_ERROR(parseScene(json.dump()), "robot.joints[2].mass", "expected a number or an expression, got [1,2]");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"] = "arm"; })), "robot", "expected an object", "a string \"arm\"");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"]["joints"] = Json::object(); })), "robot.joints", "expected an array");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"]["joints"][0] = 3; })), "robot.joints[0]", "expected an object",
                     "the number 3");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["robot"]["joints"][0]["com"] = {1, 2};
                     })),
                     "robot.joints[0].com", "array of 3", "[1,2]");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["robot"]["joints"][0]["com"] = {1, true, 2};
                     })),
                     "robot.joints[0].com[1]", "expected a number or an expression, got true");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["robot"]["joints"][0]["inertia"] = {1, 2, 3};
                     })),
                     "robot.joints[0].inertia", "expected an object", "[1,2,3]");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"]["joints"][0]["alpha"] = nullptr; })), "robot.joints[0].alpha",
                     "got null");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"]["joints"][0]["type"] = "rotary"; })), "robot.joints[0].type",
                     "\"revolute\" or \"prismatic\"", "\"rotary\"");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"]["convention"] = "craig"; })), "robot.convention",
                     "\"standard\" or \"modified\"");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["name"] = 5; })), "name", "expected a string", "the number 5");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["effects"] = {{"gravity", "down"}};
                     })),
                     "effects.gravity", "array of 3", "a string \"down\"");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["effects"] = {{"springs", {{"joint", 1}}}};
                     })),
                     "effects.springs", "expected an array");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["effects"] = "none"; })), "effects", "expected an object");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["parameters"] = {1, 2}; })), "parameters", "expected an object");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["parameters"] = {{"l1", {1}}};
                     })),
                     "parameters.l1", "expected a number or an expression");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["initial"] = {{"q", 0.5}}; })), "initial.q", "expected an array");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["simulation"] = {{"integrator", 4}};
                     })),
                     "simulation.integrator", "expected a string");
        EXPECT_ERROR(parseScene("[1, 2]"), "scene", "expected a JSON object");
        // Joint numbers of effects: integers from 1.
        for (const char* joint : {"\"2\"", "1.5", "0", "-1", "null"})
            EXPECT_ERROR(parseScene(minimalWith([&](Json& j) {
                             j["effects"] = Json::parse(std::string(R"({"viscous": [{"joint": )") + joint + R"(, "coefficient": 1}]})");
                         })),
                         "effects.viscous[0].joint", "from 1");
    }

    void missingRequiredFields() {
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j.erase("format"); })), "format", "missing", "lagrangelab-scene/1");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j.erase("name"); })), "name", "missing");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j.erase("robot"); })), "robot", "missing");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"].erase("convention"); })), "robot.convention", "missing");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"].erase("joints"); })), "robot.joints", "missing");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"]["joints"] = Json::array(); })), "robot.joints", "at least one joint");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"]["joints"][0].erase("mass"); })), "robot.joints[0].mass", "missing");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["effects"] = Json::parse(R"({"springs": [{"stiffness": 1}]})"); })),
                     "effects.springs[0].joint", "missing");
    }

    void otherFormat() {
        // Another format or version: only that is said, nothing about its contents.
        const auto diagnostics = diagnosticsOf([] {
            parseScene(minimalWith([](Json& j) {
                j["format"] = "lagrangelab-scene/2";
                j["colour"] = "red";
            }));
        });
        QVERIFY(diagnostics && diagnostics->size() == 1);
        QCOMPARE(diagnostics->front().field, std::string("format"));
        QVERIFY(contains(diagnostics->front().message.english(), "expected \"lagrangelab-scene/1\", got a string \"lagrangelab-scene/2\""));
    }

    void malformedJson() {
        const std::string text = "{\n  \"format\": \"lagrangelab-scene/1\",\n  \"name\": ,\n}";
        EXPECT_ERROR(parseScene(text), "scene", "JSON syntax error at line 3, column 11", "unexpected ','");
        EXPECT_ERROR(parseScene("{\"format\": \"lagrangelab-scene/1\",\n\"name\": \"x\""), "scene",
                     "JSON syntax error at line 2, column 12");
        EXPECT_ERROR(parseScene(""), "scene", "JSON syntax error at line 1, column 1");
        EXPECT_ERROR(parseScene("{\n\"format\": \"lagrangelab-scene/1\", \"x\": 1e400}"), "scene",
                     "number out of range at line 2, column 39", "1e400");
        const auto first = diagnosticsOf([&] { parseScene(text); });
        QVERIFY(first && first->size() == 1);  // syntax errors stop at the first
    }

    void duplicateKeys() {
        EXPECT_ERROR(parseScene(R"({"format": "lagrangelab-scene/1", "name": "x",
            "parameters": {"l1": 1, "l2": 2, "l1": 3},
            "robot": {"convention": "standard", "joints": [{"mass": 1}, {"mass": 1, "a": 1, "mass": 2}]}})"),
                     "parameters.l1", "given twice");
        EXPECT_ERROR(parseScene(R"({"format": "lagrangelab-scene/1", "name": "x",
            "robot": {"convention": "standard", "joints": [{"mass": 1, "com": [1, 2, 3]}, {"mass": 1, "a": 1, "mass": 2}]}})"),
                     "robot.joints[1].mass", "given twice");
    }

    void expressionErrorsNameTheField() {
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["parameters"] = {{"l1", 1}};
                         j["robot"]["joints"].push_back({{"a", "l3/2"}, {"mass", 1}});
                     })),
                     "robot.joints[1].a", "unknown symbol 'l3' at position 1 in \"l3/2\"");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["robot"]["joints"][0]["d"] = "1/(2-2)"; })), "robot.joints[0].d",
                     "division by zero in \"1/(2-2)\"");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["robot"]["joints"][0]["inertia"] = {{"xz", "1e400"}};
                     })),
                     "robot.joints[0].inertia.xz", "value is not finite (inf) in \"1e400\"");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["effects"] = {{"gravity", {0, "-9.81*", 0}}};
                     })),
                     "effects.gravity[1]", "syntax error", "\"-9.81*\"");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["initial"] = {{"qd", {"oops"}}}; })), "initial.qd[0]", "unknown symbol 'oops'");
        EXPECT_ERROR(parseScene(minimalWith(
                         [](Json& j) { j["effects"] = Json::parse(R"({"coulomb": [{"joint": 1, "force": 1, "smoothing": "v"}]})"); })),
                     "effects.coulomb[0].smoothing", "unknown symbol 'v'");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["robot"]["base"] = {{"rpy", {0, 0, "pi/"}}};
                     })),
                     "robot.base.rpy[2]", "syntax error");
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) { j["simulation"] = {{"dt", "1/0"}}; })), "simulation.dt", "division by zero");
        // Parameters: later ones may use earlier ones only; reserved names refused.
        EXPECT_ERROR(parseScene(minimalWith([](Json& j) {
                         j["parameters"] = {{"a", "b"}, {"b", 1}};
                     })),
                     "parameters.a", "unknown symbol 'b'");
        for (const char* name : {"pi", "q1", "qd2", "t", "sin", "cos"})
            EXPECT_ERROR(parseScene(minimalWith([&](Json& j) {
                             j["parameters"] = {{name, 1}};
                         })),
                         std::string("parameters.") + name, "reserved");
        // Several broken fields: each reported.
        const auto both = diagnosticsOf([] {
            parseScene(minimalWith([](Json& j) {
                j["robot"]["joints"][0]["a"] = "x";
                j["robot"]["joints"][0]["d"] = "y";
            }));
        });
        QVERIFY(both && both->size() == 2);
    }

    void saveIsAtomicAndKeepsBackup() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const fs::path path = fs::path(dir.path().toStdString()) / "arm.json";
        const Scene first = parseScene(kFullScene);
        saveScene(first, path.string());
        QCOMPARE(readFile(path), serializeScene(first));
        QVERIFY(!fs::exists(path.string() + ".bak"));  // there was nothing to keep

        Scene second = first;
        second.name = "Second version";
        second.robot.joints[0].link.mass = 3.5;
        second.expressions.erase("robot.joints[0].mass");
        const std::string before = readFile(path);
        saveScene(second, path.string());
        QCOMPARE(readFile(path), serializeScene(second));
        QCOMPARE(readFile(path.string() + ".bak"), before);
        QCOMPARE(parseScene(readFile(path)).robot.joints[0].link.mass, 3.5);
        // No temporary file is left behind.
        for (const auto& entry : fs::directory_iterator(path.parent_path()))
            QVERIFY2(!contains(entry.path().filename().string(), ".tmp-"), entry.path().c_str());
    }

    void failedSaveLeavesOldFile() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const fs::path root(dir.path().toStdString());
        const Scene scene = parseScene(kFullScene);

        // The directory does not exist (root may write anywhere, so not "not writable").
        const fs::path nowhere = root / "missing" / "arm.json";
        bool threw = false;
        try {
            saveScene(scene, nowhere.string());
        } catch (const std::runtime_error& e) {
            threw = contains(e.what(), nowhere.string());
        }
        QVERIFY2(threw, "saving into a missing directory must throw, naming the path");
        QVERIFY(!fs::exists(root / "missing"));

        // The temporary file cannot be created: the old file stays whole.
        const fs::path path = root / "arm.json";
        writeFile(path, "old content");
        fs::create_directory(path.string() + ".tmp-" + std::to_string(::getpid()));
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, saveScene(scene, path.string()));
        QCOMPARE(readFile(path), std::string("old content"));
        fs::remove(path.string() + ".tmp-" + std::to_string(::getpid()));

        // The backup cannot be written: nothing is replaced either.
        fs::remove(path.string() + ".bak");
        fs::create_directories(path.string() + ".bak/occupied");
        QVERIFY_THROWS_EXCEPTION(std::runtime_error, saveScene(scene, path.string()));
        QCOMPARE(readFile(path), std::string("old content"));
        for (const auto& entry : fs::directory_iterator(root))
            QVERIFY2(!contains(entry.path().filename().string(), ".tmp-"), entry.path().c_str());
    }

    void loadNamesTheFile() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const fs::path root(dir.path().toStdString());

        const fs::path good = root / "good.json";
        writeFile(good, kMinimalScene);
        const LoadedScene loaded = loadScene(good.string());
        QCOMPARE(loaded.scene.name, std::string("Pendulum"));

        const std::string missing = (root / "absent.json").string();
        EXPECT_ERROR(loadScene(missing), missing, "cannot read");

        const fs::path broken = root / "broken.json";
        writeFile(broken, "{\n  \"name\": 1,,\n}");
        EXPECT_ERROR(loadScene(broken.string()), broken.string(), "JSON syntax error at line 2, column 13");

        const fs::path typo = root / "typo.json";
        writeFile(typo, minimalWith([](Json& j) { j["robot"]["joints"][0]["mas"] = 1; }));
        EXPECT_ERROR(loadScene(typo.string()), typo.string() + ": robot.joints[0].mas", "unknown key");

        // Physical errors and warnings come from validation, also naming the file.
        const fs::path negative = root / "negative.json";
        writeFile(negative, minimalWith([](Json& j) { j["robot"]["joints"][0]["mass"] = -1; }));
        EXPECT_ERROR(loadScene(negative.string()), negative.string() + ": robot.joints[0].mass", "negative");

        const fs::path extraQ = root / "extra.json";
        writeFile(extraQ, minimalWith([](Json& j) { j["initial"] = {{"q", {0, 0}}}; }));
        EXPECT_ERROR(loadScene(extraQ.string()), extraQ.string() + ": initial.q", "2 entries");

        const fs::path outOfRange = root / "range.json";
        writeFile(outOfRange, minimalWith([](Json& j) { j["effects"] = Json::parse(R"({"springs": [{"joint": 3, "stiffness": 1}]})"); }));
        EXPECT_ERROR(loadScene(outOfRange.string()), outOfRange.string() + ": effects.springs[0].joint", "joint 3 does not exist");

        const fs::path oddInertia = root / "odd.json";
        writeFile(oddInertia, minimalWith([](Json& j) { j["robot"]["joints"][0]["inertia"] = {{"xx", 0.1}, {"yy", 0.1}, {"zz", 0.5}}; }));
        const LoadedScene odd = loadScene(oddInertia.string());
        QVERIFY(!odd.warnings.empty());
        QCOMPARE(odd.warnings.front().severity, Severity::Warning);
        QVERIFY(contains(odd.warnings.front().field, oddInertia.string() + ": robot.joints[0]"));
    }

    void examples() {
        std::vector<fs::path> files;
        if (fs::exists(LL_EXAMPLES_DIR))
            for (const auto& entry : fs::recursive_directory_iterator(LL_EXAMPLES_DIR))
                if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
        if (files.empty()) QSKIP("no examples/*.json yet");

        const std::vector<std::string> numericFields = {"a",          "alpha",      "d",          "theta",      "mass",
                                                        "com[0]",     "com[1]",     "com[2]",     "inertia.xx", "inertia.yy",
                                                        "inertia.zz", "inertia.xy", "inertia.xz", "inertia.yz"};
        const Json corruptions[] = {"oops", Json::object({{"x", 1}}), nullptr};
        for (const fs::path& file : files) {
            const std::string text = readFile(file);
            Scene scene;
            try {
                scene = parseScene(text);
            } catch (const InputError& e) {
                QFAIL((file.string() + ": " + e.what()).c_str());
            }
            const std::string diff = differences(scene, parseScene(serializeScene(scene)), 1e-14);
            QVERIFY2(diff.empty(), (file.string() + " does not round-trip: " + diff).c_str());

            const Json original = Json::parse(text);
            if (!original.contains("robot")) continue;  // a Lagrangian system: test_lagrangian_derivation
            for (std::size_t i = 0; i < original["robot"]["joints"].size(); ++i)
                for (const std::string& name : numericFields)
                    for (const Json& bad : corruptions) {
                        Json json = original;
                        Json& joint = json["robot"]["joints"][i];
                        if (name.rfind("com[", 0) == 0) {
                            if (!joint.contains("com")) joint["com"] = {0, 0, 0};
                            joint["com"][static_cast<std::size_t>(name[4] - '0')] = bad;
                        } else if (name.rfind("inertia.", 0) == 0) {
                            joint["inertia"][name.substr(8)] = bad;
                        } else {
                            joint[name] = bad;
                        }
                        const std::string field = jointField(static_cast<int>(i), name);
                        const std::string problem = findError(diagnosticsOf([&] { parseScene(json.dump()); }), field, {});
                        QVERIFY2(problem.empty(), (file.string() + ", " + bad.dump() + ": " + problem).c_str());
                    }
        }
    }
};

LL_TEST_APPLESS_MAIN(TestSceneFile)

}  // namespace test_scene_file
#include "test_scene_file.moc"
