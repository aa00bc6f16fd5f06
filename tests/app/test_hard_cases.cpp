// The hard cases of examples/hard/: each scene states in its description the property
// it must keep, and each test here checks that property on the scene file as shipped.
#include "test_registry.hpp"

#include <QProcess>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/forward_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/kinematics/jacobians.hpp"
#include "core/model/utf8_text.hpp"
#include "core/simulation/integrators.hpp"
#include "core/simulation/robot_ode.hpp"
#include "core/pipeline/scene_simulation.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_hard_cases {

using namespace ll;

namespace {

std::string hardPath(const char* name) { return std::string(LL_EXAMPLES_DIR) + "/hard/" + name; }
Scene hard(const char* name) { return loadScene(hardPath(name)).scene; }

bool finite(const Trajectory& tr) {
    for (size_t k = 0; k < tr.size(); ++k)
        if (!tr.q[k].allFinite() || !tr.qd[k].allFinite() || !std::isfinite(tr.E[k])) return false;
    return true;
}

// Max relative change of p1 = (B q̇)_1, the momentum of a cyclic first joint.
double momentumDrift(const Scene& scene, const Trajectory& tr) {
    RobotData data(scene.robot);
    double p0 = 0, drift = 0;
    for (size_t k = 0; k < tr.size(); ++k) {
        forwardKinematics(scene.robot, data, tr.q[k]);
        computeMassMatrix(scene.robot, data);
        const double p = data.B.row(0).dot(tr.qd[k]);
        if (k == 0) p0 = p;
        drift = std::max(drift, std::abs(p - p0) / std::abs(p0));
    }
    return drift;
}

double maxAbsDiff(const std::vector<double>& v, double ref, size_t from, size_t to) {
    double m = 0;
    for (size_t k = from; k < to; ++k) m = std::max(m, std::abs(v[k] - ref));
    return m;
}

}  // namespace

class TestHardCases : public QObject {
    Q_OBJECT
private slots:
    void chaoticDoublePendulumKeepsEnergy() {
        const Scene scene = hard("chaotic_double_pendulum.json");
        QCOMPARE(scene.simulation.duration, 100.0);
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        QVERIFY(finite(r.trajectory));
        QVERIFY2(r.stats.maxRelEnergyError <= 1e-8, qPrintable(QString::number(r.stats.maxRelEnergyError)));
        QVERIFY(r.stats.maxRelEnergyError > 0);
    }

    // Drift falls with the setting as the method's order predicts: for rk4 the energy
    // error is O(dt^4) (at least; here it falls a little faster, ~dt^5); for dopri5
    // (error per step controlled, 5th-order solution) drift ~ tol^1. Slopes are fitted
    // over four settings, each run over the full 100 s.
    void chaoticDoublePendulumDriftFollowsOrder() {
        const auto slope = [](const std::vector<double>& x, const std::vector<double>& y) {
            double mx = 0, my = 0, sxy = 0, sxx = 0;
            for (size_t i = 0; i < x.size(); ++i) {
                mx += std::log10(x[i]) / x.size();
                my += std::log10(y[i]) / y.size();
            }
            for (size_t i = 0; i < x.size(); ++i) {
                sxy += (std::log10(x[i]) - mx) * (std::log10(y[i]) - my);
                sxx += (std::log10(x[i]) - mx) * (std::log10(x[i]) - mx);
            }
            return sxy / sxx;
        };
        Scene scene = hard("chaotic_double_pendulum.json");
        scene.simulation.integrator = "rk4";
        const std::vector<double> steps = {8e-3, 4e-3, 2e-3, 1e-3};
        std::vector<double> drift;
        for (double dt : steps) {
            scene.simulation.dt = dt;
            const SimulationResult r = simulate(scene);
            QCOMPARE(int(r.status), int(SimulationStatus::Completed));
            drift.push_back(r.stats.maxRelEnergyError);
        }
        const double rk4 = slope(steps, drift);
        QVERIFY2(rk4 >= 4.0 - 0.3 && rk4 <= 5.5, qPrintable(QString("rk4 drift ~ dt^%1").arg(rk4)));

        scene.simulation.integrator = "dopri5";
        const std::vector<double> tolerances = {1e-6, 1e-8, 1e-10, 1e-12};
        drift.clear();
        for (double tol : tolerances) {
            scene.simulation.absTol = scene.simulation.relTol = tol;
            drift.push_back(simulate(scene).stats.maxRelEnergyError);
        }
        for (size_t i = 1; i < drift.size(); ++i) QVERIFY(drift[i] < drift[i - 1]);
        const double dopri5 = slope(tolerances, drift);
        QVERIFY2(dopri5 > 0.7 && dopri5 < 1.3, qPrintable(QString("dopri5 drift ~ tol^%1").arg(dopri5)));
    }

