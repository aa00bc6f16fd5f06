// Fixed-step integrators take exactly the step asked for, whatever the output rate:
// steps at t_k = k·dt, samples between steps by cubic Hermite interpolation, a last
// shorter step only when the duration is not a multiple of dt, events still located
// inside a step. Errors are measured against a tight dopri5 reference.
#include "test_registry.hpp"

#include <boost/numeric/odeint.hpp>

#include "core/io/scene_file.hpp"
#include "core/simulation/robot_ode.hpp"
#include "core/pipeline/scene_simulation.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_fixed_step {

using namespace ll;

namespace {
Scene example(const std::string& name) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + name).scene; }

// The double pendulum on a regular (non-chaotic) swing of several rad/s.
Scene smoothScene(double duration) {
    Scene scene = example("double_pendulum.json");
    scene.initial.q = Eigen::Vector2d(0.8, -0.3);
    scene.initial.qd = Eigen::Vector2d(0.2, 0.5);
    scene.simulation.duration = duration;
    scene.simulation.outputRate = 100;
    return scene;
}

SimulationResult run(const Scene& scene, const std::string& integrator, double dt) {
    SimulationSettings s = scene.simulation;
    s.integrator = integrator;
    s.dt = dt;
    s.absTol = s.relTol = 1e-12;
    return simulate(scene, s);
}

// Max over every sample (most of them interpolated at coarse steps) of the error measure
// of work_precision.hpp against a reference recorded at the same times.
double maxSampleError(const Trajectory& a, const Trajectory& reference) {
    double e = 0;
    for (size_t k = 0; k < a.size(); ++k) {
        Eigen::VectorXd x(2 * a.n), r(2 * a.n);
        x << a.q[k], a.qd[k];
        r << reference.q[k], reference.qd[k];
        e = std::max(e, finalStateError(x, r));
    }
    return e;
}
}  // namespace

