// C(q, q̇) from Christoffel symbols: textbook closed form (planar 2R), exact ∂B/∂q and
// every Christoffel symbol against finite differences of B, Ḃ − 2C skew-symmetric, and
// the independent RNEA:
// since RNEA's bias h(v) = C(q, v) v is quadratic in v and the Christoffel C is
// the symmetric bilinear form behind it, C(q, q̇) x = (h(q̇ + x) − h(q̇ − x)) / 4.
#include "test_registry.hpp"

#include "core/dynamics/coriolis.hpp"
#include "core/dynamics/inverse_dynamics.hpp"
#include "core/dynamics/mass_matrix.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_coriolis {

using namespace ll;

namespace {
void evaluate(const RobotModel& robot, RobotData& data, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
    forwardKinematics(robot, data, q);
    computeMassMatrix(robot, data);
    computeCoriolisMatrix(robot, data, qd);
}

// B(q) by the CRBA, in the scratch `fd`.
Eigen::MatrixXd massMatrixAt(const RobotModel& robot, RobotData& fd, const Eigen::VectorXd& q) {
    forwardKinematics(robot, fd, q);
    computeMassMatrix(robot, fd);
    return fd.B;
}

// ∂B/∂q_k for every k by central differences of the CRBA's B (no exact derivatives).
std::vector<Eigen::MatrixXd> massMatrixDifferences(const RobotModel& robot, RobotData& fd, const Eigen::VectorXd& q, double step) {
    std::vector<Eigen::MatrixXd> dB;
    for (int k = 0; k < q.size(); ++k) {
        const Eigen::VectorXd e = step * Eigen::VectorXd::Unit(q.size(), k);
        dB.push_back((massMatrixAt(robot, fd, q + e) - massMatrixAt(robot, fd, q - e)) / (2 * step));
    }
    return dB;
}
}  // namespace

class TestCoriolis : public QObject {
    Q_OBJECT
private slots:
    // Siciliano et al. (7.83): h = −m2 a1 ℓ2 s2, C = [h q̇2, h(q̇1+q̇2); −h q̇1, 0].
    void planar2RClosedForm() {
        const test::Planar2R p;
        const RobotModel robot = p.model();
        RobotData data(robot);
        std::mt19937 rng(2);
        for (int trial = 0; trial < 100; ++trial) {
            const Eigen::VectorXd q = test::randomVector(rng, 2, 3.14), qd = test::randomVector(rng, 2, 4.0);
            evaluate(robot, data, q, qd);
            const double h = -p.m2 * p.a1 * p.l2 * std::sin(q[1]);
            Eigen::Matrix2d C;
            C << h * qd[1], h * (qd[0] + qd[1]), -h * qd[0], 0;
            QVERIFY2(test::scaledError(data.C, C) < 1e-13, qPrintable(QString::number(test::scaledError(data.C, C))));
        }
    }

