// Geometric Jacobians against finite differences of the forward kinematics.
#include "test_registry.hpp"

#include "core/kinematics/forward_kinematics.hpp"
#include "core/kinematics/jacobians.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_jacobians {

using namespace ll;

class TestJacobians : public QObject {
    Q_OBJECT
private slots:
    void comJacobianMatchesFiniteDifferences() {
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            std::mt19937 rng(11);
            const int n = 6;
            const RobotModel robot = test::randomRobot(rng, n, convention);
            RobotData data(robot), plus(robot), minus(robot);
            Jacobian J;
            for (int trial = 0; trial < 20; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, n, 2.5);
                forwardKinematics(robot, data, q);
                const double h = 1e-6;
                for (int i = 0; i < n; ++i) {
                    comJacobian(data, i, J);
                    for (int k = 0; k < n; ++k) {
                        Eigen::VectorXd qp = q, qm = q;
                        qp[k] += h;
                        qm[k] -= h;
                        forwardKinematics(robot, plus, qp);
                        forwardKinematics(robot, minus, qm);
                        const Eigen::Vector3d v = (plus.p_ci[i] - minus.p_ci[i]) / (2 * h);
                        // ω from Ṙ Rᵀ = [ω]×
                        const Eigen::Matrix3d W =
                            (plus.T_0i[i + 1].linear() - minus.T_0i[i + 1].linear()) / (2 * h) * data.T_0i[i + 1].linear().transpose();
                        const Eigen::Vector3d w(W(2, 1), W(0, 2), W(1, 0));
                        QVERIFY2((J.block<3, 1>(0, k) - v).norm() < 1e-7, qPrintable(QString("J_v link %1 col %2").arg(i).arg(k)));
                        QVERIFY2((J.block<3, 1>(3, k) - w).norm() < 1e-7, qPrintable(QString("J_w link %1 col %2").arg(i).arg(k)));
                    }
                }
            }
        }
    }
};

LL_TEST_APPLESS_MAIN(TestJacobians)

}  // namespace test_jacobians
#include "test_jacobians.moc"
