// Simulating hand-typed Lagrangian systems (LagrangianOde, compiled once): the course
// notes' mass–spring pair against its analytic normal-mode solution, with and without
// the torque (energy conserved; E − E0 = W = τ Δθ2), against the same system as a robot
// in relative angles, the elastic pendulum against its right-hand side written out,
// and a clean stop where the chosen coordinates become dependent.
#include "test_registry.hpp"

#include <chrono>
#include <fstream>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "core/io/scene_file.hpp"
#include "core/simulation/integrators.hpp"
#include "core/simulation/lagrangian_ode.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/symbolic/compiled_derivation.hpp"
#include "core/symbolic/derivation_evaluator.hpp"
#include "core/symbolic/lagrangian_derivation.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_lagrangian_ode {

using namespace ll;

namespace {

Scene example(const std::string& name) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + name).scene; }

// B q̈ + K q = Q with constant B, K, Q from rest at q0: q(t) = q* + V cos(Ωt) Vᵀ B (q0 − q*),
// with K V = B V Ω², Vᵀ B V = I and the equilibrium q* = K⁻¹ Q.
Eigen::Vector2d normalModes(const Eigen::Matrix2d& B, const Eigen::Matrix2d& K, const Eigen::Vector2d& Q, const Eigen::Vector2d& q0,
                            double t) {
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> modes(K, B);
    const Eigen::Matrix2d& V = modes.eigenvectors();
    const Eigen::Vector2d omega = modes.eigenvalues().cwiseSqrt();
    const Eigen::Vector2d equilibrium = K.inverse() * Q;
    const Eigen::Vector2d amplitude = V.transpose() * B * (q0 - equilibrium);
    return equilibrium + V * (omega * t).array().cos().matrix().cwiseProduct(amplitude);
}

struct Pair {
    double I1 = 0.5, I2 = 0.2, K1 = 10, K2 = 4, tau = 1;
    Eigen::Matrix2d B() const { return Eigen::Vector2d(I1, I2).asDiagonal(); }
    Eigen::Matrix2d K() const {
        Eigen::Matrix2d k;
        k << K1 + K2, -K2, -K2, K2;
        return k;
    }
};

}  // namespace

class TestLagrangianOde : public QObject {
    Q_OBJECT
private slots:
    void massSpringPairConservesEnergyAndFollowsNormalModes() {
        Scene scene = example("mass_spring_pair_lagrangian.json");
        scene.lagrangian->forces.clear();  // no τ
        scene.simulation.absTol = scene.simulation.relTol = 1e-11;
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        const Trajectory& tr = r.trajectory;
        QCOMPARE(tr.n, 2);
        QCOMPARE(int(tr.size()), 1001);
        QVERIFY2(r.stats.maxRelEnergyError < 1e-8, qPrintable(QString::number(r.stats.maxRelEnergyError)));
        QVERIFY(std::abs(tr.E[0] - 0.07) < 1e-12);  // ½ K1 0.1² + ½ K2 0.1²
        QCOMPARE(tr.work.back(), 0.0);
        const Pair p;
        double worst = 0;
        for (size_t k = 0; k < tr.size(); ++k)
            worst = std::max(worst, (tr.q[k] - normalModes(p.B(), p.K(), Eigen::Vector2d::Zero(), Eigen::Vector2d(0.1, 0), tr.t[k]))
                                        .cwiseAbs()
                                        .maxCoeff());
        QVERIFY2(worst < 1e-8, qPrintable(QString::number(worst)));
    }

