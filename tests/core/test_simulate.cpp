// Simulation against physical laws: a conservative scene keeps E to the integrator's
// tolerance; with friction and torques E(t) − E(0) equals the work of Q; friction
// alone never increases E; cancellation and failures stop cleanly with partial data.
#include "test_registry.hpp"

#include "core/model/scene.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_simulate {

using namespace ll;

namespace {
Scene doublePendulumScene() {
    Scene scene;
    scene.name = "double pendulum";
    scene.robot = test::Planar2R{}.model();
    scene.effects.gravity = Eigen::Vector3d(0, -9.81, 0);
    scene.initial.q = Eigen::Vector2d(1.2, -0.4);
    scene.initial.qd = Eigen::Vector2d(0.0, 1.0);
    scene.simulation.duration = 10.0;
    return scene;
}
}  // namespace

class TestSimulate : public QObject {
    Q_OBJECT
private slots:
    void conservativeSceneConservesEnergy_data() {
        QTest::addColumn<double>("tolerance");
        QTest::newRow("1e-6") << 1e-6;
        QTest::newRow("1e-9") << 1e-9;
    }
    void conservativeSceneConservesEnergy() {
        QFETCH(double, tolerance);
        Scene scene = doublePendulumScene();
        scene.simulation.absTol = scene.simulation.relTol = tolerance;
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        QCOMPARE(r.trajectory.t.back(), 10.0);
        QCOMPARE(int(r.trajectory.size()), 1001);
        // Local errors of size tol per step accumulate over the run; allow 100x.
        QVERIFY2(r.stats.maxRelEnergyError < 100 * tolerance, qPrintable(QString::number(r.stats.maxRelEnergyError)));
        QVERIFY(r.stats.maxRelEnergyError > 0);   // it is a real measurement, not a copy of E(0)
        QCOMPARE(r.trajectory.work.back(), 0.0);  // no Q declared: no work
        QVERIFY(r.stats.rhsEvaluations > r.stats.steps);
    }

    void frictionAndTorqueSatisfyEnergyBalance() {
        Scene scene = doublePendulumScene();
        scene.effects.viscous = {{0, 0.3}};
        scene.effects.coulomb = {{1, 0.4, 1e-2}};
        JointTorque torque;
        torque.joint = 0;
        torque.kind = TorqueKind::Sine;
        torque.amplitude = 2.0;
        torque.frequency = 0.7;
        scene.effects.torques = {torque};
        scene.simulation.absTol = scene.simulation.relTol = 1e-10;
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        // E(t) − E(0) = ∫ Qᵀ q̇ dt, with W integrated alongside the state
        const Trajectory& tr = r.trajectory;
        QVERIFY(std::abs(tr.work.back()) > 0.1);  // the forces did real work
        QVERIFY2(r.stats.maxRelEnergyError < 1e-7, qPrintable(QString::number(r.stats.maxRelEnergyError)));
        // independent check of dE/dt = Qᵀq̇ by differencing the recorded energy
        for (size_t k = 1; k + 1 < tr.size(); k += 50) {
            const double dEdt = (tr.E[k + 1] - tr.E[k - 1]) / (tr.t[k + 1] - tr.t[k - 1]);
            const double power = (tr.work[k + 1] - tr.work[k - 1]) / (tr.t[k + 1] - tr.t[k - 1]);
            QVERIFY(std::abs(dEdt - power) < 1e-2 * std::max(1.0, std::abs(power)));
        }
    }

    void frictionNeverAddsEnergy() {
        Scene scene = doublePendulumScene();
        scene.effects.viscous = {{0, 1.0}, {1, 0.5}};
        scene.effects.coulomb = {{0, 0.5, 1e-3}, {1, 0.3, 1e-3}};
        scene.simulation.duration = 40.0;
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        const Trajectory& tr = r.trajectory;
        for (size_t k = 1; k < tr.size(); ++k)
            QVERIFY2(tr.E[k] <= tr.E[k - 1] + 1e-7 * std::abs(tr.E[0]), qPrintable(QString("t=%1").arg(tr.t[k])));
        QVERIFY(tr.E.back() < tr.E.front() - 1.0);  // and it really dissipated
        QVERIFY(tr.qd.back().norm() < 0.05);        // the pendulum comes (nearly) to rest
    }

    void cancellationStopsWithPartialTrajectory() {
        const Scene scene = doublePendulumScene();
        std::atomic<bool> cancel{false};
        double lastFraction = 0;
        const SimulationResult r = simulate(
            scene, scene.simulation,
            [&](double f) {
                lastFraction = f;
                if (f >= 0.3) cancel = true;
            },
            &cancel);
        QCOMPARE(int(r.status), int(SimulationStatus::Cancelled));
        QCOMPARE(int(r.message.id), int(MessageId::CancelledAtTime));
        QVERIFY(r.trajectory.t.back() >= 3.0 && r.trajectory.t.back() < 3.1);
        QVERIFY(lastFraction < 0.31);
    }

    void unstableFixedStepStopsWithMessage() {
        Scene scene = doublePendulumScene();
        scene.effects.springs = {{1, 1e7, 0.0}};  // natural frequency ~1e4 rad/s
        scene.simulation.integrator = "euler";
        scene.simulation.dt = 1e-2;
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Failed));
        QVERIFY2(r.message.english().find("non-finite") != std::string::npos, r.message.english().c_str());
        QVERIFY(r.message.english().find("reduce dt") != std::string::npos);
        QVERIFY(r.trajectory.size() > 0);
    }

    void unknownIntegratorIsRejectedBeforeRunning() {
        Scene scene = doublePendulumScene();
        scene.simulation.integrator = "rk45x";
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, simulate(scene));
    }

    void outputTimesEndExactlyOnDuration() {
        const std::vector<double> t = outputTimes(1.05, 10);
        QCOMPARE(int(t.size()), 12);
        QCOMPARE(t.back(), 1.05);
        QCOMPARE(t[10], 1.0);
    }
};

LL_TEST_APPLESS_MAIN(TestSimulate)

}  // namespace test_simulate
#include "test_simulate.moc"