    void nearSingularMassMatrixStaysAccurate() {
        const Scene scene = hard("near_singular_mass.json");
        RobotData data(scene.robot);
        forwardKinematics(scene.robot, data, scene.initial.q);
        computeMassMatrix(scene.robot, data);
        const Eigen::VectorXd eig = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(data.B).eigenvalues();
        QVERIFY2(eig.maxCoeff() / eig.minCoeff() > 1e8, qPrintable(QString("cond %1").arg(eig.maxCoeff() / eig.minCoeff())));

        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        QVERIFY(finite(r.trajectory));
        QVERIFY2(r.stats.maxRelEnergyError <= 1e-8, qPrintable(QString::number(r.stats.maxRelEnergyError)));
        // residual of B q̈ = Q − C q̇ − g along the trajectory
        const Eigen::VectorXd Q = Eigen::VectorXd::Zero(3);
        double worst = 0;
        for (size_t k = 0; k < r.trajectory.size(); k += 5) {
            forwardDynamics(scene.robot, data, scene.effects, r.trajectory.q[k], r.trajectory.qd[k], Q);
            worst = std::max(worst, (data.B * data.qdd - data.rhs).norm() / data.rhs.norm());
        }
        QVERIFY2(worst <= 1e-9, qPrintable(QString("residual %1").arg(worst)));
    }

    void stiffSpringIsDetectedAndRosenbrockCompletes() {
        const Scene scene = hard("stiff_spring.json");
        // the scene's claim: a 1e4 rad/s mode
        RobotOde ode(scene.robot, scene.effects);
        Eigen::MatrixXd J;
        numericJacobian(ode, ode.initialState(scene.initial.q, scene.initial.qd), 0.0, J);
        const double fastest = Eigen::EigenSolver<Eigen::MatrixXd>(J, false).eigenvalues().cwiseAbs().maxCoeff();
        QVERIFY2(std::abs(fastest / 1e4 - 1) < 0.15, qPrintable(QString("fastest mode %1 rad/s").arg(fastest)));

        for (const char* name : {"dopri5", "cash_karp54"}) {
            SimulationSettings s = scene.simulation;
            s.integrator = name;
            const SimulationResult r = simulate(scene, s);
            QCOMPARE(int(r.status), int(SimulationStatus::Failed));
            QVERIFY2(r.message.id == MessageId::SceneStiffFor, r.message.english().c_str());
            QVERIFY2(r.message.english().find("rosenbrock4") != std::string::npos, r.message.english().c_str());
            QVERIFY(r.trajectory.t.back() < s.duration);
            QVERIFY(r.stats.steps > 0 && r.stats.steps < 20000);  // detected early, not after a long crawl
            QVERIFY(finite(r.trajectory));
        }
        const SimulationResult r = simulate(scene);  // rosenbrock4
        QCOMPARE(QString::fromStdString(scene.simulation.integrator), QString("rosenbrock4"));
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        QVERIFY(finite(r.trajectory));
        QVERIFY2(r.stats.maxRelEnergyError <= 1e-4, qPrintable(QString::number(r.stats.maxRelEnergyError)));
        // fewer than half the steps the stability limit of an explicit method (h <= ~3/|λ|) allows
        QVERIFY2(r.stats.steps < scene.simulation.duration * fastest / 3 / 2, qPrintable(QString::number(r.stats.steps)));
    }

