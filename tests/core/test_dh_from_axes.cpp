// Step 0 by the textbook's rules (core/kinematics/dh_from_axes): the DH table found from
// the joint axes reproduces the axes' own forward kinematics (each joint turning or
// sliding everything after it about or along its line) at random q, frame by frame, in
// both conventions, over random robots and every special case of two neighbouring
// axes; and the example robots' axes give their own tables back.
#include "test_registry.hpp"

#include <random>

#include "core/io/scene_file.hpp"
#include "core/kinematics/axes_at_home.hpp"
#include "core/kinematics/dh_from_axes.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_dh_from_axes {

using namespace ll;
using Eigen::Vector3d;

namespace {

RobotModel modelOf(const DhFromAxes& dh) {
    RobotModel robot;
    robot.convention = dh.convention;
    robot.base = dh.base;
    for (const DhRow& row : dh.rows) {
        Joint joint;
        joint.dh = row;
        joint.link.mass = 1.0;
        robot.joints.push_back(joint);
    }
    return robot;
}

// The largest difference between the DH model's frames and tool and the axes' own at q:
// frame i rides on link i, so it is the joints 1..i's motion of where it was at home.
double largestDifference(const AxesDescription& axes, const DhFromAxes& dh, const Eigen::VectorXd& q) {
    const RobotModel robot = modelOf(dh);
    RobotData data(robot);
    forwardKinematics(robot, data, q);
    double worst = ((data.T_0i.back() * dh.tool).matrix() - toolPoseFromAxes(axes, q).matrix()).cwiseAbs().maxCoeff();
    for (std::size_t i = 1; i < dh.frames.size(); ++i) {
        AxesDescription upToI;
        upToI.axes.assign(axes.axes.begin(), axes.axes.begin() + static_cast<long>(i));
        Eigen::Isometry3d home = Eigen::Isometry3d::Identity();
        home.linear() << dh.frames[i].x, dh.frames[i].z.cross(dh.frames[i].x), dh.frames[i].z;
        home.translation() = dh.frames[i].origin;
        upToI.tool = home;
        const Eigen::Isometry3d moved = toolPoseFromAxes(upToI, q.head(static_cast<Eigen::Index>(i)));
        worst = std::max(worst, (moved.matrix() - data.T_0i[i].matrix()).cwiseAbs().maxCoeff());
    }
    return worst;
}

Vector3d randomPoint(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(-0.8, 0.8);
    return {u(rng), u(rng), u(rng)};
}

Vector3d randomDirection(std::mt19937& rng) {
    std::normal_distribution<double> g;
    return Vector3d(g(rng), g(rng), g(rng)).normalized();
}

// A tool frame somewhere, turned somehow.
Eigen::Isometry3d randomPose(std::mt19937& rng) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    std::normal_distribution<double> g;
    T.linear() = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
    T.translation() = randomPoint(rng);
    return T;
}

// The axes of a DH model at home (q = 0) and its last frame as the tool.
}  // namespace

