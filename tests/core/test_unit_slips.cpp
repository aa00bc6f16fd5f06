// Data typed in the wrong unit: a COM in mm, a in mm, a mass in g, an inertia in g·mm²
// warn naming the field and the likely slip, and still load. A B(q) that cannot be
// factored says which kind it is: a joint that truly moves nothing (the published
// UR5 table without inertias: add armature) or an ill-conditioned B (a COM typed
// 1e6 too large: the slip is named, not "joint 4 moves no mass").
#include "test_registry.hpp"

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/io/scene_file.hpp"
#include "core/model/unit_slips.hpp"
#include "core/simulation/scene_validation.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_unit_slips {

using namespace ll;
using Json = nlohmann::ordered_json;

namespace {

Json exampleJson(const std::string& name) {
    std::ifstream in(std::string(LL_EXAMPLES_DIR) + "/" + name);
    return Json::parse(in);
}

// The warnings of loading `json` (as a file, so the reader's warnings are in), or the
// errors it was refused with.
struct Outcome {
    bool loaded = false;
    std::vector<Diagnostic> diagnostics;
};

Outcome load(const Json& json) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "ll_unit_slips_scene.json";
    {
        std::ofstream out(path);
        out << json.dump();
    }
    Outcome outcome;
    try {
        outcome.diagnostics = loadScene(path.string()).warnings;
        outcome.loaded = true;
    } catch (const InputError& e) {
        outcome.diagnostics = e.diagnostics();
    }
    std::filesystem::remove(path);
    return outcome;
}

// The message of a diagnostic of `severity` whose field ends with `field` and which
// says `part`, or "".
std::string messageAt(const Outcome& o, Severity severity, const std::string& field, const std::string& part = "") {
    for (const Diagnostic& d : o.diagnostics)
        if (d.severity == severity && d.field.size() >= field.size() &&
            d.field.compare(d.field.size() - field.size(), field.size(), field) == 0 &&
            (d.message.english() + "\n" + d.hint.english()).find(part) != std::string::npos)
            return d.message.english() + (d.hint.english().empty() ? "" : "\nhint: " + d.hint.english());
    return "";
}

