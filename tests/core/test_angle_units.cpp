// Angles as people copy them: "90°", "90 deg", "90*deg" and "pi/2" are the same angle
// (the same B); a bare 90 in an angle field loads as radians with a warning naming the
// field; degrees in a length are refused by field; look-alike characters and bytes that
// are not UTF-8 are named by code point, and every message is valid UTF-8.
#include "test_registry.hpp"

#include <filesystem>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "core/dynamics/mass_matrix.hpp"
#include "core/symbolic/angle_units.hpp"
#include "core/symbolic/expression.hpp"
#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/utf8_text.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/robot_derivation.hpp"
#include "derivation_support.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_angle_units {

using namespace ll;
using Json = nlohmann::ordered_json;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The PUMA 560 of examples/ with joint 1's twist and joint 2's initial angle as given.
Json pumaWith(const Json& alpha, const Json& q2) {
    std::ifstream in(std::string(LL_EXAMPLES_DIR) + "/puma560.json");
    Json json = Json::parse(in);
    json["robot"]["joints"][0]["alpha"] = alpha;
    json["initial"]["q"][1] = q2;
    return json;
}

Eigen::MatrixXd massMatrixAtInitial(const Scene& scene) {
    RobotData data(scene.robot);
    forwardKinematics(scene.robot, data, scene.initial.q);
    computeMassMatrix(scene.robot, data);
    return data.B;
}

LoadedScene loadJson(const Json& json) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / "ll_angle_units_scene.json";
    {
        std::ofstream out(path);
        out << json.dump();
    }
    struct Remove {
        std::filesystem::path p;
        ~Remove() { std::filesystem::remove(p); }
    } remove{path};
    return loadScene(path.string());
}

// The first error message `call` throws, "" if none.
template <class Call>
std::string errorOf(Call call) {
    try {
        call();
    } catch (const InputError& e) {
        return e.diagnostics().front().field + ": " + e.diagnostics().front().message.english();
    }
    return "";
}

}  // namespace

class TestAngleUnits : public QObject {
    Q_OBJECT
private slots:
    void degreesAndRadiansGiveTheSameB() {
        const Scene radians = parseScene(pumaWith("pi/2", "pi/4").dump());
        const Eigen::MatrixXd B = massMatrixAtInitial(radians);
        for (const char* alpha : {"90°", "90 deg", "90deg", "90*deg", "(45 + 45)°"}) {
            const Scene scene = parseScene(pumaWith(alpha, "45°").dump());
            QCOMPARE(scene.robot.joints[0].dh.alpha, radians.robot.joints[0].dh.alpha);
            QCOMPARE(scene.initial.q[1], radians.initial.q[1]);
            QVERIFY2((massMatrixAtInitial(scene) - B).cwiseAbs().maxCoeff() == 0.0, alpha);
        }
        QVERIFY(contains(errorOf([] { parseScene(pumaWith("100 grad", 0).dump()); }), "robot.joints[0].alpha: syntax error"));
    }

    // The derivation keeps 90° exact: the same B as pi/2, term for term (the motors'
    // symbols, one set per derivation, replaced by their values).
    void derivationReadsDegreesExactly() {
        auto lock = symbolic::lockGinac();
        Json degrees = pumaWith("90°", "45 deg"), radians = pumaWith("pi/2", "pi/4");
        for (Json* json : {&degrees, &radians}) {
            while ((*json)["robot"]["joints"].size() > 3) (*json)["robot"]["joints"].erase(3);  // the arm, for speed
            (*json)["initial"] = Json::object();
        }
        const symbolic::Derivation a = symbolic::deriveRobot(parseScene(degrees.dump()));
        const symbolic::Derivation b = symbolic::deriveRobot(parseScene(radians.dump()));
        for (unsigned i = 0; i < 3; ++i)
            for (unsigned j = 0; j < 3; ++j)
                QVERIFY(
                    (test::inSymbolsOf(a, b, a.B(i, j)).subs(a.parameterValues) - b.B(i, j).subs(b.trigToFunctions).subs(b.parameterValues))
                        .expand()
                        .is_zero());
    }

