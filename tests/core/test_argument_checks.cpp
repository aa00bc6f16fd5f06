// Public core functions check argument sizes in every build: a worker fed a stale
// state after a joint was deleted gets std::invalid_argument naming both sizes, not an
// out-of-bounds write (the project builds Release, where asserts are off).
#include "test_registry.hpp"

#include <functional>
#include <stdexcept>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/energy.hpp"
#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/kinematics/jacobians.hpp"
#include "core/simulation/generalized_forces.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/symbolic/compiled_derivation.hpp"
#include "core/symbolic/ginac_lock.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_argument_checks {

using namespace ll;

namespace {
// The message of the std::invalid_argument that f throws; "" if it throws nothing.
QString invalidArgument(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return QString::fromStdString(e.what());
    }
    return {};
}

Scene exampleScene(const char* name) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + name).scene; }
}  // namespace

class TestArgumentChecks : public QObject {
    Q_OBJECT
private slots:
    // A q of 5 entries for a 6-joint robot, at every public entry point.
    void staleStateIsRefusedNamingTheSizes() {
        std::mt19937 rng(3);
        const RobotModel robot = test::randomRobot(rng, 6, DhConvention::Standard);
        RobotData data(robot);
        const Eigen::VectorXd q6 = test::randomVector(rng, 6, 1.0), q5 = q6.head(5);
        Effects effects;
        effects.gravity = Eigen::Vector3d(0, 0, -9.81);
        forwardKinematics(robot, data, q6);
        computeMassMatrix(robot, data);

        QCOMPARE(invalidArgument([&] { forwardKinematics(robot, data, q5); }),
                 QString("forwardKinematics: q has 5 entries, the robot has 6 joints"));
        QCOMPARE(invalidArgument([&] { computeCoriolisMatrix(robot, data, q5); }),
                 QString("computeCoriolisMatrix: qd has 5 entries, the robot has 6 joints"));
        QCOMPARE(invalidArgument([&] { computePotentialGradient(robot, data, effects, q5); }),
                 QString("computePotentialGradient: q has 5 entries, the robot has 6 joints"));
        QCOMPARE(invalidArgument([&] { (void)kineticEnergy(data, q5); }),
                 QString("kineticEnergy: qd has 5 entries, the robot has 6 joints"));
        QCOMPARE(invalidArgument([&] { (void)potentialEnergy(robot, data, effects, q5); }),
                 QString("potentialEnergy: q has 5 entries, the robot has 6 joints"));
        QCOMPARE(invalidArgument([&] { (void)inverseDynamics(robot, data, effects, q6, q6, q5); }),
                 QString("rnea: qdd has 5 entries, the robot has 6 joints"));
        QCOMPARE(invalidArgument([&] { (void)forwardDynamics(robot, data, effects, q6, q5, q6); }),
                 QString("forwardDynamics: qd has 5 entries, the robot has 6 joints"));
        QCOMPARE(invalidArgument([&] { (void)forwardDynamics(robot, data, effects, q6, q6, q5); }),
                 QString("forwardDynamics: Q has 5 entries, the robot has 6 joints"));
        Jacobian J;
        QCOMPARE(invalidArgument([&] { pointJacobian(data, 6, Eigen::Vector3d::Zero(), J); }),
                 QString("pointJacobian: link is joint 7 (numbered from 1), the robot has 6 joints"));
        Eigen::VectorXd Q(6);
        QCOMPARE(invalidArgument([&] { computeGeneralizedForces(effects, 0.0, q5, Q); }),
                 QString("computeGeneralizedForces: Q has 6 entries, qd has 5 entries"));
        // and the right sizes still work
        QVERIFY(invalidArgument([&] { (void)forwardDynamics(robot, data, effects, q6, q6, q6); }).isEmpty());
    }

    // The robot lost its last joint; the scratch data and the effects still have six.
    void dataAndEffectsOfAnotherRobotAreRefused() {
        std::mt19937 rng(4);
        RobotModel robot = test::randomRobot(rng, 6, DhConvention::Modified);
        RobotData data(robot);
        robot.joints.pop_back();
        const Eigen::VectorXd q5 = test::randomVector(rng, 5, 1.0);
        QCOMPARE(invalidArgument([&] { forwardKinematics(robot, data, q5); }),
                 QString("forwardKinematics: the RobotData was made for 6 joints, the robot has 5 joints"));
        QCOMPARE(invalidArgument([&] { computeMassMatrix(robot, data); }),
                 QString("computeMassMatrix: the RobotData was made for 6 joints, the robot has 5 joints"));
        RobotData fresh(robot);
        forwardKinematics(robot, fresh, q5);
        Effects effects;
        effects.springs = {{5, 10.0, 0.0}};
        QCOMPARE(invalidArgument([&] { (void)potentialEnergy(robot, fresh, effects, q5); }),
                 QString("potentialEnergy: effects.springs[0] is joint 6 (numbered from 1), the robot has 5 joints"));
        QCOMPARE(invalidArgument([&] { (void)linkTransform(robot, 5, 0.0); }),
                 QString("linkTransform: i is joint 6 (numbered from 1), the robot has 5 joints"));
    }

    // A scene edited in a window: the last joint deleted, the initial state and an
    // effect not yet updated.
    void simulateRefusesAStaleScene() {
        Scene scene = exampleScene("puma560.json");
        scene.robot.joints.pop_back();
        QCOMPARE(invalidArgument([&] { (void)simulate(scene); }),
                 QString("simulate: initial.q has 6 entries, the scene has 5 coordinates"));
        scene.initial.q.conservativeResize(5);
        scene.initial.qd.conservativeResize(5);
        scene.effects.viscous = {{5, 0.1}};
        QCOMPARE(invalidArgument([&] { (void)simulate(scene); }),
                 QString("simulate: effects.viscous[0] is joint 6 (numbered from 1), the robot has 5 joints"));
    }

    void compiledLagrangianRefusesAStaleState() {
        auto lock = symbolic::lockGinac();
        const Scene scene = exampleScene("mass_spring_pair_lagrangian.json");
        const CompiledLagrangian model = symbolic::compileDerivation(symbolic::deriveLagrangian(scene, symbolic::ParameterMode::Numeric));
        QCOMPARE(invalidArgument([&] { (void)model.terms(Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(2), 0.0); }),
                 QString("CompiledLagrangian::terms: q has 3 entries, the system has 2 coordinates"));
    }
};

LL_TEST_APPLESS_MAIN(TestArgumentChecks)

}  // namespace test_argument_checks
#include "test_argument_checks.moc"