    void fastSpinConservesEnergyAndMomentum() {
        const Scene scene = hard("fast_spin.json");
        RobotData data(scene.robot);
        forwardKinematics(scene.robot, data, scene.initial.q);
        computeMassMatrix(scene.robot, data);
        computeCoriolisMatrix(scene.robot, data, scene.initial.qd);
        QVERIFY((data.C * scene.initial.qd).norm() > 100.0);  // N m: Coriolis dominated
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        QVERIFY(finite(r.trajectory));
        QVERIFY2(r.stats.maxRelEnergyError <= 1e-8, qPrintable(QString::number(r.stats.maxRelEnergyError)));
        const double p = momentumDrift(scene, r.trajectory);
        QVERIFY2(p <= 1e-8, qPrintable(QString::number(p)));
    }

    void longSymplecticPendulumHasBoundedEnergyError() {
        const Scene scene = hard("long_pendulum_symplectic.json");
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        const Trajectory& tr = r.trajectory;
        QCOMPARE(tr.t.back(), 1e4);
        const size_t tenth = tr.size() / 10;
        const double scale = std::abs(tr.E[0]);
        const double first = maxAbsDiff(tr.E, tr.E[0], 1, tenth) / scale;
        const double last = maxAbsDiff(tr.E, tr.E[0], tr.size() - tenth, tr.size()) / scale;
        QVERIFY2(last <= 1.2 * first && last < 1e-2, qPrintable(QString("first %1 last %2").arg(first).arg(last)));
        QVERIFY(first > 0);
        // the explicit Euler at the same step gains energy period after period
        Scene euler = scene;
        euler.simulation.integrator = "euler";
        euler.simulation.duration = 200;
        const SimulationResult re = simulate(euler);
        const Trajectory& te = re.trajectory;
        const double early = maxAbsDiff(te.E, te.E[0], 1, 20), late = std::abs(te.E.back() - te.E[0]);
        QVERIFY2(late > 5 * early, qPrintable(QString("euler early %1 late %2").arg(early).arg(late)));
        // and it is not silently wrong: the completed run carries a warning
        QCOMPARE(int(re.status), int(SimulationStatus::Completed));
        QVERIFY(re.stats.maxRelEnergyError > 1e-2);
        QVERIFY2(re.message.id == MessageId::EnergyBalanceOff, re.message.english().c_str());
        QVERIFY2(re.message.english().find("not accurate") != std::string::npos, re.message.english().c_str());
        QVERIFY(r.message.empty());
    }