    void torqueDoesWorkTauTimesDeltaTheta2() {
        Scene scene = example("mass_spring_pair_lagrangian.json");
        scene.simulation.absTol = scene.simulation.relTol = 1e-11;
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Completed));
        const Trajectory& tr = r.trajectory;
        const Pair p;
        double worstState = 0, worstWork = 0;
        for (size_t k = 0; k < tr.size(); ++k) {
            const Eigen::Vector2d exact = normalModes(p.B(), p.K(), Eigen::Vector2d(0, p.tau), Eigen::Vector2d(0.1, 0), tr.t[k]);
            worstState = std::max(worstState, (tr.q[k] - exact).cwiseAbs().maxCoeff());
            // Constant τ on θ2: W = τ (θ2 − θ2(0)), and E − E0 = W.
            worstWork = std::max(worstWork, std::abs(tr.work[k] - p.tau * (tr.q[k][1] - tr.q[0][1])));
            worstWork = std::max(worstWork, std::abs(tr.E[k] - tr.E[0] - tr.work[k]));
        }
        QVERIFY2(worstState < 1e-8, qPrintable(QString::number(worstState)));
        QVERIFY2(worstWork < 1e-8, qPrintable(QString::number(worstWork)));
        double maxWork = 0;
        for (double w : tr.work) maxWork = std::max(maxWork, std::abs(w));
        QVERIFY(maxWork > 0.1);  // τ really worked
    }

    // The same physics typed as a Lagrangian in absolute angles and read as a robot in
    // relative ones (θ1 = q1, θ2 = q1 + q2): the same motion.
    void agreesWithTheRobotScene() {
        const SimulationResult lagrangian = simulate(example("mass_spring_pair_lagrangian.json"));
        const SimulationResult robot = simulate(example("mass_spring_pair_torque.json"));
        QCOMPARE(lagrangian.trajectory.size(), robot.trajectory.size());
        double worst = 0;
        for (size_t k = 0; k < robot.trajectory.size(); ++k) {
            const Eigen::VectorXd& q = robot.trajectory.q[k];
            worst = std::max(worst, (lagrangian.trajectory.q[k] - Eigen::Vector2d(q[0], q[0] + q[1])).cwiseAbs().maxCoeff());
            worst = std::max(worst, std::abs(lagrangian.trajectory.E[k] - robot.trajectory.E[k]));
        }
        QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));
    }

    // The elastic pendulum's q̈ written out by hand, against the compiled right-hand side.
    void elasticPendulumRightHandSide() {
        const Scene scene = example("elastic_pendulum.json");
        LagrangianOde ode(symbolic::compileDerivation(symbolic::deriveLagrangian(scene, symbolic::ParameterMode::Numeric)));
        QCOMPARE(ode.coordinates(), 2);
        const double m = 1, k = 40, l0 = 1, g = 9.81;
        std::mt19937 rng(3);
        for (int trial = 0; trial < 50; ++trial) {
            const Eigen::VectorXd q = test::randomVector(rng, 2, 1.0) + Eigen::Vector2d(1.5, 0);
            const Eigen::VectorXd qd = test::randomVector(rng, 2, 2.0);
            OdeState x = ode.initialState(q, qd), dxdt(x.size());
            ode(x, dxdt, 0.3);
            const double r = q[0], phi = q[1], rd = qd[0], phid = qd[1];
            const double rdd = r * phid * phid + g * std::cos(phi) - k / m * (r - l0);
            const double phidd = -(2 * rd * phid + g * std::sin(phi)) / r;
            QVERIFY(std::abs(dxdt[0] - rd) < 1e-15 && std::abs(dxdt[1] - phid) < 1e-15);
            QVERIFY(std::abs(dxdt[2] - rdd) < 1e-12 * std::max(1.0, std::abs(rdd)));
            QVERIFY(std::abs(dxdt[3] - phidd) < 1e-12 * std::max(1.0, std::abs(phidd)));
            QCOMPARE(dxdt[4], 0.0);  // no Q: no power
        }
        QCOMPARE(ode.evaluations(), 50L);
        Scene tight = scene;
        tight.simulation.absTol = tight.simulation.relTol = 1e-11;
        const SimulationResult result = simulate(tight);
        QCOMPARE(int(result.status), int(SimulationStatus::Completed));
        QVERIFY2(result.stats.maxRelEnergyError < 1e-8, qPrintable(QString::number(result.stats.maxRelEnergyError)));
    }

    // E_kin = ½ m x² ẋ² keeps x ẋ constant: from x = 1, ẋ = −1, x reaches 0 (B = m x² singular)
    // at t = 0.5. The simulation stops there and says so, with partial data.
    void stopsWhereCoordinatesBecomeDependent() {
        Scene scene = parseScene(R"({"format": "lagrangelab-scene/1", "name": "degenerate", "parameters": {"m": 1},
            "lagrangian": {"coordinates": ["x"], "kinetic": "m*x^2*x_dot^2/2"},
            "initial": {"q": [1], "qd": [-1]}, "simulation": {"duration": 1}})");
        const SimulationResult r = simulate(scene);
        QCOMPARE(int(r.status), int(SimulationStatus::Failed));
        QVERIFY(!r.message.empty());
        QVERIFY(r.trajectory.t.back() < 0.5 + 1e-6);
        QVERIFY(r.trajectory.t.back() > 0.4);
    }

    // What compiling buys: one right-hand side against evaluating the derivation's B, C,
    // g and Q with GiNaC (subs + evalf), both for the elastic pendulum.
    void compiledRightHandSideIsFast() {
        const Scene scene = example("elastic_pendulum.json");
        const symbolic::Derivation d = symbolic::deriveLagrangian(scene, symbolic::ParameterMode::Parametric);
        LagrangianOde ode(symbolic::compileDerivation(d));
        const symbolic::DerivationEvaluator slow(d);
        OdeState x = ode.initialState(Eigen::Vector2d(1.3, 0.4), Eigen::Vector2d(0.2, -0.1)), dxdt(x.size());
        const auto perCall = [](auto&& f, int times) {
            const auto start = std::chrono::steady_clock::now();
            for (int i = 0; i < times; ++i) f(i);
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / times;
        };
        double sink = 0;
        const double compiled = perCall(
            [&](int i) {
                x[0] = 1.3 + 1e-7 * i;
                ode(x, dxdt, 0.0);
                sink += dxdt[2];
            },
            200000);
        const Eigen::VectorXd q(Eigen::Vector2d(1.3, 0.4)), qd(Eigen::Vector2d(0.2, -0.1));
        const double ginac = perCall(
            [&](int) {
                const Eigen::MatrixXd B = slow.value(d.B, q, qd), C = slow.value(d.C, q, qd), g = slow.value(d.g, q, qd),
                                      Q = slow.value(d.Q, q, qd);
                sink += (B.llt().solve(Q - C * qd - g))(0, 0);
            },
            200);
        qInfo("elastic pendulum right-hand side (%d instructions): compiled %.3g us, GiNaC B, C, g, Q %.3g us (%.0fx) [%g]",
              ode.model().dynamicsInstructions(), 1e6 * compiled, 1e6 * ginac, ginac / compiled, 0 * sink);
        QVERIFY(ginac > 100 * compiled);
    }
};

LL_TEST_APPLESS_MAIN(TestLagrangianOde)

}  // namespace test_lagrangian_ode
#include "test_lagrangian_ode.moc"
