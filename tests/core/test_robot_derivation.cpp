// The symbolic derivation against the numeric dynamics (an independent route: CRBA,
// spatial Christoffel derivatives, RNEA) on every example, in every parameter mode,
// and Ḃ − 2C skew-symmetric symbolically.
#include "test_registry.hpp"

#include <filesystem>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/energy.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/simulation/generalized_forces.hpp"
#include "core/symbolic/derivation_evaluator.hpp"
#include "core/present/expression_printer.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/robot_derivation.hpp"
#include "core/symbolic/trig_context.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_robot_derivation {

using namespace ll;
using namespace ll::symbolic;
using namespace ll::present;

namespace {
double relativeError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    return (a - b).cwiseAbs().maxCoeff() / std::max(1e-300, std::max(1.0, b.cwiseAbs().maxCoeff()));
}

Scene exampleScene(const std::string& name) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + name).scene; }

// The example's file with every occurrence of each `from` replaced by its `to`.
Scene renamedExample(const std::string& name, const std::vector<std::pair<std::string, std::string>>& renames) {
    QFile file(QString::fromStdString(std::string(LL_EXAMPLES_DIR) + "/" + name));
    if (!file.open(QIODevice::ReadOnly)) qFatal("cannot read %s", name.c_str());
    std::string text = file.readAll().toStdString();
    for (const auto& [from, to] : renames)
        for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
            text.replace(at, from.size(), to);
    return parseScene(text);
}

// The symbol of the parameter `name` in a derivation kept in parameters.
GiNaC::symbol parameterSymbol(const Derivation& d, const std::string& name) {
    for (const GiNaC::ex& relation : d.parameterValues)
        if (GiNaC::is_a<GiNaC::symbol>(relation.lhs()) && GiNaC::ex_to<GiNaC::symbol>(relation.lhs()).get_name() == name)
            return GiNaC::ex_to<GiNaC::symbol>(relation.lhs());
    qFatal("no parameter %s in the derivation", name.c_str());
}

// Compares B, C, g, Q, E_kin, E_pot of the derivation with core/dynamics at random states.
void compareWithNumeric(const Scene& scene, const Derivation& d, int states, double tolerance) {
    const RobotModel& robot = scene.robot;
    const int n = robot.dof();
    RobotData data(robot);
    const DerivationEvaluator eval(d);
    std::mt19937 rng(99);
    for (int k = 0; k < states; ++k) {
        const Eigen::VectorXd q = test::randomVector(rng, n, 2.0), qd = test::randomVector(rng, n, 2.0);
        const double t = 0.37 + k;
        forwardKinematics(robot, data, q);
        computeMassMatrix(robot, data);
        computeCoriolisMatrix(robot, data, qd);
        computePotentialGradient(robot, data, scene.effects, q);
        Eigen::VectorXd Q(n);
        computeGeneralizedForces(scene.effects, t, qd, Q);
        const auto check = [&](const char* what, const Eigen::MatrixXd& symbolic, const Eigen::MatrixXd& numeric) {
            const double e = relativeError(symbolic, numeric);
            QVERIFY2(e < tolerance, qPrintable(QString("%1 %2: relative error %3").arg(QString::fromStdString(scene.name), what).arg(e)));
        };
        check("B", eval.value(d.B, q, qd, t), data.B);
        check("C", eval.value(d.C, q, qd, t), data.C);
        check("g", eval.value(d.g, q, qd, t), data.g);
        check("Q", eval.value(d.Q, q, qd, t), Q);
        check("E_kin", Eigen::Matrix<double, 1, 1>(eval.value(d.Ekin, q, qd, t)), Eigen::Matrix<double, 1, 1>(kineticEnergy(data, qd)));
        check("E_pot", Eigen::Matrix<double, 1, 1>(eval.value(d.Epot, q, qd, t)),
              Eigen::Matrix<double, 1, 1>(potentialEnergy(robot, data, scene.effects, q)));
    }
}
}  // namespace

