// DH transforms against their definition as products of elementary motions, for
// both conventions and both joint types.
#include "test_registry.hpp"

#include "core/kinematics/forward_kinematics.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_forward_kinematics {

using namespace ll;

namespace {
Eigen::Isometry3d rotX(double a) { return Eigen::Isometry3d(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX())); }
Eigen::Isometry3d rotZ(double a) { return Eigen::Isometry3d(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ())); }
Eigen::Isometry3d transX(double x) { return Eigen::Isometry3d(Eigen::Translation3d(x, 0, 0)); }
Eigen::Isometry3d transZ(double z) { return Eigen::Isometry3d(Eigen::Translation3d(0, 0, z)); }
}  // namespace

class TestForwardKinematics : public QObject {
    Q_OBJECT
private slots:
    void matchesElementaryProducts_data() {
        QTest::addColumn<int>("convention");
        QTest::newRow("standard") << int(DhConvention::Standard);
        QTest::newRow("modified") << int(DhConvention::Modified);
    }
    void matchesElementaryProducts() {
        QFETCH(int, convention);
        std::mt19937 rng(7);
        const RobotModel robot = test::randomRobot(rng, 6, DhConvention(convention));
        RobotData data(robot);
        for (int trial = 0; trial < 50; ++trial) {
            const Eigen::VectorXd q = test::randomVector(rng, 6, 3.0);
            forwardKinematics(robot, data, q);
            Eigen::Isometry3d T = robot.base;
            for (int i = 0; i < 6; ++i) {
                const DhRow& r = robot.joints[i].dh;
                const bool rev = r.type == JointType::Revolute;
                const double theta = r.theta + (rev ? q[i] : 0), d = r.d + (rev ? 0 : q[i]);
                T = T * (DhConvention(convention) == DhConvention::Standard ? rotZ(theta) * transZ(d) * transX(r.a) * rotX(r.alpha)
                                                                            : rotX(r.alpha) * transX(r.a) * rotZ(theta) * transZ(d));
                QVERIFY2((T.matrix() - data.T_0i[i + 1].matrix()).norm() < 1e-12, qPrintable(QString("frame %1").arg(i + 1)));
                QVERIFY((data.p_ci[i] - T * robot.joints[i].link.com).norm() < 1e-12);
            }
        }
    }

    // Joint i turns about z_{i-1} (standard) or z_i (modified): moving q_i rotates
    // every later frame about that axis through that point.
    void jointAxisIsTheRotationAxis() {
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            std::mt19937 rng(3);
            const RobotModel robot = test::randomRobot(rng, 5, convention, false);
            RobotData a(robot), b(robot);
            const Eigen::VectorXd q = test::randomVector(rng, 5, 2.0);
            forwardKinematics(robot, a, q);
            for (int j = 0; j < 5; ++j) {
                Eigen::VectorXd q2 = q;
                q2[j] += 0.3;
                forwardKinematics(robot, b, q2);
                const Eigen::Isometry3d rot =
                    Eigen::Translation3d(a.axisPoint[j]) * Eigen::AngleAxisd(0.3, a.axis[j]) * Eigen::Translation3d(-a.axisPoint[j]);
                const Eigen::Isometry3d expected = rot * a.T_0i[5];
                QVERIFY((expected.matrix() - b.T_0i[5].matrix()).norm() < 1e-12);
            }
        }
    }

    void planarArmReachesTextbookPosition() {
        const test::Planar2R arm;
        const RobotModel robot = arm.model();
        RobotData data(robot);
        const Eigen::Vector2d q(0.3, -1.1);
        forwardKinematics(robot, data, q);
        const Eigen::Vector3d tip(arm.a1 * std::cos(q[0]) + arm.a2 * std::cos(q[0] + q[1]),
                                  arm.a1 * std::sin(q[0]) + arm.a2 * std::sin(q[0] + q[1]), 0);
        QVERIFY((data.T_0i[2].translation() - tip).norm() < 1e-14);
        const Eigen::Vector3d com1(arm.l1 * std::cos(q[0]), arm.l1 * std::sin(q[0]), 0);
        QVERIFY((data.p_ci[0] - com1).norm() < 1e-14);
    }
};

LL_TEST_APPLESS_MAIN(TestForwardKinematics)

}  // namespace test_forward_kinematics
#include "test_forward_kinematics.moc"
