// Motor (rotor) inertia on the joints: "armature" (Jm G²) or "motor" {inertia, gear_ratio}.
// The PUMA 560 with Corke's motors gives the Robotics Toolbox's inertia matrix; the
// armature enters b_jj (CRBA and the Jacobian sum), RNEA, the energy and the symbolic
// derivation exactly as the closed form b_jj + Jm G²; bad motor data is refused by field.
#include "test_registry.hpp"

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <random>
#include <sstream>

#include "core/dynamics/energy.hpp"
#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/present/step_formula_text.hpp"
#include "core/simulation/scene_validation.hpp"
#include "core/symbolic/derivation_evaluator.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/robot_derivation.hpp"
#include "derivation_support.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_joint_motor {

using namespace ll;

namespace {

Scene puma() { return loadScene(std::string(LL_EXAMPLES_DIR) + "/puma560.json").scene; }

Eigen::MatrixXd massMatrix(const RobotModel& robot, const Eigen::VectorXd& q) {
    RobotData data(robot);
    forwardKinematics(robot, data, q);
    computeMassMatrix(robot, data);
    return data.B;
}

Eigen::VectorXd pumaNominal() {
    const double pi = std::numbers::pi;
    Eigen::VectorXd q(6);
    q << 0, pi / 4, pi, 0, pi / 4, 0;
    return q;
}

bool mentionsSymbol(const GiNaC::ex& e, const std::string& name) {
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
        if (GiNaC::is_a<GiNaC::symbol>(*it) && GiNaC::ex_to<GiNaC::symbol>(*it).get_name() == name) return true;
    return false;
}

std::string firstError(const std::string& json) {
    try {
        requireValidScene(parseScene(json));
    } catch (const InputError& e) {
        return e.diagnostics().front().field + ": " + e.diagnostics().front().message.english();
    }
    return "";
}

const char* const kPendulum = R"({"format": "lagrangelab-scene/1", "name": "p",
  "robot": {"convention": "standard", "joints": [{"type": "revolute", "a": 1, "mass": 1, %s}]}})";

std::string pendulumWith(const std::string& motor) {
    char text[512];
    std::snprintf(text, sizeof text, kPendulum, motor.c_str());
    return text;
}

}  // namespace

class TestJointMotor : public QObject {
    Q_OBJECT
private slots:
    // Robotics Toolbox (Puma560.py with its motors, Jm·G² on the diagonal) at
    // qn = (0, π/4, π, 0, π/4, 0).
    void pumaWithMotorsGivesTheRoboticsToolboxInertia() {
        const Scene scene = puma();
        const Eigen::MatrixXd B = massMatrix(scene.robot, pumaNominal());
        const double toolbox[] = {3.6594, 4.4137, 0.9378, 0.1925, 0.1713, 0.1941};
        for (int j = 0; j < 6; ++j)
            QVERIFY2(std::abs(B(j, j) - toolbox[j]) < 5e-5, qPrintable(QString("b%1%1 = %2").arg(j + 1).arg(B(j, j), 0, 'f', 6)));
        const double armature[] = {0.7840, 2.3248, 0.5769, 0.1908, 0.1707, 0.1941};
        for (int j = 0; j < 6; ++j) QVERIFY(std::abs(scene.robot.joints[j].motor.armature() - armature[j]) < 5e-5);
    }

    // Motors switched off: the rigid-body PUMA of Corke & Armstrong at q = 0.
    void pumaWithoutMotorsKeepsTheRigidBodyInertia() {
        Scene scene = puma();
        for (Joint& joint : scene.robot.joints) joint.motor = JointMotor{};
        const Eigen::MatrixXd B = massMatrix(scene.robot, Eigen::VectorXd::Zero(6));
        const double rigid[] = {3.1771, 2.1318, 0.3618, 0.00164, 0.00064, 0.00004};
        for (int j = 0; j < 6; ++j) QVERIFY(std::abs(B(j, j) - rigid[j]) < 1e-4);
    }

