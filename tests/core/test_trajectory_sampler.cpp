// Cubic Hermite sampling of a recorded trajectory: exact at the samples and for cubic
// motions, fourth-order local error on a real simulation, frame times on the grid.
#include "test_registry.hpp"

#include <cmath>

#include "core/io/scene_file.hpp"
#include "core/visual/trajectory_sampler.hpp"
#include "core/pipeline/scene_simulation.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_trajectory_sampler {

using namespace ll;

class TestTrajectorySampler : public QObject {
    Q_OBJECT

    // q(t) = c0 + c1 t + c2 t² + c3 t³ per coordinate, sampled at uneven times.
    static Trajectory cubic(const std::vector<double>& times) {
        Trajectory tr;
        tr.n = 2;
        for (double t : times) {
            Eigen::VectorXd q(2), qd(2);
            q << 1 + 2 * t - 3 * t * t + 0.5 * t * t * t, -0.2 + t * t * t;
            qd << 2 - 6 * t + 1.5 * t * t, 3 * t * t;
            tr.t.push_back(t);
            tr.q.push_back(q);
            tr.qd.push_back(qd);
            tr.E.push_back(10 * t);
        }
        return tr;
    }

private slots:
    void exactForCubicMotion() {
        const Trajectory tr = cubic({0.0, 0.1, 0.35, 0.4, 1.0});
        const TrajectorySampler sampler(tr);
        Eigen::VectorXd q(2), qd(2);
        for (double t = 0; t <= 1.0; t += 0.0137) {
            sampler.sample(t, q, qd);
            QVERIFY(std::abs(q[0] - (1 + 2 * t - 3 * t * t + 0.5 * t * t * t)) < 1e-12);
            QVERIFY(std::abs(q[1] - (-0.2 + t * t * t)) < 1e-12);
            QVERIFY(std::abs(qd[0] - (2 - 6 * t + 1.5 * t * t)) < 1e-12);
            QVERIFY(std::abs(qd[1] - 3 * t * t) < 1e-12);
        }
        QCOMPARE(sampler.scalar(tr.E, 0.2), 2.0);  // linear between samples
    }

    void exactAtSamplesAndClampedOutside() {
        const Trajectory tr = cubic({0.0, 0.5, 1.0});
        const TrajectorySampler sampler(tr);
        Eigen::VectorXd q(2), qd(2);
        for (size_t k = 0; k < tr.size(); ++k) {
            sampler.sample(tr.t[k], q, qd);
            QCOMPARE(q, tr.q[k]);
        }
        sampler.sample(-1.0, q, qd);
        QCOMPARE(q, tr.q.front());
        sampler.sample(7.0, q, qd);
        QCOMPARE(q, tr.q.back());
    }

    // A chaotic double pendulum recorded at 100 Hz and at 20 Hz: the 20 Hz record
    // sampled between its samples lands on the 100 Hz one within the Hermite error
    // O(h⁴ q⁗) (h = 0.05 s), and halving h shrinks the error about 16-fold.
    void fourthOrderOnARealSimulation() {
        Scene scene = loadScene(LL_EXAMPLES_DIR "/double_pendulum.json").scene;
        SimulationSettings settings = scene.simulation;
        settings.duration = 2.0;
        settings.absTol = settings.relTol = 1e-11;
        settings.outputRate = 100;
        const Trajectory fine = simulate(scene, settings).trajectory;
        const auto maxError = [&](double rate) {
            SimulationSettings coarse = settings;
            coarse.outputRate = rate;
            const Trajectory tr = simulate(scene, coarse).trajectory;
            const TrajectorySampler sampler(tr);
            Eigen::VectorXd q(2), qd(2);
            double error = 0;
            for (size_t k = 0; k < fine.size(); ++k) {
                sampler.sample(fine.t[k], q, qd);
                error = std::max(error, (q - fine.q[k]).cwiseAbs().maxCoeff());
            }
            return error;
        };
        const double e20 = maxError(20), e40 = maxError(40);
        qInfo("max |q - q_ref|: %.3g at 20 Hz, %.3g at 40 Hz (ratio %.1f)", e20, e40, e20 / e40);
        QVERIFY(e20 < 1e-2);
        QVERIFY(e20 / e40 > 8);  // fourth order: 16; a first- or second-order scheme gives 2 or 4
    }

    void frameTimesOnTheGrid() {
        const std::vector<double> t = frameTimes(0.0, 1.0, 10, 1.0);
        QCOMPARE(static_cast<int>(t.size()), 10);
        QCOMPARE(t[3], 0.3);
        QCOMPARE(t.back(), 0.9);
        const std::vector<double> slow = frameTimes(2.0, 1.0, 30, 0.25);  // slow motion: 4 s of video
        QCOMPARE(static_cast<int>(slow.size()), 120);
        QVERIFY(std::abs(slow[1] - (2.0 + 0.25 / 30)) < 1e-15);
        QCOMPARE(static_cast<int>(frameTimes(0, 0.001, 10, 1).size()), 1);
    }
};

LL_TEST_APPLESS_MAIN(TestTrajectorySampler)

}  // namespace test_trajectory_sampler
#include "test_trajectory_sampler.moc"
