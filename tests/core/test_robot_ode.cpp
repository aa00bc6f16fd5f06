// The right-hand side is composed from the declared effects only: each term counts its
// evaluations, so "no gravity → g(q) is never computed, no friction → no friction code
// runs" is checked by counting, not by looking at Q. The composed right-hand side must
// still equal the reference pipeline forwardDynamics(Q from computeGeneralizedForces).
#include "test_registry.hpp"

#include "core/dynamics/forward_dynamics.hpp"
#include "core/io/scene_file.hpp"
#include "core/simulation/generalized_forces.hpp"
#include "core/simulation/integrators.hpp"
#include "core/simulation/robot_ode.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_robot_ode {

using namespace ll;

namespace {

Scene puma() { return loadScene(std::string(LL_EXAMPLES_DIR) + "/puma560.json").scene; }

Effects allEffects(int n) {
    Effects e;
    e.gravity = Eigen::Vector3d(0, 0, -9.81);
    for (int j = 0; j < n; ++j) {
        e.springs.push_back({j, 5.0 + j, 0.1 * j});
        e.viscous.push_back({j, 0.2});
        e.coulomb.push_back({j, 0.3, 1e-2});
        JointTorque t;
        t.joint = j;
        t.kind = TorqueKind::Sine;
        t.amplitude = 1.5;
        t.frequency = 0.8;
        e.torques.push_back(t);
    }
    return e;
}

// Evaluates the ODE at `count` random states; returns the ODE for its counters.
void evaluate(RobotOde& ode, int n, int count) {
    std::mt19937 rng(7);
    OdeState dxdt(2 * n + 1);
    for (int k = 0; k < count; ++k) {
        const OdeState x = ode.initialState(test::randomVector(rng, n, 2.0), test::randomVector(rng, n, 1.5));
        ode(x, dxdt, 0.1 * k);
    }
}

}  // namespace

class TestRobotOde : public QObject {
    Q_OBJECT
private slots:
    void noEffectsRunsOnlyInertiaAndCoriolis() {
        const Scene scene = puma();
        const Effects none;
        RobotOde ode(scene.robot, none);
        evaluate(ode, 6, 25);
        QCOMPARE(ode.evaluations(), 25L);
        QCOMPARE(ode.termEvaluations(RhsTerm::MassMatrix), 25L);
        QCOMPARE(ode.termEvaluations(RhsTerm::Coriolis), 25L);
        for (RhsTerm t : {RhsTerm::Gravity, RhsTerm::Springs, RhsTerm::Viscous, RhsTerm::Coulomb, RhsTerm::Torques})
            QVERIFY2(ode.termEvaluations(t) == 0, toString(t));
        QCOMPARE(int(ode.terms().size()), 2);
    }

    void gravityOnlyNeverRunsFrictionTorquesOrSprings() {
        const Scene scene = puma();  // declares gravity only
        QVERIFY(scene.effects.gravity && !scene.effects.hasFriction() && scene.effects.torques.empty());
        RobotOde ode(scene.robot, scene.effects);
        // a whole integration, not just single calls
        OdeState x = ode.initialState(scene.initial.q, scene.initial.qd);
        IntegrationSettings s;
        s.absTol = s.relTol = 1e-8;
        integrate(ode, x, {0.0, 0.5}, s, [](double, const OdeState&) { return true; });
        QVERIFY(ode.evaluations() > 50);
        QCOMPARE(ode.termEvaluations(RhsTerm::Gravity), ode.evaluations());
        for (RhsTerm t : {RhsTerm::Springs, RhsTerm::Viscous, RhsTerm::Coulomb, RhsTerm::Torques})
            QVERIFY2(ode.termEvaluations(t) == 0, toString(t));
        QCOMPARE(x[12], 0.0);  // no work of Q: Ẇ was never computed from anything but 0
    }

    void everyDeclaredEffectRunsOncePerEvaluation() {
        const Scene scene = puma();
        Effects effects = allEffects(6);
        Control control;  // and a controller (its τ joins Q)
        control.kp = control.kd = Eigen::VectorXd::Ones(6);
        control.reference.q0 = Eigen::VectorXd::Zero(6);
        effects.control = control;
        RobotOde ode(scene.robot, effects);
        evaluate(ode, 6, 17);
        for (int t = 0; t < kRhsTermCount; ++t) QVERIFY2(ode.termEvaluations(RhsTerm(t)) == 17, toString(RhsTerm(t)));
        QCOMPARE(int(ode.terms().size()), kRhsTermCount);
    }

    // The composition must give the same q̈ and Ẇ as the reference pipeline.
    void composedRightHandSideEqualsForwardDynamics_data() {
        QTest::addColumn<bool>("withEffects");
        QTest::newRow("no effects") << false;
        QTest::newRow("all effects") << true;
    }
    void composedRightHandSideEqualsForwardDynamics() {
        QFETCH(bool, withEffects);
        std::mt19937 rng(99);
        const RobotModel robot = test::randomRobot(rng, 5, DhConvention::Modified);
        const Effects effects = withEffects ? allEffects(5) : Effects{};
        RobotOde ode(robot, effects);
        RobotData data(robot);
        for (int k = 0; k < 10; ++k) {
            const Eigen::VectorXd q = test::randomVector(rng, 5, 2.0), qd = test::randomVector(rng, 5, 1.0);
            const double t = 0.37 * k;
            OdeState dxdt(11);
            ode(ode.initialState(q, qd), dxdt, t);
            Eigen::VectorXd Q(5);
            computeGeneralizedForces(effects, t, qd, Q);
            const Eigen::VectorXd qdd = forwardDynamics(robot, data, effects, q, qd, Q);
            const Eigen::VectorXd got = Eigen::Map<const Eigen::VectorXd>(dxdt.data() + 5, 5);
            QVERIFY2(test::scaledError(got, qdd) < 1e-10, qPrintable(QString::number(test::scaledError(got, qdd))));
            QVERIFY(std::abs(dxdt[10] - Q.dot(qd)) < 1e-12 * std::max(1.0, std::abs(Q.dot(qd))));
            for (int i = 0; i < 5; ++i) QCOMPARE(dxdt[i], qd[i]);
        }
    }
};

LL_TEST_APPLESS_MAIN(TestRobotOde)

}  // namespace test_robot_ode
#include "test_robot_ode.moc"