    // b_jj + Jm G² and nothing else, in both B algorithms; RNEA adds Jm G² q̈_j; the
    // kinetic energy ½ Jm G² q̇_j²; forward dynamics inverts it.
    void armatureIsTheClosedFormEverywhere() {
        std::mt19937 rng(17);
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            const RobotModel bare = test::randomRobot(rng, 6, convention);
            RobotModel motors = bare;
            Eigen::VectorXd armature(6);
            for (int j = 0; j < 6; ++j) {
                motors.joints[j].motor = {0.5e-4 * (j + 1), j % 2 ? 80.0 : -60.0, true};
                armature[j] = motors.joints[j].motor.armature();
            }
            RobotData a(bare), b(motors);
            const Eigen::VectorXd q = test::randomVector(rng, 6, 2.0), qd = test::randomVector(rng, 6, 2.0),
                                  qdd = test::randomVector(rng, 6, 2.0);
            forwardKinematics(bare, a, q);
            forwardKinematics(motors, b, q);
            computeMassMatrix(bare, a);
            computeMassMatrix(motors, b);
            const Eigen::MatrixXd expected = a.B + Eigen::MatrixXd(armature.asDiagonal());
            QVERIFY(test::scaledError(b.B, expected) < 1e-13);
            QVERIFY(test::scaledError(massMatrixFromJacobians(motors, b), expected) < 1e-12);
            QVERIFY(std::abs(kineticEnergy(b, qd) - kineticEnergy(a, qd) - 0.5 * qd.dot(armature.cwiseProduct(qd))) < 1e-12);
            const Effects gravity{Eigen::Vector3d(0, 0, -9.81), {}, {}, {}, {}};
            const Eigen::VectorXd tauBare = inverseDynamics(bare, a, gravity, q, qd, qdd);
            const Eigen::VectorXd tauMotors = inverseDynamics(motors, b, gravity, q, qd, qdd);
            QVERIFY(test::scaledError(tauMotors, Eigen::VectorXd(tauBare + armature.cwiseProduct(qdd))) < 1e-12);
            const Eigen::VectorXd back = forwardDynamics(motors, b, gravity, q, qd, tauMotors);
            QVERIFY(test::scaledError(back, qdd) < 1e-9);
        }
    }

    // The derivation shows the armature as its own term: b11 = … + Jm1 G1², and the
    // difference to the motor-free derivation is exactly that term.
    void derivationShowsTheArmatureTerms() {
        auto lock = symbolic::lockGinac();
        Scene scene = puma();
        scene.robot.joints.resize(3);
        scene.initial.q.conservativeResize(3);
        scene.initial.qd.conservativeResize(3);
        const symbolic::Derivation withMotors = symbolic::deriveRobot(scene);
        Scene bare = scene;
        for (Joint& joint : bare.robot.joints) joint.motor = JointMotor{};
        const symbolic::Derivation without = symbolic::deriveRobot(bare);
        for (int j = 0; j < 3; ++j) {
            const std::string k = std::to_string(j + 1);
            const GiNaC::ex term =
                (test::inSymbolsOf(withMotors, without, withMotors.B(j, j)) - without.B(j, j).subs(without.trigToFunctions)).expand();
            QVERIFY2(mentionsSymbol(term, "Jm" + k) && mentionsSymbol(term, "G" + k), qPrintable(QString::fromStdString(k)));
            std::ostringstream shown;
            shown << term;
            QVERIFY2(GiNaC::is_a<GiNaC::mul>(term), shown.str().c_str());  // one product Jm_k G_k², not a number merged in
            for (int i = 0; i < 3; ++i)
                if (i != j)
                    QVERIFY((test::inSymbolsOf(withMotors, without, withMotors.B(i, j)) - without.B(i, j).subs(without.trigToFunctions))
                                .expand()
                                .is_zero());
        }
        bool explained = false;
        for (const symbolic::DerivationStep& step : withMotors.steps)
            if (step.number == 7) {
                const std::string text = present::formulaText(step.formula, {present::Language::English, present::Notation::Notes, true});
                explained = text.find("Jm_j G_j^2 to b_jj") != std::string::npos && text.find("Jm1 = 0.0002") != std::string::npos;
            }
        QVERIFY(explained);
        // Its value is the numeric core's, in every mode.
        for (symbolic::ParameterMode mode :
             {symbolic::ParameterMode::Parametric, symbolic::ParameterMode::Numeric, symbolic::ParameterMode::Textbook}) {
            symbolic::DerivationOptions options;
            options.mode = mode;
            const symbolic::Derivation d = symbolic::deriveRobot(scene, options);
            const Eigen::VectorXd q = pumaNominal().head(3);
            const Eigen::MatrixXd B = symbolic::DerivationEvaluator(d).value(d.B, q, Eigen::VectorXd::Zero(3), 0.0);
            QVERIFY(test::scaledError(B, massMatrix(scene.robot, q)) < 1e-10);
        }
    }

    void armatureAndMotorFields() {
        const Scene a = parseScene(pendulumWith(R"("armature": 0.25)"));
        QCOMPARE(a.robot.joints[0].motor.armature(), 0.25);
        QVERIFY(!a.robot.joints[0].motor.fromMotor);
        const Scene m = parseScene(pendulumWith(R"("motor": {"inertia": 1e-4, "gear_ratio": -50})"));
        QVERIFY(std::abs(m.robot.joints[0].motor.armature() - 0.25) < 1e-15);
        QVERIFY(m.robot.joints[0].motor.fromMotor);
        // B of the pendulum: m a² + Jm G² (the COM at the frame origin, a = 1 from the axis)
        QVERIFY(std::abs(massMatrix(m.robot, Eigen::VectorXd::Zero(1))(0, 0) - 1.25) < 1e-12);
    }

    void badMotorDataIsRefusedByField_data() {
        QTest::addColumn<QString>("motor");
        QTest::addColumn<QString>("field");
        QTest::addColumn<QString>("says");
        QTest::newRow("negative armature") << R"("armature": -0.1)"
                                           << "robot.joints[0].armature"
                                           << "negative";
        QTest::newRow("negative rotor") << R"("motor": {"inertia": -1e-4, "gear_ratio": 50})"
                                        << "robot.joints[0].motor.inertia"
                                        << "negative";
        QTest::newRow("zero gear") << R"("motor": {"inertia": 1e-4, "gear_ratio": 0})"
                                   << "robot.joints[0].motor.gear_ratio"
                                   << "gear ratio is 0";
        QTest::newRow("both") << R"("armature": 0.1, "motor": {"inertia": 1e-4, "gear_ratio": 50})"
                              << "robot.joints[0].motor"
                              << "not both";
        QTest::newRow("no gear") << R"("motor": {"inertia": 1e-4})"
                                 << "robot.joints[0].motor.gear_ratio"
                                 << "required";
        QTest::newRow("unknown key") << R"("motor": {"inertia": 1e-4, "gear": 50})"
                                     << "robot.joints[0].motor.gear"
                                     << "unknown key";
        QTest::newRow("armature in degrees") << R"("armature": "2°")"
                                             << "robot.joints[0].armature"
                                             << "U+00B0";
    }
    void badMotorDataIsRefusedByField() {
        QFETCH(QString, motor);
        QFETCH(QString, field);
        QFETCH(QString, says);
        const std::string error = firstError(pendulumWith(motor.toStdString()));
        QVERIFY2(error.rfind(field.toStdString() + ": ", 0) == 0 && error.find(says.toStdString()) != std::string::npos, error.c_str());
    }

    // Saving keeps what was typed: the motor as a motor, an armature expression as text.
    void roundTripKeepsTheMotorAsTyped() {
        const std::string json = R"({"format": "lagrangelab-scene/1", "name": "p", "parameters": {"Ja": 0.02},
          "robot": {"convention": "standard", "joints": [
            {"type": "revolute", "a": 1, "mass": 1, "motor": {"inertia": 2e-4, "gear_ratio": -62.6111}},
            {"type": "revolute", "a": 1, "mass": 1, "armature": "Ja*2"},
            {"type": "revolute", "a": 1, "mass": 1}]}})";
        const Scene first = parseScene(json);
        const std::string text = serializeScene(first);
        QVERIFY2(text.find(R"("motor": {"inertia": 0.0002, "gear_ratio": -62.6111})") != std::string::npos, text.c_str());
        QVERIFY2(text.find(R"("armature": "Ja*2")") != std::string::npos, text.c_str());
        QCOMPARE(std::count(text.begin(), text.end(), '\n') > 0, true);
        const Scene second = parseScene(text);
        for (int j = 0; j < 3; ++j) {
            QCOMPARE(second.robot.joints[j].motor.armature(), first.robot.joints[j].motor.armature());
            QCOMPARE(second.robot.joints[j].motor.fromMotor, first.robot.joints[j].motor.fromMotor);
        }
        QVERIFY(text.find("armature\": 0") == std::string::npos);  // no motor, no key
        QCOMPARE(serializeScene(second), text);
    }
};

LL_TEST_APPLESS_MAIN(TestJointMotor)

}  // namespace test_joint_motor
#include "test_joint_motor.moc"
