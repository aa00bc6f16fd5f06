// The small unblocked Cholesky against Eigen's LLT, its detection of matrices that
// are not positive definite, and in-place solves with several right-hand sides.
#include "test_registry.hpp"

#include <Eigen/Cholesky>

#include "core/math/cholesky.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_cholesky {

using namespace ll;

namespace {
Eigen::MatrixXd randomSpd(std::mt19937& rng, int n, double condition) {
    const Eigen::MatrixXd A = Eigen::MatrixXd::NullaryExpr(n, n, [&] { return std::uniform_real_distribution<double>(-1, 1)(rng); });
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(A);
    const Eigen::MatrixXd Q = qr.householderQ();
    Eigen::VectorXd d(n);
    for (int i = 0; i < n; ++i) d[i] = std::pow(condition, -double(i) / std::max(1, n - 1));
    return Q * d.asDiagonal() * Q.transpose();
}
}  // namespace

class TestCholesky : public QObject {
    Q_OBJECT
private slots:
    void agreesWithEigen() {
        std::mt19937 rng(3);
        for (int n : {1, 2, 6, 7, 12})
            for (double condition : {1.0, 1e4, 1e8}) {
                const Eigen::MatrixXd B = randomSpd(rng, n, condition);
                Cholesky chol(n);
                QCOMPARE(int(chol.compute(B).info()), int(Eigen::Success));
                const Eigen::MatrixXd L = chol.matrixL().triangularView<Eigen::Lower>();
                QVERIFY((L * L.transpose() - B).norm() < 1e-14 * B.norm() * n);
                Eigen::VectorXd x = test::randomVector(rng, n, 1.0);
                const Eigen::VectorXd b = x;
                chol.solveInPlace(x);
                // backward stable: the residual is small even when B is ill-conditioned
                QVERIFY2((B * x - b).norm() <= 1e-12 * b.norm() * std::max(1.0, B.norm() * x.norm() / b.norm()),
                         qPrintable(QString("n %1 cond %2").arg(n).arg(condition)));
                const Eigen::VectorXd eigen = B.llt().solve(b);
                QVERIFY((x - eigen).norm() <= 1e-15 * condition * 100 * eigen.norm());
            }
    }

    void solvesSeveralColumnsInPlace() {
        std::mt19937 rng(4);
        const Eigen::MatrixXd B = randomSpd(rng, 5, 10.0);
        Cholesky chol(5);
        chol.compute(B);
        Eigen::MatrixXd X = Eigen::MatrixXd::Identity(5, 5);
        chol.solveInPlace(X);
        QVERIFY((B * X - Eigen::MatrixXd::Identity(5, 5)).norm() < 1e-12);
    }

    void detectsMatricesThatAreNotPositiveDefinite() {
        Eigen::Matrix2d indefinite;
        indefinite << 1, 2, 2, 1;  // eigenvalues 3 and −1
        Cholesky chol(2);
        QCOMPARE(int(chol.compute(indefinite).info()), int(Eigen::NumericalIssue));
        Eigen::Matrix3d singular = Eigen::Matrix3d::Zero();
        singular(0, 0) = 1;
        QCOMPARE(int(Cholesky(3).compute(singular).info()), int(Eigen::NumericalIssue));
        Eigen::Matrix2d nan;
        nan << std::nan(""), 0, 0, 1;
        QCOMPARE(int(chol.compute(nan).info()), int(Eigen::NumericalIssue));
    }
};

LL_TEST_APPLESS_MAIN(TestCholesky)

}  // namespace test_cholesky
#include "test_cholesky.moc"