    void bareNumberOverTwoPiWarnsNamingTheField() {
        const LoadedScene loaded = loadJson(pumaWith(90, 0.5));
        QCOMPARE(loaded.scene.robot.joints[0].dh.alpha, 90.0);  // loaded as given
        std::string warning;
        for (const Diagnostic& d : loaded.warnings)
            if (contains(d.field, "robot.joints[0].alpha")) warning = d.message.english();
        QVERIFY2(contains(warning, "alpha 90 rad — did you mean 90°? write 90° or pi/2"), warning.c_str());
        // An expression, degrees or a small number do not warn; neither does the second
        // joint's initial angle of 0.5 rad.
        for (const Json& alpha : {Json("4*pi"), Json("90°"), Json(1.5708)}) {
            const LoadedScene quiet = loadJson(pumaWith(alpha, 0.5));
            for (const Diagnostic& d : quiet.warnings) QVERIFY2(!contains(d.message.english(), "did you mean"), d.toString().c_str());
        }
        const LoadedScene q = loadJson(pumaWith("pi/2", 45));
        bool warnedQ = false;
        for (const Diagnostic& d : q.warnings) warnedQ |= contains(d.field, "initial.q[1]") && contains(d.message.english(), "pi/4");
        QVERIFY(warnedQ);
    }

    void readingAsDegrees() {
        const std::pair<double, const char*> cases[] = {{90, "pi/2"},  {-90, "-pi/2"}, {180, "pi"},       {270, "3*pi/2"},  {45, "pi/4"},
                                                        {360, "2*pi"}, {30, "pi/6"},   {37, "37*pi/180"}, {-135, "-3*pi/4"}};
        for (const auto& [value, radians] : cases) QCOMPARE(readAsDegrees(value).radians, std::string(radians));
        QCOMPARE(readAsDegrees(37.5).degrees, std::string("37.5°"));
    }

