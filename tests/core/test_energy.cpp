// E_kin = ½ q̇ᵀ B q̇ against the sum over links ½(m v_cᵀ v_c + ωᵀ I ω) with
// velocities from finite differences of the kinematics (no Jacobians, no B).
#include "test_registry.hpp"

#include "core/dynamics/energy.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_energy {

using namespace ll;

class TestEnergy : public QObject {
    Q_OBJECT
private slots:
    void kineticEnergyIsTheSumOverLinks() {
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            std::mt19937 rng(31);
            const int n = 6;
            const RobotModel robot = test::randomRobot(rng, n, convention);
            RobotData data(robot), plus(robot), minus(robot);
            for (int trial = 0; trial < 30; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, n, 3.0), qd = test::randomVector(rng, n, 2.0);
                forwardKinematics(robot, data, q);
                computeMassMatrix(robot, data);
                const double dt = 1e-6;
                forwardKinematics(robot, plus, q + dt * qd);
                forwardKinematics(robot, minus, q - dt * qd);
                double E = 0;
                for (int i = 0; i < n; ++i) {
                    const Eigen::Vector3d v = (plus.p_ci[i] - minus.p_ci[i]) / (2 * dt);
                    const Eigen::Matrix3d W =
                        (plus.T_0i[i + 1].linear() - minus.T_0i[i + 1].linear()) / (2 * dt) * data.T_0i[i + 1].linear().transpose();
                    const Eigen::Vector3d w(W(2, 1), W(0, 2), W(1, 0));
                    E += 0.5 * (robot.joints[i].link.mass * v.squaredNorm() + w.dot(data.I_li0[i] * w));
                }
                const double Ekin = kineticEnergy(data, qd);
                QVERIFY2(std::abs(Ekin - E) < 1e-7 * std::max(1.0, E), qPrintable(QString("%1 vs %2").arg(Ekin).arg(E)));
            }
        }
    }
};

LL_TEST_APPLESS_MAIN(TestEnergy)

}  // namespace test_energy
#include "test_energy.moc"
