// g(q) = ∂E_pot/∂q: planar 2R closed form, gradient of E_pot, springs, and only
// declared effects.
#include "test_registry.hpp"

#include "core/dynamics/energy.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_potential_gradient {

using namespace ll;

class TestPotentialGradient : public QObject {
    Q_OBJECT
private slots:
    // Siciliano et al. (7.84) with g0 = [0, −g, 0].
    void planar2RClosedForm() {
        const test::Planar2R p;
        const RobotModel robot = p.model();
        RobotData data(robot);
        Effects effects;
        const double g = 9.81;
        effects.gravity = Eigen::Vector3d(0, -g, 0);
        std::mt19937 rng(3);
        for (int trial = 0; trial < 100; ++trial) {
            const Eigen::VectorXd q = test::randomVector(rng, 2, 3.14);
            forwardKinematics(robot, data, q);
            computePotentialGradient(robot, data, effects, q);
            const double c1 = std::cos(q[0]), c12 = std::cos(q[0] + q[1]);
            const Eigen::Vector2d expected((p.m1 * p.l1 + p.m2 * p.a1) * g * c1 + p.m2 * p.l2 * g * c12, p.m2 * p.l2 * g * c12);
            QVERIFY(test::scaledError(data.g, expected) < 1e-13);
            const double Epot = p.m1 * g * p.l1 * std::sin(q[0]) + p.m2 * g * (p.a1 * std::sin(q[0]) + p.l2 * std::sin(q[0] + q[1]));
            QVERIFY(std::abs(potentialEnergy(robot, data, effects, q) - Epot) < 1e-13);
        }
    }

    void isTheGradientOfPotentialEnergy() {
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            std::mt19937 rng(13);
            const int n = 6;
            const RobotModel robot = test::randomRobot(rng, n, convention);
            Effects effects;
            effects.gravity = Eigen::Vector3d(1.2, -0.7, -9.5);
            effects.springs = {{1, 30.0, 0.2}, {4, 5.0, -0.1}};
            RobotData data(robot), fd(robot);
            for (int trial = 0; trial < 30; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, n, 3.0);
                forwardKinematics(robot, data, q);
                computePotentialGradient(robot, data, effects, q);
                Eigen::VectorXd gradient(n);
                for (int k = 0; k < n; ++k) {
                    const double h = 1e-6;
                    Eigen::VectorXd qp = q, qm = q;
                    qp[k] += h;
                    qm[k] -= h;
                    forwardKinematics(robot, fd, qp);
                    const double Ep = potentialEnergy(robot, fd, effects, qp);
                    forwardKinematics(robot, fd, qm);
                    gradient[k] = (Ep - potentialEnergy(robot, fd, effects, qm)) / (2 * h);
                }
                QVERIFY2(test::scaledError(data.g, gradient) < 1e-7, qPrintable(QString::number(test::scaledError(data.g, gradient))));
            }
        }
    }

    void undeclaredEffectsContributeNothing() {
        std::mt19937 rng(17);
        const RobotModel robot = test::randomRobot(rng, 4, DhConvention::Standard);
        RobotData data(robot);
        const Eigen::VectorXd q = test::randomVector(rng, 4, 3.0);
        forwardKinematics(robot, data, q);
        computePotentialGradient(robot, data, Effects{}, q);
        QCOMPARE(data.g.norm(), 0.0);
        QCOMPARE(potentialEnergy(robot, data, Effects{}, q), 0.0);
        Effects springOnly;
        springOnly.springs = {{2, 40.0, 0.5}};
        computePotentialGradient(robot, data, springOnly, q);
        QCOMPARE(data.g[2], 40.0 * (q[2] - 0.5));
        QCOMPARE(data.g[0], 0.0);
    }
};

LL_TEST_APPLESS_MAIN(TestPotentialGradient)

}  // namespace test_potential_gradient
#include "test_potential_gradient.moc"