    void degreesOnlyInAngleFields() {
        const std::string length = errorOf([] {
            Json json = pumaWith("pi/2", 0);
            json["robot"]["joints"][1]["a"] = "431.8°";
            parseScene(json.dump());
        });
        QVERIFY2(contains(length, "robot.joints[1].a: '°' (U+00B0) at position 6") && contains(length, "angle fields"), length.c_str());
        const std::string prismatic = errorOf([] {
            parseScene(R"({"format": "lagrangelab-scene/1", "name": "slider", "robot": {"convention": "standard",
              "joints": [{"type": "prismatic", "mass": 1}]}, "initial": {"q": ["10 deg"]}})");
        });
        QVERIFY2(contains(prismatic, "initial.q[0]: 'deg' at position 4"), prismatic.c_str());
        // A revolute spring's rest angle and a torque's phase are angles.
        const Scene scene = parseScene(R"({"format": "lagrangelab-scene/1", "name": "p", "robot": {"convention": "standard",
          "joints": [{"type": "revolute", "a": 1, "mass": 1}]},
          "effects": {"springs": [{"joint": 1, "stiffness": 2, "rest": "30°"}],
                      "torques": [{"joint": 1, "kind": "sine", "amplitude": 1, "frequency": 1, "phase": "-90 deg"}]}})");
        QVERIFY(std::abs(scene.effects.springs[0].rest - std::numbers::pi / 6) < 1e-15);
        QVERIFY(std::abs(scene.effects.torques[0].phase + std::numbers::pi / 2) < 1e-15);
    }

    // A parameter called deg is the user's: it wins over the unit, and ° still works.
    void aParameterNamedDegWins() {
        const Scene scene = parseScene(R"({"format": "lagrangelab-scene/1", "name": "p", "parameters": {"deg": 0.5},
          "robot": {"convention": "standard", "joints": [{"type": "revolute", "a": 1, "mass": 1, "alpha": "deg", "theta": "30°"}]}})");
        QCOMPARE(scene.robot.joints[0].dh.alpha, 0.5);
        QVERIFY(std::abs(scene.robot.joints[0].dh.theta - std::numbers::pi / 6) < 1e-15);
    }

    void unexpectedCharactersAreNamedByCodePoint_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("says");
        QTest::newRow("ordinal, not degree") << QString::fromUtf8("90º")
                                             << QString::fromUtf8("'º' (U+00BA) at position 3") + " in \"" + QString::fromUtf8("90º") +
                                                    "\": it is not the degree sign";
        QTest::newRow("ring above") << QString::fromUtf8("90˚") << QString::fromUtf8("'˚' (U+02DA) at position 3");
        QTest::newRow("minus sign") << QString::fromUtf8("−pi/2")
                                    << QString::fromUtf8("'−' (U+2212) at position 1") + " in \"" + QString::fromUtf8("−pi/2") +
                                           "\": write - (the ASCII minus)";
        QTest::newRow("times") << QString::fromUtf8("2×pi") << QString::fromUtf8("'×' (U+00D7) at position 2");
        QTest::newRow("pi letter") << QString::fromUtf8("π/2")
                                   << QString::fromUtf8("'π' (U+03C0) at position 1") + " in \"" + QString::fromUtf8("π/2") +
                                          "\": write pi";
        QTest::newRow("no-break space") << QString::fromUtf8("90\u00a0deg") << "(U+00A0) at position 3";
        QTest::newRow("emoji") << QString::fromUtf8("1 + \U0001F600") << QString::fromUtf8("'\U0001F600' (U+1F600) at position 5");
        // Positions after a degree sign count characters, as the user sees them.
        QTest::newRow("after a degree sign") << QString::fromUtf8("90° + zz") << "unknown symbol 'zz' at position 7";
        QTest::newRow("syntax after degree") << QString::fromUtf8("90° + )") << "at position 7";
    }
    void unexpectedCharactersAreNamedByCodePoint() {
        QFETCH(QString, text);
        QFETCH(QString, says);
        ParameterTable table;
        const std::string error = errorOf([&] { table.evaluate("robot.joints[0].alpha", text.toStdString()); });
        QVERIFY2(contains(error, says.toStdString()), error.c_str());
        QVERIFY(isValidUtf8(error));
    }

    // Bytes that are not UTF-8, in an expression or in a file: named, never cut.
    void bytesThatAreNotUtf8() {
        ParameterTable table;
        const std::string expression = errorOf([&] { table.evaluate("robot.joints[0].alpha", "90\xC2"); });
        QVERIFY2(contains(expression, "byte 0xC2 at position 3 in \"90\\xC2\": not UTF-8"), expression.c_str());
        QVERIFY(isValidUtf8(expression));
        std::string file = pumaWith("pi/2", 0).dump();
        file.replace(file.find("\"pi/2\""), 6, "\"90\xC2\xB0\xB0\"");
        const std::string whole = errorOf([&] { parseScene(file); });
        QVERIFY2(contains(whole, "scene: the file is not UTF-8: byte 0xB0 at line 1, column"), whole.c_str());
        QVERIFY(isValidUtf8(whole));
    }

    // What was typed is what is saved.
    void roundTripKeepsTheDegrees() {
        Json json = pumaWith("90°", "45 deg");
        json["robot"]["base"]["rpy"] = {0, 0, "-90°"};
        const Scene first = parseScene(json.dump());
        const std::string text = serializeScene(first);
        QVERIFY2(contains(text, "\"alpha\": \"90°\"") && contains(text, "\"45 deg\"") && contains(text, "\"-90°\""), text.c_str());
        const Scene second = parseScene(text);
        QCOMPARE(second.robot.joints[0].dh.alpha, first.robot.joints[0].dh.alpha);
        QCOMPARE(serializeScene(second), text);
    }

    void preparedTextMapsBackToCharacters() {
        const PreparedExpression p = prepareExpression("f", "90° + 1 deg", false);
        QCOMPARE(p.text, std::string("90*deg_unit_  + 1 *deg"));
        QCOMPARE(p.unitPosition, std::size_t(3));
        QCOMPARE(p.unit, std::string("°"));
        QCOMPARE(p.position.size(), p.text.size() + 1);
        QCOMPARE(p.at(p.text.rfind("deg") + 1), std::string(" at position 9"));
    }
};

LL_TEST_APPLESS_MAIN(TestAngleUnits)

}  // namespace test_angle_units
#include "test_angle_units.moc"
