// The DH step-through against an independent product of elementary motions: after each
// motion the frame is frame i−1 times the motions so far (rotations and translations
// written here from their definitions), after all four it is frame i of forward
// kinematics, for both conventions, revolute and prismatic joints, and the examples.
#include "test_registry.hpp"

#include "core/io/scene_file.hpp"
#include "core/kinematics/dh_step_through.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/visual/dh_dimensions.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_dh_step_through {

using namespace ll;

namespace {
Eigen::Matrix4d rotX(double a) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m(1, 1) = std::cos(a), m(1, 2) = -std::sin(a), m(2, 1) = std::sin(a), m(2, 2) = std::cos(a);
    return m;
}
Eigen::Matrix4d rotZ(double a) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m(0, 0) = std::cos(a), m(0, 1) = -std::sin(a), m(1, 0) = std::sin(a), m(1, 1) = std::cos(a);
    return m;
}
Eigen::Matrix4d trans(int axis, double x) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m(axis, 3) = x;
    return m;
}
// Row i's motions in the order the convention reads them.
std::vector<Eigen::Matrix4d> motionsOf(const RobotModel& robot, int i, double q) {
    const DhRow& r = robot.joints[i].dh;
    const bool rev = r.type == JointType::Revolute;
    const double theta = r.theta + (rev ? q : 0), d = r.d + (rev ? 0 : q);
    if (robot.convention == DhConvention::Standard) return {rotZ(theta), trans(2, d), trans(0, r.a), rotX(r.alpha)};
    return {rotX(r.alpha), trans(0, r.a), rotZ(theta), trans(2, d)};
}

void checkRobot(const RobotModel& robot, const Eigen::VectorXd& q) {
    RobotData data(robot);
    forwardKinematics(robot, data, q);
    for (int i = 0; i < robot.dof(); ++i) {
        const std::vector<Eigen::Matrix4d> motions = motionsOf(robot, i, q[i]);
        Eigen::Matrix4d expected = data.T_0i[i].matrix();
        for (int k = 0; k <= 4; ++k) {
            if (k > 0) expected = expected * motions[k - 1];
            const double error = (steppedFrame(robot, data, q, i, k).matrix() - expected).cwiseAbs().maxCoeff();
            QVERIFY2(error <= 1e-12, qPrintable(QString("joint %1 after %2 motions: %3").arg(i + 1).arg(k).arg(error)));
        }
        const double toFk = (steppedFrame(robot, data, q, i, 4).matrix() - data.T_0i[i + 1].matrix()).cwiseAbs().maxCoeff();
        QVERIFY2(toFk <= 1e-12, qPrintable(QString("joint %1: %2 from T_%1^0").arg(i + 1).arg(toFk)));
        // Half of the next motion, done twice, is the whole motion (half its angle or length).
        for (int k = 0; k < 4; ++k) {
            const Eigen::Matrix4d half = (steppedFrame(robot, data, q, i, k).inverse() * steppedFrame(robot, data, q, i, k, 0.5)).matrix();
            QVERIFY((half * half - motions[k]).cwiseAbs().maxCoeff() < 1e-12);
        }
    }
}
}  // namespace

class TestDhStepThrough : public QObject {
    Q_OBJECT
private slots:
    void randomRobots_data() {
        QTest::addColumn<int>("convention");
        QTest::newRow("standard") << int(DhConvention::Standard);
        QTest::newRow("modified") << int(DhConvention::Modified);
    }
    void randomRobots() {
        QFETCH(int, convention);
        std::mt19937 rng(11);
        for (int trial = 0; trial < 20; ++trial) {
            const RobotModel robot = test::randomRobot(rng, 6, DhConvention(convention));  // joints 3 and 6 prismatic
            checkRobot(robot, test::randomVector(rng, 6, 3.0));
        }
    }