    void stickSlipComesToRestWithoutGainingEnergy() {
        const Scene scene = hard("stick_slip.json");
        QCOMPARE(int(scene.effects.coulomb.at(0).model), int(CoulombModel::Stick));
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        const Trajectory& tr = r.trajectory;
        QVERIFY(finite(tr));
        size_t rest = tr.size();  // first sample from which q̇ stays exactly 0
        while (rest > 0 && tr.qd[rest - 1][0] == 0.0) --rest;
        QVERIFY2(rest < tr.size() && tr.t[rest] < scene.simulation.duration - 2,
                 qPrintable(QString("at rest from t = %1").arg(rest < tr.size() ? tr.t[rest] : -1)));
        for (size_t k = rest; k < tr.size(); ++k) QCOMPARE(tr.q[k][0], tr.q[rest][0]);  // stuck, no creep
        const double m = 1.0, g = 9.81, l = 1.0, Fc = scene.effects.coulomb[0].force;
        QVERIFY(std::abs(tr.q.back()[0]) <= std::asin(Fc / (m * g * l)) + 1e-9);  // friction can hold it there
        QVERIFY(std::abs(tr.q.back()[0]) > 1e-3);                                 // and it did not slide to the bottom
        for (size_t k = 1; k < tr.size(); ++k)
            QVERIFY2(tr.E[k] <= tr.E[k - 1] + 1e-9 * std::abs(tr.E[0]), qPrintable(QString("E rose at t = %1").arg(tr.t[k])));
        QVERIFY(tr.work.back() < -1.0);  // friction did the dissipating
        QVERIFY2(r.stats.maxRelEnergyError < 1e-6, qPrintable(QString::number(r.stats.maxRelEnergyError)));
        QVERIFY2(r.stats.steps < 100000, qPrintable(QString::number(r.stats.steps)));
        // other integrators, fixed step too, also stick
        for (const char* name : {"rk4", "fehlberg78", "bulirsch_stoer"}) {
            SimulationSettings s = scene.simulation;
            s.integrator = name;
            const SimulationResult o = simulate(scene, s);
            QCOMPARE(int(o.status), int(SimulationStatus::Completed));
            QVERIFY2(o.trajectory.qd.back()[0] == 0.0, name);
            QVERIFY2(std::abs(o.trajectory.q.back()[0] - tr.q.back()[0]) < 1e-3, name);
        }
        // the smooth tanh model never sticks: it creeps
        Scene smooth = scene;
        smooth.effects.coulomb[0].model = CoulombModel::Tanh;
        const Trajectory& ts = simulate(smooth).trajectory;
        QVERIFY(std::abs(ts.qd.back()[0]) > 1e-5);
        QVERIFY(ts.q.back()[0] != ts.q[ts.size() - 100][0]);
    }