class TestRobotDerivation : public QObject {
    Q_OBJECT
private slots:
    void agreesWithNumericDynamicsOnEveryExample_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("mode");
        for (const auto& entry : std::filesystem::directory_iterator(LL_EXAMPLES_DIR)) {
            if (entry.path().extension() != ".json") continue;
            const std::string name = entry.path().filename().string();
            for (int mode : {int(ParameterMode::Parametric), int(ParameterMode::Numeric), int(ParameterMode::Textbook)})
                QTest::newRow((name + "/" + std::to_string(mode)).c_str()) << QString::fromStdString(name) << mode;
        }
    }
    void agreesWithNumericDynamicsOnEveryExample() {
        QFETCH(QString, file);
        QFETCH(int, mode);
        const Scene scene = exampleScene(file.toStdString());
        if (scene.lagrangian) QSKIP("a Lagrangian system, not a robot (tests/test_lagrangian_derivation.cpp)");
        DerivationOptions options;
        options.mode = ParameterMode(mode);
        const Derivation d = deriveRobot(scene, options);
        compareWithNumeric(scene, d, 3, 1e-10);
    }

    // Ḃ − 2C is skew-symmetric as a polynomial identity, not only at sampled states.
    void bDotMinusTwoCIsSkewSymbolically_data() {
        QTest::addColumn<QString>("file");
        QTest::newRow("planar 2R") << "planar_2r.json";
        QTest::newRow("SCARA") << "scara.json";
        QTest::newRow("3R") << "puma560.json";  // its first three joints, below
    }
    void bDotMinusTwoCIsSkewSymbolically() {
        QFETCH(QString, file);
        Scene scene = exampleScene(file.toStdString());
        if (scene.robot.dof() > 4) {  // the PUMA's arm: a spatial 3R
            scene.robot.joints.resize(3);
            scene.initial.q.conservativeResize(3);
            scene.initial.qd.conservativeResize(3);
        }
        DerivationOptions options;
        options.mode = ParameterMode::Textbook;
        const Derivation d = deriveRobot(scene, options);
        const int n = scene.robot.dof();
        std::vector<bool> revolute(n);
        for (int i = 0; i < n; ++i) revolute[i] = scene.robot.joints[i].dh.type == JointType::Revolute;
        // Ḃ = Σ_k ∂B/∂q_k q̇_k, differentiated as functions of q (independently of the
        // chain rule the derivation uses for C)
        GiNaC::matrix Bdot(n, n);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                GiNaC::ex b = d.B(i, j).subs(d.trigToFunctions), dot = 0;
                for (int k = 0; k < n; ++k) dot += b.diff(d.q[k]) * d.qd[k];
                Bdot(i, j) = dot;
            }
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const GiNaC::ex N_ij = Bdot(i, j) - 2 * d.C(i, j).subs(d.trigToFunctions);
                const GiNaC::ex N_ji = Bdot(j, i) - 2 * d.C(j, i).subs(d.trigToFunctions);
                // sum of a skew pair, with sin² = 1 − cos² everywhere
                GiNaC::ex sum = (N_ij + N_ji).expand();
                for (int k = 0; k < n; ++k)
                    if (revolute[k])
                        sum = sum.subs(GiNaC::pow(GiNaC::sin(d.q[k]), GiNaC::wild()) ==
                                       GiNaC::pow(GiNaC::sin(d.q[k]), GiNaC::wild() - 2) * (1 - GiNaC::pow(GiNaC::cos(d.q[k]), 2)))
                                  .expand();
                QVERIFY2(sum.normal().is_zero(), qPrintable(QString("(%1,%2)").arg(i).arg(j)));
            }
    }

    // Parameters named like the derivation's shorthand (c1 = cos q1, s12 = sin(q1 + q2))
    // once turned the parameter into the cosine in the plain expressions and printed
    // s12 · sin(q1 + q2) as s12²: the scene is refused, naming the clash.
    void shorthandParameterNamesAreRefused_data() {
        QTest::addColumn<QString>("from");
        QTest::addColumn<QString>("to");
        QTest::addColumn<QString>("meaning");
        QTest::newRow("c1") << "lc1"
                            << "c1"
                            << "cos q1";
        QTest::newRow("s12") << "lc2"
                             << "s12"
                             << "sin(q1 + q2)";
        QTest::newRow("s2") << "lc2"
                            << "s2"
                            << "sin q2";
    }
    void shorthandParameterNamesAreRefused() {
        QFETCH(QString, from);
        QFETCH(QString, to);
        QFETCH(QString, meaning);
        auto lock = lockGinac();
        const Scene scene = renamedExample("planar_2r.json", {{from.toStdString(), to.toStdString()}});
        try {
            (void)deriveRobot(scene);
            QFAIL("derived a scene whose parameter is named like the shorthand");
        } catch (const InputError& e) {
            QCOMPARE(e.diagnostics().size(), std::size_t(1));
            QCOMPARE(QString::fromStdString(e.diagnostics()[0].field), "parameters." + to);
            QVERIFY2(QString::fromStdString(e.diagnostics()[0].message.english()).contains(meaning),
                     e.diagnostics()[0].message.english().c_str());
        }
        // With numbers in place of the parameters there is no clash, and the model is
        // the numeric dynamics'.
        DerivationOptions numeric;
        numeric.mode = ParameterMode::Numeric;
        compareWithNumeric(scene, deriveRobot(scene, numeric), 3, 1e-10);
    }

    // A name that is not a shorthand for this robot (c3 on a 2-joint arm) is a plain
    // parameter: the same mathematics as under its old name, printed as itself.
    void otherParameterNamesDeriveTheSameModel() {
        auto lock = lockGinac();
        const Scene scene = renamedExample("planar_2r.json", {{"lc1", "c3"}, {"lc2", "s4"}});
        const Derivation renamed = deriveRobot(scene), original = deriveRobot(exampleScene("planar_2r.json"));
        // Both in cos/sin of one set of coordinates and one set of parameter symbols, the
        // renamed parameters renamed back.
        const std::map<std::string, std::string> oldName{{"c3", "lc1"}, {"s4", "lc2"}};
        GiNaC::lst back;
        for (const GiNaC::ex& relation : renamed.parameterValues) {
            const std::string name = GiNaC::ex_to<GiNaC::symbol>(relation.lhs()).get_name();
            back.append(relation.lhs() == parameterSymbol(original, oldName.count(name) ? oldName.at(name) : name));
        }
        for (int i = 0; i < 2; ++i) {
            back.append(renamed.q[i] == original.q[i]);
            back.append(renamed.qd[i] == original.qd[i]);
        }
        for (const auto& [a, b] : {std::pair{&renamed.B, &original.B}, {&renamed.C, &original.C}, {&renamed.g, &original.g}}) {
            for (unsigned i = 0; i < a->rows(); ++i)
                for (unsigned j = 0; j < a->cols(); ++j) {
                    const GiNaC::ex mine = (*a)(i, j).subs(renamed.trigToFunctions).subs(back);
                    QVERIFY((mine - (*b)(i, j).subs(original.trigToFunctions)).expand().is_zero());
                }
        }
        const std::string b11 = print(renamed.B(0, 0), printOptionsFor(renamed, Style::Plain));
        QVERIFY2(b11.find("m1*c3^2") != std::string::npos && b11.find("m2*s4^2") != std::string::npos &&
                     b11.find("q3") == std::string::npos && b11.find("q4") == std::string::npos,
                 b11.c_str());
        compareWithNumeric(scene, renamed, 3, 1e-10);
    }

    void onlyDeclaredEffectsAppear() {
        Scene scene = exampleScene("planar_2r.json");
        scene.effects = Effects{};
        const Derivation d = deriveRobot(scene);
        for (int i = 0; i < 2; ++i) {
            QVERIFY(d.g(i, 0).is_zero());
            QVERIFY(d.Q(i, 0).is_zero());
        }
        QVERIFY(d.Epot.is_zero());
        QVERIFY(d.underactuated);
        QVERIFY(d.actuated.empty());
    }
};

LL_TEST_APPLESS_MAIN(TestRobotDerivation)

}  // namespace test_robot_derivation
#include "test_robot_derivation.moc"