    void examples_data() {
        QTest::addColumn<QString>("file");
        for (const char* f : {"puma560.json", "puma560_modified.json", "panda.json", "stanford_arm.json", "scara.json", "ur5.json"})
            QTest::newRow(f) << QString(f);
    }
    void examples() {
        QFETCH(QString, file);
        const Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + "/" + file.toStdString()).scene;
        checkRobot(scene.robot, scene.initial.q);
        std::mt19937 rng(3);
        checkRobot(scene.robot, test::randomVector(rng, scene.dof(), 2.0));
    }

    // The static view: every parameter on the robot. A length is an arrow as long as its
    // value; an angle is an arc of the given radius about the frame's origin, whose end
    // points along x_i (θ_i) or z_i (α), in both conventions; zero parameters are left out;
    // labels name the table's entries (modified: a0, α0 on row 1).
    void dimensionsDrawTheTable_data() { examples_data(); }
    void dimensionsDrawTheTable() {
        QFETCH(QString, file);
        const Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + "/" + file.toStdString()).scene;
        const RobotModel& robot = scene.robot;
        std::mt19937 rng(9);
        const Eigen::VectorXd q = test::randomVector(rng, scene.dof(), 2.0);
        RobotData data(robot);
        forwardKinematics(robot, data, q);
        const double r = 0.07;
        const std::vector<DhDimension> dims = dhDimensions(robot, data, q, r);
        int expected = 0;
        for (int j = 0; j < robot.dof(); ++j)
            for (const ElementaryMotion& m : elementaryMotions(robot, j, q[j])) expected += std::abs(m.amount) > 1e-9;
        QCOMPARE(int(dims.size()), expected);
        const bool standard = robot.convention == DhConvention::Standard;
        for (const DhDimension& d : dims) {
            const Eigen::Isometry3d& next = data.T_0i[d.joint + 1];
            if (!d.angle) {
                QCOMPARE(int(d.points.size()), 2);
                QVERIFY(std::abs((d.points[1] - d.points[0]).norm() - std::abs(d.value)) < 1e-12);
                if (d.parameter == DhParameter::A && standard) QVERIFY((d.points[1] - next.translation()).norm() < 1e-12);
                if (d.parameter == DhParameter::D && !standard) QVERIFY((d.points[1] - next.translation()).norm() < 1e-12);
            } else {
                // The arc ends r along the turned axis (x_i for θ, z_i for α) from its centre;
                // every point is r from that centre; the chord is 2 r |sin(value / 2)|.
                const Eigen::Vector3d turned = d.parameter == DhParameter::Theta ? next.linear().col(0) : next.linear().col(2);
                const Eigen::Vector3d centre = d.points.back() - r * turned;
                for (const Eigen::Vector3d& p : d.points) QVERIFY(std::abs((p - centre).norm() - r) < 1e-12);
                QVERIFY(std::abs((d.points.back() - d.points.front()).norm() - 2 * r * std::abs(std::sin(d.value / 2))) < 1e-12);
                // About the right origin: standard θ_i at o_{i−1}, α_i at o_i; modified α_{i−1} at o_{i−1}.
                if (standard && d.parameter == DhParameter::Theta) QVERIFY((centre - data.T_0i[d.joint].translation()).norm() < 1e-12);
                if (standard && d.parameter == DhParameter::Alpha) QVERIFY((centre - next.translation()).norm() < 1e-12);
                if (!standard && d.parameter == DhParameter::Alpha) QVERIFY((centre - data.T_0i[d.joint].translation()).norm() < 1e-12);
            }
            const std::string index =
                std::to_string(d.joint + (standard || d.parameter == DhParameter::D || d.parameter == DhParameter::Theta ? 1 : 0));
            QVERIFY2(d.label.find(index + " = ") != std::string::npos, d.label.c_str());
        }
    }

    // The motions name the table's columns in the convention's order.
    void motionsNameTheirParameters() {
        std::mt19937 rng(5);
        const RobotModel standard = test::randomRobot(rng, 3, DhConvention::Standard);
        const RobotModel modified = test::randomRobot(rng, 3, DhConvention::Modified);
        const auto s = elementaryMotions(standard, 0, 0.3), m = elementaryMotions(modified, 0, 0.3);
        const DhParameter sOrder[] = {DhParameter::Theta, DhParameter::D, DhParameter::A, DhParameter::Alpha};
        const DhParameter mOrder[] = {DhParameter::Alpha, DhParameter::A, DhParameter::Theta, DhParameter::D};
        for (int k = 0; k < 4; ++k) {
            QCOMPARE(int(s[k].parameter), int(sOrder[k]));
            QCOMPARE(int(m[k].parameter), int(mOrder[k]));
        }
        QCOMPARE(s[0].amount, standard.joints[0].dh.theta + 0.3);  // joint 1 revolute: q adds to θ
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, elementaryMotions(standard, 3, 0.0));
    }
};

LL_TEST_APPLESS_MAIN(TestDhStepThrough)

}  // namespace test_dh_step_through
#include "test_dh_step_through.moc"
