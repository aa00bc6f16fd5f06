// RNEA against the Lagrangian form τ = B q̈ + C q̇ + g (two independent routes).
#include "test_registry.hpp"

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/potential_gradient.hpp"
#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_inverse_dynamics {

using namespace ll;

class TestInverseDynamics : public QObject {
    Q_OBJECT
private slots:
    void newtonEulerEqualsLagrange() {
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            std::mt19937 rng(41);
            const int n = 7;
            const RobotModel robot = test::randomRobot(rng, n, convention);
            Effects effects;
            effects.gravity = Eigen::Vector3d(0.3, 0.2, -9.81);
            effects.springs = {{0, 12.0, 0.1}};
            RobotData data(robot), lagrange(robot);
            for (int trial = 0; trial < 100; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, n, 3.0), qd = test::randomVector(rng, n, 3.0),
                                      qdd = test::randomVector(rng, n, 5.0);
                const Eigen::VectorXd tau = inverseDynamics(robot, data, effects, q, qd, qdd);
                forwardKinematics(robot, lagrange, q);
                computeMassMatrix(robot, lagrange);
                computeCoriolisMatrix(robot, lagrange, qd);
                computePotentialGradient(robot, lagrange, effects, q);
                const Eigen::VectorXd expected = lagrange.B * qdd + lagrange.C * qd + lagrange.g;
                QVERIFY2(test::scaledError(tau, expected) < 1e-11, qPrintable(QString::number(test::scaledError(tau, expected))));
            }
        }
    }
};

LL_TEST_APPLESS_MAIN(TestInverseDynamics)

}  // namespace test_inverse_dynamics
#include "test_inverse_dynamics.moc"