std::string all(const Outcome& o) {
    std::string text;
    for (const Diagnostic& d : o.diagnostics) text += "\n  " + d.toString();
    return text;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

class TestUnitSlips : public QObject {
    Q_OBJECT
private slots:
    void slipsWarnNamingTheFieldAndLoad_data() {
        QTest::addColumn<QString>("pointer");
        QTest::addColumn<double>("value");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("says");
        QTest::newRow("COM in mm") << "/robot/joints/1/com/0" << -363.8 << "robot.joints[1].com[0]"
                                   << "-363.8 mm = -0.3638 m";
        QTest::newRow("a in mm") << "/robot/joints/1/a" << 431.8 << "robot.joints[1].a"
                                 << "431.8 mm = 0.4318 m";
        QTest::newRow("mass in g") << "/robot/joints/1/mass" << 17400.0 << "robot.joints[1].mass"
                                   << "17400 g = 17.4 kg";
        QTest::newRow("inertia in g mm²") << "/robot/joints/1/inertia/yy" << 0.524e9 << "robot.joints[1].inertia"
                                          << "g mm²";
    }
    void slipsWarnNamingTheFieldAndLoad() {
        QFETCH(QString, pointer);
        QFETCH(double, value);
        QFETCH(QString, field);
        QFETCH(QString, says);
        Json json = exampleJson("puma560.json");
        json[Json::json_pointer(pointer.toStdString())] = value;
        const Outcome o = load(json);
        QVERIFY2(o.loaded, all(o).c_str());
        const std::string message = messageAt(o, Severity::Warning, field.toStdString(), says.toStdString());
        QVERIFY2(!message.empty(), (field.toStdString() + all(o)).c_str());
    }

    // The published examples raise none, except the Stanford arm's link 3 COM (6.447 m
    // on an arm of about 0.8 m reach), which its description flags as a likely slip.
    void examplesRaiseNoSlipWarning() {
        for (const auto& entry : std::filesystem::directory_iterator(LL_EXAMPLES_DIR)) {
            if (entry.path().extension() != ".json") continue;
            const LoadedScene loaded = loadScene(entry.path().string());
            std::vector<std::string> slips;
            for (const Diagnostic& d : unitSlipWarnings(loaded.scene.robot)) slips.push_back(d.field);
            const std::string name = entry.path().filename().string();
            if (name == "stanford_arm.json") QCOMPARE(slips, std::vector<std::string>{"robot.joints[2].com[2]"});
            else QVERIFY2(slips.empty(), (name + ": " + (slips.empty() ? "" : slips.front())).c_str());
        }
    }

    // A COM typed a million times too large: B spans 1e16, the wrist joint's pivot is
    // lost in rounding. The error says ill-conditioned, gives the condition number and
    // names the slip; it does not blame a joint for moving nothing.
    void illConditionedBNamesTheSlip() {
        Json json = exampleJson("puma560.json");
        for (Json& joint : json["robot"]["joints"]) joint.erase("motor");
        json["robot"]["joints"][1]["com"][0] = -3638;  // 3.638 m typed in mm: in range, but B loses joint 6
        const Outcome o = load(json);
        QVERIFY(!o.loaded);
        std::string error, first;
        for (const Diagnostic& d : o.diagnostics)
            if (d.severity == Severity::Error) {
                error = d.text();
                first = d.toString().substr(0, d.toString().find('\n'));
                // the one value that explains it is the field named, on a first line of at most 200 bytes
                QVERIFY2(d.field.ends_with(": robot.joints[1].com[0]"), d.field.c_str());
            }
        QVERIFY2(contains(first, "ill-conditioned") && contains(first, "condition number") && first.size() <= 200, first.c_str());
        QVERIFY2(contains(error, "\nhint: ") && contains(error, "unit slip"), error.c_str());
        QVERIFY2(!contains(error, "moves no mass"), error.c_str());

        // Beyond any physical length it is named as such, before B is looked at.
        json["robot"]["joints"][1]["com"][0] = -363800;
        const Outcome absurd = load(json);
        QVERIFY(!absurd.loaded);
        bool named = false;
        for (const Diagnostic& d : absurd.diagnostics) {
            QVERIFY2(!contains(d.message.english(), "ill-conditioned"), d.message.english().c_str());
            named =
                named || (d.field.ends_with("robot.joints[1].com[0]") && contains(d.message.english(), "absurdly large length -363800 m"));
        }
        QVERIFY(named);
    }

    // The published UR5 table (Corke's UR5.py: DH, masses and COMs, no inertia tensors):
    // link 6's mass sits on joint 6's axis, so joint 6 moves nothing. Refused, saying to
    // add the motor's armature; with an (illustrative) armature on every joint it loads
    // and simulates.
    void publishedUr5LoadsOnceArmatureIsGiven() {
        Json json = exampleJson("ur5.json");
        const double com[6][3] = {{0, -0.02561, 0.00193}, {0.2125, 0, 0.11336},  {0.15, 0, 0.0265},
                                  {0, -0.0018, 0.01634},  {0, -0.0018, 0.01634}, {0, 0, -0.001159}};
        const double mass[6] = {3.7, 8.393, 2.33, 1.219, 1.219, 0.1897};
        for (std::size_t j = 0; j < 6; ++j) {
            Json& joint = json["robot"]["joints"][j];
            joint.erase("inertia");
            joint["mass"] = mass[j];
            joint["com"] = {com[j][0], com[j][1], com[j][2]};
        }
        const Outcome refused = load(json);
        QVERIFY(!refused.loaded);
        const std::string error = messageAt(refused, Severity::Error, "robot.joints[5]");
        QVERIFY2(contains(error, "joint 6 moves no mass") && contains(error, "armature"), all(refused).c_str());

        for (Json& joint : json["robot"]["joints"]) joint["armature"] = 0.1;
        const Outcome accepted = load(json);
        QVERIFY2(accepted.loaded, all(accepted).c_str());
        Scene scene = parseScene(json.dump());
        scene.simulation.duration = 0.5;
        const SimulationResult r = simulate(scene, scene.simulation);
        QVERIFY2(r.status == SimulationStatus::Completed, r.message.english().c_str());
        QVERIFY(r.stats.maxRelEnergyError < 1e-6);
    }
};

LL_TEST_APPLESS_MAIN(TestUnitSlips)

}  // namespace test_unit_slips
#include "test_unit_slips.moc"