    void massMatrixDerivativesMatchFiniteDifferences() {
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            std::mt19937 rng(21);
            const int n = 6;
            const RobotModel robot = test::randomRobot(rng, n, convention);
            RobotData data(robot), fd(robot);
            for (int trial = 0; trial < 20; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, n, 3.0);
                evaluate(robot, data, q, Eigen::VectorXd::Zero(n));
                const std::vector<Eigen::MatrixXd> differences = massMatrixDifferences(robot, fd, q, 1e-6);
                for (int k = 0; k < n; ++k) {
                    const Eigen::MatrixXd& dB = differences[k];
                    QVERIFY2(test::scaledError(data.dB_dq[k], dB) < 1e-7,
                             qPrintable(QString("k=%1 err=%2").arg(k).arg(test::scaledError(data.dB_dq[k], dB))));
                }
            }
        }
    }

    // Ḃ − 2C is skew-symmetric (Ḃ by central differences along q̇).
    void bDotMinusTwoCIsSkew() {
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            std::mt19937 rng(4);
            const int n = 7;
            const RobotModel robot = test::randomRobot(rng, n, convention);
            RobotData data(robot), fd(robot);
            for (int trial = 0; trial < 50; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, n, 3.0), qd = test::randomVector(rng, n, 3.0);
                evaluate(robot, data, q, qd);
                const double dt = 1e-6;
                const Eigen::MatrixXd Bdot = (massMatrixAt(robot, fd, q + dt * qd) - massMatrixAt(robot, fd, q - dt * qd)) / (2 * dt);
                const Eigen::MatrixXd N = Bdot - 2 * data.C;
                const double scale = std::max(1.0, data.C.cwiseAbs().maxCoeff());
                QVERIFY2((N + N.transpose()).cwiseAbs().maxCoeff() < 1e-6 * scale,
                         qPrintable(QString::number((N + N.transpose()).cwiseAbs().maxCoeff())));
                // and the exact ∂B/∂q give Ḃ = Σ_k ∂B/∂q_k q̇_k, so the identity holds to rounding
                Eigen::MatrixXd BdotExact = Eigen::MatrixXd::Zero(n, n);
                for (int k = 0; k < n; ++k) BdotExact += data.dB_dq[k] * qd[k];
                const Eigen::MatrixXd Ne = BdotExact - 2 * data.C;
                QVERIFY((Ne + Ne.transpose()).cwiseAbs().maxCoeff() < 1e-12 * scale);
            }
        }
    }

    void matchesPolarisedNewtonEuler() {
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            std::mt19937 rng(8);
            const int n = 6;
            const RobotModel robot = test::randomRobot(rng, n, convention);
            RobotData data(robot), rnea(robot);
            const Effects none;
            const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
            for (int trial = 0; trial < 50; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, n, 3.0), qd = test::randomVector(rng, n, 3.0);
                evaluate(robot, data, q, qd);
                Eigen::MatrixXd C(n, n);
                for (int j = 0; j < n; ++j) {
                    const Eigen::VectorXd e = Eigen::VectorXd::Unit(n, j);
                    const Eigen::VectorXd hp = inverseDynamics(robot, rnea, none, q, qd + e, zero);
                    const Eigen::VectorXd hm = inverseDynamics(robot, rnea, none, q, qd - e, zero);
                    C.col(j) = (hp - hm) / 4;
                }
                QVERIFY2(test::scaledError(data.C, C) < 1e-11, qPrintable(QString::number(test::scaledError(data.C, C))));
            }
        }
    }

    // Each Christoffel symbol Γ_ijk = ½(∂b_ij/∂q_k + ∂b_ik/∂q_j − ∂b_jk/∂q_i) against the
    // same formula over ∂B/∂q from central differences of the CRBA's B (no exact
    // derivatives involved), and C = Σ_k Γ_ijk q̇_k built from those values.
    void christoffelSymbolsMatchFiniteDifferencesOfB() {
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            std::mt19937 rng(12);
            const int n = 5;
            const RobotModel robot = test::randomRobot(rng, n, convention);
            RobotData data(robot), fd(robot);
            for (int trial = 0; trial < 10; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, n, 3.0), qd = test::randomVector(rng, n, 3.0);
                evaluate(robot, data, q, qd);
                const std::vector<Eigen::MatrixXd> dB = massMatrixDifferences(robot, fd, q, 1e-5);
                Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
                double worst = 0.0;
                for (int i = 0; i < n; ++i)
                    for (int j = 0; j < n; ++j)
                        for (int k = 0; k < n; ++k) {
                            const double gamma = 0.5 * (dB[k](i, j) + dB[j](i, k) - dB[i](j, k));
                            worst = std::max(worst, std::abs(christoffel(data, i, j, k) - gamma));
                            C(i, j) += gamma * qd[k];
                        }
                const double scale = std::max(1.0, data.B.cwiseAbs().maxCoeff());
                QVERIFY2(worst < 1e-7 * scale, qPrintable(QString::number(worst)));
                QVERIFY2(test::scaledError(data.C, C) < 1e-7, qPrintable(QString::number(test::scaledError(data.C, C))));
            }
        }
    }
};

LL_TEST_APPLESS_MAIN(TestCoriolis)

}  // namespace test_coriolis
#include "test_coriolis.moc"