class TestFixedStep : public QObject {
    Q_OBJECT
private slots:
    // Halving dt divides the error by 2^order, at the final state and at every sample
    // (the Hermite interpolant's O(dt⁴) error keeps rk4's order); dt = 0.04 s is four
    // output intervals, so each step here is as long as asked.
    void errorFallsWithTheOrder_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("order");
        QTest::addColumn<double>("T");
        QTest::newRow("rk4") << "rk4" << 4.0 << 2.0;
        QTest::newRow("euler") << "euler" << 1.0 << 1.0;
    }
    void errorFallsWithTheOrder() {
        QFETCH(QString, name);
        QFETCH(double, order);
        QFETCH(double, T);
        // Euler at dt = 0.04 s is in its asymptotic regime only on a slower scene: the
        // simple pendulum released at 1 rad.
        Scene scene = smoothScene(T);
        if (name == "euler") {
            scene = example("simple_pendulum.json");
            scene.simulation.duration = T;
            scene.simulation.outputRate = 100;
        }
        const long samples = std::lround(100 * T);
        const SimulationResult reference = run(scene, "dopri5", 1e-3);
        QCOMPARE(int(reference.status), int(SimulationStatus::Completed));
        std::vector<double> finalErrors, sampleErrors;
        for (double dt : {0.04, 0.02, 0.01}) {
            const SimulationResult r = run(scene, name.toStdString(), dt);
            QCOMPARE(int(r.status), int(SimulationStatus::Completed));
            QCOMPARE(r.stats.steps, std::lround(T / dt));  // the steps taken, each dt
            QCOMPARE(r.stats.dt, dt);
            QCOMPARE(r.stats.lastStep, 0.0);
            QCOMPARE(long(r.trajectory.size()), samples + 1);
            QCOMPARE(r.stats.interpolatedSamples, samples - std::lround(T / dt));  // those not on a step end
            finalErrors.push_back(finalStateError(finalState(r.trajectory), finalState(reference.trajectory)));
            sampleErrors.push_back(maxSampleError(r.trajectory, reference.trajectory));
        }
        const double expected = std::pow(2.0, order);
        for (const std::vector<double>* errors : {&finalErrors, &sampleErrors})
            for (size_t i = 0; i + 1 < errors->size(); ++i) {
                const double ratio = (*errors)[i] / (*errors)[i + 1];
                QVERIFY2(std::abs(ratio / expected - 1) <= 0.3, qPrintable(QString("%1 %2 error ratio %3 (expected %4): errors %5, %6")
                                                                               .arg(name, errors == &finalErrors ? "final" : "max sample")
                                                                               .arg(ratio)
                                                                               .arg(expected)
                                                                               .arg((*errors)[i])
                                                                               .arg((*errors)[i + 1])));
            }
    }

    // dt = 0.003 s does not divide the 0.01 s output interval: the run still steps at
    // 0.003 s, exactly as a bare rk4 loop at t_k = k·0.003, and the output rate changes
    // nothing but the samples.
    void stepsAtTheAskedDtWhateverTheOutputRate() {
        const double dt = 0.003, T = 0.9;
        const Scene scene = smoothScene(T);
        const SimulationResult r = run(scene, "rk4", dt);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        QCOMPARE(r.stats.steps, 300L);
        QCOMPARE(r.stats.lastStep, 0.0);
        QVERIFY(r.stats.interpolatedSamples >= 60);  // samples at 0.01 k fall between steps of 0.003

        RobotOde ode(scene.robot, scene.effects);
        OdeState x = ode.initialState(scene.initial.q, scene.initial.qd);
        boost::numeric::odeint::runge_kutta4<OdeState> rk4;
        for (int k = 0; k < 300; ++k) rk4.do_step(std::ref(ode), x, k * dt, dt);
        const Eigen::VectorXd bare = Eigen::Map<const Eigen::VectorXd>(x.data(), 4);
        QVERIFY2((finalState(r.trajectory) - bare).cwiseAbs().maxCoeff() <= 1e-14,
                 qPrintable(QString::number((finalState(r.trajectory) - bare).cwiseAbs().maxCoeff())));

        Scene sparse = scene;
        sparse.simulation.outputRate = 1.0 / T;  // samples at 0 and T only
        const SimulationResult s = run(sparse, "rk4", dt);
        QCOMPARE(int(s.trajectory.size()), 2);
        QCOMPARE(s.stats.steps, 300L);
        QCOMPARE(s.stats.interpolatedSamples, 0L);
        QVERIFY(finalState(s.trajectory) == finalState(r.trajectory));
    }

    // A duration that is not a multiple of dt ends with one shorter step.
    void lastShorterStepOnlyWhenNeeded() {
        const Scene scene = smoothScene(1.0);
        const SimulationResult r = run(scene, "rk4", 0.003);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        QCOMPARE(r.stats.steps, 334L);  // 333 of 0.003 s and one of 0.001 s
        QVERIFY2(std::abs(r.stats.lastStep - 0.001) < 1e-12, qPrintable(QString::number(r.stats.lastStep)));
        QCOMPARE(r.trajectory.t.back(), 1.0);
        const SimulationResult coarse = run(scene, "euler", 0.3);  // longer than the output interval
        QCOMPARE(coarse.stats.steps, 4L);
        QVERIFY2(std::abs(coarse.stats.lastStep - 0.1) < 1e-12, qPrintable(QString::number(coarse.stats.lastStep)));
        QCOMPARE(coarse.stats.interpolatedSamples, 96L);  // 100 samples after t = 0, 4 on step ends (.3, .6, .9, 1)
    }

    // The stick–slip hard case at steps longer than the output interval and at one that
    // does not divide it: the crossing is located inside the step, the pendulum stops
    // where the adaptive reference stops it, held exactly, and never gains energy.
    void stickSlipKeepsItsPropertiesAtCoarseSteps_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<double>("dt");
        QTest::newRow("rk4 0.02") << "rk4" << 0.02;
        QTest::newRow("rk4 0.003") << "rk4" << 0.003;
        QTest::newRow("midpoint 0.004") << "midpoint" << 0.004;
    }
    void stickSlipKeepsItsPropertiesAtCoarseSteps() {
        QFETCH(QString, name);
        QFETCH(double, dt);
        const Scene scene = example("hard/stick_slip.json");
        const SimulationResult reference = simulate(scene);
        const SimulationResult r = run(scene, name.toStdString(), dt);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        const Trajectory& tr = r.trajectory;
        QVERIFY(r.stats.eventSteps > 0);  // crossings located inside steps
        const long grid = std::lround(std::ceil(scene.simulation.duration / dt - 1e-9));
        QCOMPARE(r.stats.steps, grid + r.stats.eventSteps);
        QCOMPARE(tr.qd.back()[0], 0.0);
        const double Fc = scene.effects.coulomb[0].force, m = 1.0, g = 9.81, l = 1.0;
        QVERIFY(std::abs(tr.q.back()[0]) <= std::asin(Fc / (m * g * l)) + 1e-9);
        QVERIFY2(std::abs(tr.q.back()[0] - reference.trajectory.q.back()[0]) < 1e-3,
                 qPrintable(QString("stopped at %1, reference %2").arg(tr.q.back()[0]).arg(reference.trajectory.q.back()[0])));
        size_t rest = tr.size();
        while (rest > 0 && tr.qd[rest - 1][0] == 0.0) --rest;
        QVERIFY(rest < tr.size() && tr.t[rest] < scene.simulation.duration - 2);
        for (size_t k = rest; k < tr.size(); ++k) QCOMPARE(tr.q[k][0], tr.q[rest][0]);  // held, no creep
        for (size_t k = 1; k < tr.size(); ++k)
            QVERIFY2(tr.E[k] <= tr.E[k - 1] + 1e-6 * std::abs(tr.E[0]), qPrintable(QString("E rose at t = %1").arg(tr.t[k])));
        QVERIFY2(r.stats.maxRelEnergyError < 1e-3, qPrintable(QString::number(r.stats.maxRelEnergyError)));
    }

    // The work–precision analysis times the fixed-step methods at the dt it reports,
    // even when that is longer than its output interval.
    void workPrecisionUsesTheRealDt() {
        const Scene scene = smoothScene(2.0);
        WorkPrecisionSettings s;
        s.integrators = {"rk4"};
        s.tolerances = {1e-8};
        s.steps = {0.2, 0.1};  // 10 Hz output: one and two samples per step
        s.repeats = 1;
        const WorkPrecisionResult r = runWorkPrecision(scene, s);
        QCOMPARE(int(r.points.size()), 2);
        for (const WorkPrecisionPoint& p : r.points) {
            QVERIFY2(p.completed, p.message.english().c_str());
            QCOMPARE(p.step, p.setting);
            QCOMPARE(p.steps, std::lround(2.0 / p.setting));
        }
        QVERIFY(r.points[0].finalError > 8 * r.points[1].finalError);  // a coarser step, a larger error
    }
};

LL_TEST_APPLESS_MAIN(TestFixedStep)

}  // namespace test_fixed_step
#include "test_fixed_step.moc"
