// B(q): textbook closed form (planar 2R), CRBA against the independent Jacobian sum,
// and its columns against Newton–Euler (symmetric and positive definite there).
#include "test_registry.hpp"

#include <Eigen/Eigenvalues>

#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_mass_matrix {

using namespace ll;

class TestMassMatrix : public QObject {
    Q_OBJECT
private slots:
    // Siciliano et al. (7.82): b11 = I1 + m1ℓ1² + I2 + m2(a1² + ℓ2² + 2a1ℓ2c2), ...
    void planar2RClosedForm() {
        const test::Planar2R p;
        const RobotModel robot = p.model();
        RobotData data(robot);
        std::mt19937 rng(1);
        for (int trial = 0; trial < 100; ++trial) {
            const Eigen::VectorXd q = test::randomVector(rng, 2, 3.14);
            forwardKinematics(robot, data, q);
            computeMassMatrix(robot, data);
            const double c2 = std::cos(q[1]);
            Eigen::Matrix2d B;
            B(0, 0) = p.I1 + p.m1 * p.l1 * p.l1 + p.I2 + p.m2 * (p.a1 * p.a1 + p.l2 * p.l2 + 2 * p.a1 * p.l2 * c2);
            B(0, 1) = B(1, 0) = p.I2 + p.m2 * (p.l2 * p.l2 + p.a1 * p.l2 * c2);
            B(1, 1) = p.I2 + p.m2 * p.l2 * p.l2;
            QVERIFY2(test::scaledError(data.B, B) < 1e-13, qPrintable(QString::number(test::scaledError(data.B, B))));
        }
    }

    void crbaMatchesJacobianSum() {
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            std::mt19937 rng(5);
            for (int n : {1, 2, 4, 7}) {
                const RobotModel robot = test::randomRobot(rng, n, convention);
                RobotData data(robot);
                for (int trial = 0; trial < 30; ++trial) {
                    forwardKinematics(robot, data, test::randomVector(rng, n, 3.0));
                    computeMassMatrix(robot, data);
                    const Eigen::MatrixXd B = massMatrixFromJacobians(robot, data);
                    QVERIFY2(test::scaledError(data.B, B) < 1e-12, qPrintable(QString::number(test::scaledError(data.B, B))));
                }
            }
        }
    }

    // Column j of B is the torque that accelerates joint j alone from rest with no
    // gravity: B e_j = RNEA(q, 0, e_j), an algorithm that never forms B. Its columns are
    // not symmetric by construction, so B = Bᵀ here is the physics (reciprocity), and
    // B is positive definite (every motion has kinetic energy).
    void columnsAreNewtonEulerResponses() {
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            std::mt19937 rng(9);
            const int n = 7;
            const RobotModel robot = test::randomRobot(rng, n, convention);
            RobotData data(robot), rnea(robot);
            const Effects none;
            const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
            for (int trial = 0; trial < 50; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, n, 3.0);
                forwardKinematics(robot, data, q);
                computeMassMatrix(robot, data);
                Eigen::MatrixXd B(n, n);
                for (int j = 0; j < n; ++j) B.col(j) = inverseDynamics(robot, rnea, none, q, zero, Eigen::VectorXd::Unit(n, j));
                QVERIFY2(test::scaledError(B, B.transpose()) < 1e-12, qPrintable(QString::number(test::scaledError(B, B.transpose()))));
                QVERIFY2(test::scaledError(data.B, B) < 1e-12, qPrintable(QString::number(test::scaledError(data.B, B))));
                QVERIFY(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(B).eigenvalues().minCoeff() > 0);
            }
        }
    }
};

LL_TEST_APPLESS_MAIN(TestMassMatrix)

}  // namespace test_mass_matrix
#include "test_mass_matrix.moc"
