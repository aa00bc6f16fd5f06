// Where the torque goes (core/simulation/torque_parts): on every example the parts
// B q̈ + C q̇ + g of each joint sum to its Q (the simulation's q̈ by recursive Newton–Euler
// against the Christoffel C and the potential's gradient: ≤ 1e-9 of the largest part);
// Q's parts are the declared effects' laws (viscous −b q̇, Coulomb against the motion);
// the simple pendulum's parts are its closed forms m ℓ² q̈ and m g ℓ sin q.
#include "test_registry.hpp"

#include <filesystem>

#include "core/io/scene_file.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/simulation/torque_parts.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_torque_parts {

using namespace ll;

namespace {

Scene exampleScene(const std::string& path) { return loadScene(path).scene; }

}  // namespace

class TestTorqueParts : public QObject {
    Q_OBJECT

private slots:
    void partsSumToQ_data() {
        QTest::addColumn<QString>("path");
        for (const char* folder : {"", "hard/"})
            for (const auto& entry : std::filesystem::directory_iterator(std::string(LL_EXAMPLES_DIR) + "/" + folder))
                if (entry.path().extension() == ".json" && entry.path().filename() != "massless_joint.json")
                    QTest::newRow(entry.path().filename().c_str()) << QString::fromStdString(entry.path().string());
    }
    void partsSumToQ() {
        QFETCH(QString, path);
        const Scene scene = exampleScene(path.toStdString());
        SimulationSettings settings = scene.simulation;
        settings.duration = std::min(settings.duration, 2.0);
        const SimulationInput input = prepareSimulation(scene);
        const SimulationResult run = simulate(input, settings);
        const TorqueHistory history = torqueHistory(input, run.trajectory);
        QCOMPARE(history.parts.size(), run.trajectory.size());
        QVERIFY(history.scale > 0);
        double worst = 0;
        for (const TorqueParts& p : history.parts)
            worst = std::max(worst, (p.inertial + p.coriolis + p.potential - p.Q()).cwiseAbs().maxCoeff());
        QCOMPARE(worst, history.largestResidual);
        qInfo("largest residual %.2e of scale %.3g", history.largestResidual, history.scale);
        QVERIFY(history.largestResidual <= 1e-9 * history.scale);
    }

    // The simple pendulum (m, ℓ, g from the scene's parameters): B q̈ = m ℓ² q̈,
    // g = m g₀ ℓ sin q, no Coriolis part, no Q.
    void pendulumClosedForms() {
        const Scene scene = exampleScene(std::string(LL_EXAMPLES_DIR) + "/simple_pendulum.json");
        const SimulationInput input = prepareSimulation(scene);
        SimulationSettings settings = scene.simulation;
        settings.duration = 1.0;
        const SimulationResult run = simulate(input, settings);
        const TorqueHistory history = torqueHistory(input, run.trajectory);
        const double m = scene.robot.joints[0].link.mass;
        const double l = (scene.robot.joints[0].link.com + Eigen::Vector3d(scene.robot.joints[0].dh.a, 0, 0)).norm();
        const double g0 = scene.effects.gravity->norm();
        for (std::size_t k = 0; k < history.parts.size(); k += 7) {
            const TorqueParts& p = history.parts[k];
            const double q = run.trajectory.q[k][0];
            QVERIFY(std::abs(p.coriolis[0]) <= 1e-12);
            QVERIFY(std::abs(p.Q()[0]) <= 1e-12);
            QVERIFY(std::abs(std::abs(p.potential[0]) - m * g0 * l * std::abs(std::sin(q))) <= 1e-9 * m * g0 * l);
            // m ℓ² q̈ = −m g ℓ sin q (the pendulum's equation, point mass plus the link's own inertia I_zz)
            const double Izz = scene.robot.joints[0].link.inertia(2, 2);
            QVERIFY(std::abs(p.inertial[0] - (m * l * l + Izz) * p.qdd[0]) <= 1e-9 * m * g0 * l);
        }
    }

    // The damped pendulum's viscous part is −b q̇ at every sample; its Coulomb part opposes q̇.
    void viscousPartIsTheLaw() {
        const Scene scene = exampleScene(std::string(LL_EXAMPLES_DIR) + "/damped_pendulum.json");
        QVERIFY(!scene.effects.viscous.empty());
        const SimulationInput input = prepareSimulation(scene);
        SimulationSettings settings = scene.simulation;
        settings.duration = 1.0;
        const SimulationResult run = simulate(input, settings);
        const TorqueHistory history = torqueHistory(input, run.trajectory);
        const ViscousFriction& f = scene.effects.viscous[0];
        for (std::size_t k = 0; k < history.parts.size(); ++k) {
            const double expected = -f.coefficient * run.trajectory.qd[k][f.joint];
            QVERIFY(std::abs(history.parts[k].viscous[f.joint] - expected) <= 1e-12 * std::max(1.0, std::abs(expected)));
            // Coulomb friction opposes the motion and never exceeds its force
            for (const CoulombFriction& c : scene.effects.coulomb) {
                const double part = history.parts[k].coulomb[c.joint], v = run.trajectory.qd[k][c.joint];
                QVERIFY(part * v <= 0);
                QVERIFY(std::abs(part) <= c.force * (1 + 1e-12));
            }
        }
    }

    void wrongTrajectoryIsRefused() {
        const Scene scene = exampleScene(std::string(LL_EXAMPLES_DIR) + "/planar_2r.json");
        Trajectory t;
        t.n = 3;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, torqueHistory(prepareSimulation(scene), t));
    }
};

LL_TEST_GUILESS_MAIN(TestTorqueParts)

}  // namespace test_torque_parts
#include "test_torque_parts.moc"