class TestDhFromAxes : public QObject {
    Q_OBJECT
private slots:
    // 40 random robots of 1 to 7 joints (a third prismatic) with their lines anywhere,
    // each at 20 random q: every frame and the tool where the axes put them, ≤ 1e-12.
    void randomAxesReproduceTheirKinematics() {
        std::mt19937 rng(11);
        std::uniform_int_distribution<int> joints(1, 7), kind(0, 2);
        double worst = 0;
        for (int robot = 0; robot < 40; ++robot) {
            AxesDescription axes;
            const int n = joints(rng);
            for (int i = 0; i < n; ++i)
                axes.axes.push_back({kind(rng) == 0 ? JointType::Prismatic : JointType::Revolute, randomPoint(rng), randomDirection(rng)});
            axes.tool = randomPose(rng);
            for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
                const DhFromAxes dh = dhFromAxes(axes, convention);
                QCOMPARE(int(dh.rows.size()), n);
                for (int trial = 0; trial < 20; ++trial)
                    worst = std::max(worst, largestDifference(axes, dh, test::randomVector(rng, n, 3.0)));
            }
        }
        qInfo("largest difference %.2e", worst);
        QVERIFY2(worst <= 1e-12, qPrintable(QString::number(worst)));
    }

    // Two neighbouring axes in each case the rules name, as the only two joints of an arm
    // with its tool off the last axis: the case said, α and a as the geometry has them,
    // and the kinematics reproduced.
    void everyCaseOfTwoAxes_data() {
        QTest::addColumn<Vector3d>("point2");
        QTest::addColumn<Vector3d>("direction2");
        QTest::addColumn<int>("type2");
        QTest::addColumn<int>("pair");
        QTest::addColumn<double>("alpha");  // |α| between the two axes
        QTest::addColumn<double>("a");      // their distance
        const int revolute = int(JointType::Revolute), prismatic = int(JointType::Prismatic);
        QTest::newRow("skew") << Vector3d(0, 0.3, 0.5) << Vector3d(1, 0, 0) << revolute << int(AxisPair::Skew) << M_PI / 2 << 0.3;
        QTest::newRow("intersecting") << Vector3d(0, 0, 0.4) << Vector3d(0, 1, 0) << revolute << int(AxisPair::Intersecting) << M_PI / 2
                                      << 0.0;
        QTest::newRow("intersecting at 30°") << Vector3d(0, 0, 0.4) << Vector3d(0, std::sin(M_PI / 6), std::cos(M_PI / 6)) << revolute
                                             << int(AxisPair::Intersecting) << M_PI / 6 << 0.0;
        QTest::newRow("parallel") << Vector3d(1, 0, 0.2) << Vector3d(0, 0, 1) << revolute << int(AxisPair::Parallel) << 0.0 << 1.0;
        QTest::newRow("antiparallel") << Vector3d(0.5, 0, 0.2) << Vector3d(0, 0, -1) << revolute << int(AxisPair::Parallel) << M_PI << 0.5;
        QTest::newRow("coincident (a cylindrical joint)")
            << Vector3d(0, 0, 0.7) << Vector3d(0, 0, 2) << prismatic << int(AxisPair::Coincident) << 0.0 << 0.0;
        QTest::newRow("coincident, antiparallel")
            << Vector3d(0, 0, -0.3) << Vector3d(0, 0, -1) << revolute << int(AxisPair::Coincident) << M_PI << 0.0;
        QTest::newRow("prismatic, skew") << Vector3d(0.2, 0.4, 0) << Vector3d(1, 1, 0) << prismatic << int(AxisPair::Skew) << M_PI / 2
                                         << std::sqrt(0.02);
    }
    void everyCaseOfTwoAxes() {
        QFETCH(Vector3d, point2);
        QFETCH(Vector3d, direction2);
        QFETCH(int, type2);
        QFETCH(int, pair);
        QFETCH(double, alpha);
        QFETCH(double, a);
        AxesDescription axes;
        axes.axes.push_back({JointType::Revolute, Vector3d(0, 0, 0), Vector3d(0, 0, 1)});
        axes.axes.push_back({JointType(type2), point2, direction2});
        axes.tool = Eigen::Translation3d(0.4, -0.2, 1.1) * Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized());
        std::mt19937 rng(5);
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            const DhFromAxes dh = dhFromAxes(axes, convention);
            // standard: frame 1 is placed by joints 1 and 2; modified: frame 1 too (on joint 1's line)
            QCOMPARE(int(dh.frames[1].pair), pair);
            QCOMPARE(int(dh.frames[2].pair), int(AxisPair::Last));
            const DhRow& between = convention == DhConvention::Standard ? dh.rows[0] : dh.rows[1];
            QVERIFY2(std::abs(std::abs(between.alpha) - alpha) < 1e-12, qPrintable(QString::number(between.alpha)));
            QVERIFY2(std::abs(between.a - a) < 1e-12, qPrintable(QString::number(between.a)));
            QCOMPARE(dh.frames[1].antiparallel, alpha > 3);
            QVERIFY(dh.base.isApprox(Eigen::Isometry3d::Identity(), 1e-12));  // joint 1 is the world's z
            for (int trial = 0; trial < 20; ++trial) {
                const double difference = largestDifference(axes, dh, test::randomVector(rng, 2, 3.0));
                QVERIFY2(difference <= 1e-12, qPrintable(QString::number(difference)));
            }
        }
    }

    // The example robots' axes at home and their last frame as the tool: in their own
    // convention the rules give back the same kinematics, the same |a| and |α| row by row
    // (a is a distance: a −0.425 comes back as 0.425 with θ turned by π), and the PUMA 560's
    // and the planar 2R's tables exactly, with no base or tool transform. (The free choices
    // differ elsewhere: the SCARA's d1 sits in d4, Corke's modified PUMA puts 0.672 in d1.)
    void examplesGiveTheirTablesBack() {
        std::mt19937 rng(9);
        for (const char* file :
             {"planar_2r.json", "puma560.json", "puma560_modified.json", "stanford_arm.json", "scara.json", "ur5.json", "panda.json"}) {
            const RobotModel robot = loadScene(std::string(LL_EXAMPLES_DIR) + "/" + file).scene.robot;
            const DhFromAxes dh = dhFromAxes(axesAtHome(robot), robot.convention);
            const RobotModel rebuilt = modelOf(dh);
            RobotData original(robot), found(rebuilt);
            for (int trial = 0; trial < 20; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, robot.dof(), 3.0);
                forwardKinematics(robot, original, q);
                forwardKinematics(rebuilt, found, q);
                const double difference = ((found.T_0i.back() * dh.tool).matrix() - original.T_0i.back().matrix()).cwiseAbs().maxCoeff();
                QVERIFY2(difference <= 1e-12, qPrintable(QString("%1: %2").arg(file).arg(difference)));
            }
            const bool exact = QByteArray(file) == "puma560.json" || QByteArray(file) == "planar_2r.json";
            for (int i = 0; i < robot.dof(); ++i) {
                const DhRow &given = robot.joints[i].dh, &rule = dh.rows[i];
                const QString where = QString("%1 row %2: a %3 / %4, α %5 / %6, d %7 / %8, θ %9 / %10")
                                          .arg(file)
                                          .arg(i + 1)
                                          .arg(given.a)
                                          .arg(rule.a)
                                          .arg(given.alpha)
                                          .arg(rule.alpha)
                                          .arg(given.d)
                                          .arg(rule.d)
                                          .arg(given.theta)
                                          .arg(rule.theta);
                QVERIFY2(std::abs(std::abs(given.a) - rule.a) < 1e-12, qPrintable(where));
                QVERIFY2(std::abs(std::abs(given.alpha) - std::abs(rule.alpha)) < 1e-12, qPrintable(where));
                if (exact)
                    QVERIFY2(std::abs(given.alpha - rule.alpha) + std::abs(given.d - rule.d) + std::abs(given.theta - rule.theta) < 1e-12,
                             qPrintable(where));
            }
            if (exact)
                QVERIFY(dh.base.isApprox(Eigen::Isometry3d::Identity(), 1e-12) && dh.tool.isApprox(Eigen::Isometry3d::Identity(), 1e-12));
        }
    }
};

LL_TEST_APPLESS_MAIN(TestDhFromAxes)

}  // namespace test_dh_from_axes
#include "test_dh_from_axes.moc"