    // Two coupled joints with stick friction (holding forces solved jointly, impulses on
    // the stuck set): every accurate integrator ends at rest in the same pose, and the
    // energy never rises between samples.
    void stickSlipOnTwoCoupledJoints() {
        Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + "/double_pendulum.json").scene;
        CoulombFriction a, b;
        a.joint = 0;
        a.force = 1.5;
        a.model = CoulombModel::Stick;
        b.joint = 1;
        b.force = 0.8;
        b.model = CoulombModel::Stick;
        scene.effects.coulomb = {a, b};
        scene.simulation.duration = 20;
        Eigen::VectorXd rest;
        for (const char* name : {"dopri5", "rk4", "cash_karp54", "fehlberg78", "bulirsch_stoer", "rosenbrock4"}) {
            SimulationSettings s = scene.simulation;
            s.integrator = name;
            const SimulationResult r = simulate(scene, s);
            QVERIFY2(r.status == SimulationStatus::Completed, qPrintable(QString("%1: %2").arg(name, r.message.english().c_str())));
            const Trajectory& tr = r.trajectory;
            QVERIFY2(tr.qd.back().isZero(0.0), name);
            for (size_t k = 1; k < tr.size(); ++k) QVERIFY2(tr.E[k] <= tr.E[k - 1] + 1e-9 * std::abs(tr.E[0]), name);
            QVERIFY2(r.stats.maxRelEnergyError < 1e-6, name);
            if (rest.size() == 0) rest = tr.q.back();
            QVERIFY2((tr.q.back() - rest).cwiseAbs().maxCoeff() < 1e-4, qPrintable(QString("%1 ends elsewhere").arg(name)));
        }
    }

    // The scene format keeps the model: serialised and parsed back, and a bad value names the field.
    void coulombModelIsReadAndWritten() {
        const Scene scene = hard("stick_slip.json");
        const std::string text = serializeScene(scene);
        QVERIFY(text.find("\"model\": \"stick\"") != std::string::npos);
        QCOMPARE(int(parseScene(text).effects.coulomb.at(0).model), int(CoulombModel::Stick));
        Scene smooth = scene;
        smooth.effects.coulomb[0].model = CoulombModel::Tanh;
        QVERIFY(serializeScene(smooth).find("\"model\"") == std::string::npos);  // the default is not written
        std::string bad = text;
        bad.replace(bad.find("\"stick\""), 7, "\"sticky\"");
        bool named = false;
        try {
            parseScene(bad);
        } catch (const InputError& e) {
            for (const Diagnostic& d : e.diagnostics())
                named = named ||
                        (d.field == "effects.coulomb[0].model" && d.message.english().find("\"tanh\" or \"stick\"") != std::string::npos);
        }
        QVERIFY(named);
    }

    void prismaticJointPassesZeroExtension() {
        const Scene scene = hard("prismatic_zero_extension.json");
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        const Trajectory& tr = r.trajectory;
        QVERIFY(finite(tr));
        double lo = 0, hi = 0;
        for (const Eigen::VectorXd& q : tr.q) {
            lo = std::min(lo, q[1]);
            hi = std::max(hi, q[1]);
        }
        QVERIFY(lo < -0.1 && hi > 0.1);  // it went through d = 0
        QVERIFY2(r.stats.maxRelEnergyError <= 1e-8, qPrintable(QString::number(r.stats.maxRelEnergyError)));
        const double p = momentumDrift(scene, tr);
        QVERIFY2(p <= 1e-8, qPrintable(QString::number(p)));
    }

    void pumaFromSingularPoseIsRegular() {
        const Scene scene = hard("puma560_singular_pose.json");
        RobotData data(scene.robot);
        forwardKinematics(scene.robot, data, scene.initial.q);
        Jacobian J(6, 6);
        pointJacobian(data, 5, data.T_0i[6].translation(), J);
        const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(J).singularValues();
        QVERIFY2(sv.minCoeff() < 1e-9 * sv.maxCoeff(), qPrintable(QString("sigma_min %1").arg(sv.minCoeff())));
        computeMassMatrix(scene.robot, data);
        QVERIFY(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(data.B).eigenvalues().minCoeff() > 0);
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        QVERIFY(finite(r.trajectory));
        QVERIFY2(r.stats.maxRelEnergyError <= 1e-7, qPrintable(QString::number(r.stats.maxRelEnergyError)));
        QVERIFY(std::abs(r.trajectory.E.front() - r.trajectory.E.back()) < 1e-6 * std::abs(r.trajectory.E.front()) + 1e-9);
    }

    void masslessJointIsRejectedBeforeIntegration() {
        bool thrown = false;
        try {
            loadScene(hardPath("massless_joint.json"));
        } catch (const InputError& e) {
            thrown = true;
            bool named = false;
            for (const Diagnostic& d : e.diagnostics())
                named = named || (d.severity == Severity::Error && d.field.find("robot.joints[1]") != std::string::npos &&
                                  d.message.english().find("moves no mass") != std::string::npos);
            QVERIFY2(named, e.what());
        }
        QVERIFY(thrown);
        // from the command line: exit code 2, the reason, and no trajectory at all
        QProcess p;
        p.start(LL_CLI, {"simulate", QString::fromStdString(hardPath("massless_joint.json"))});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(p.readAllStandardOutput().isEmpty());
        const QByteArray err = p.readAllStandardError();
        QVERIFY(err.contains("robot.joints[1]"));
        QVERIFY(isValidUtf8(err.toStdString()));
        // a model built in code that skips validation still stops at the first evaluation
        Scene scene;
        scene.robot.joints.resize(2);
        scene.robot.joints[0].dh.a = 1.0;
        scene.robot.joints[0].link.mass = 1.0;
        scene.robot.joints[0].link.com = {-0.5, 0, 0};
        scene.robot.joints[1].dh.a = 1.0;
        scene.initial.q = Eigen::Vector2d(0.5, 0);
        scene.initial.qd = Eigen::Vector2d(0, 0);
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Failed));
        QCOMPARE(r.stats.steps, 0L);
        QVERIFY2(r.message.english().find("joint 2") != std::string::npos, r.message.english().c_str());
        QVERIFY(finite(r.trajectory));
    }
};

LL_TEST_APPLESS_MAIN(TestHardCases)

}  // namespace test_hard_cases
#include "test_hard_cases.moc"
