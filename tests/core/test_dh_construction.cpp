// Step 0 shown rule by rule (core/visual/dh_construction): the steps are numbered as the
// window's --dh-from-axes reads them; the axes drawn at the first step are the robot's
// joint lines at home; each origin step draws the normal the rule took (perpendicular to
// both lines, its feet on them); at the end the frames drawn are the robot's own DH frames
// at home where its table is the rules' (the PUMA 560, the planar 2R), and a table made
// with another free choice is named row by row.
#include "test_registry.hpp"

#include <algorithm>

#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/visual/dh_construction.hpp"

namespace test_dh_construction {

using namespace ll;
using Eigen::Vector3d;

namespace {

RobotModel example(const char* file) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + file).scene.robot; }

std::vector<ConstructionMark> ofKind(const std::vector<ConstructionMark>& marks, ConstructionMarkKind kind) {
    std::vector<ConstructionMark> found;
    std::copy_if(marks.begin(), marks.end(), std::back_inserter(found), [&](const ConstructionMark& m) { return m.kind == kind; });
    return found;
}

double distanceToLine(const Vector3d& p, const JointAxis& line) {
    const Vector3d u = line.direction.normalized();
    return ((p - line.point) - (p - line.point).dot(u) * u).norm();
}

}  // namespace

class TestDhConstruction : public QObject {
    Q_OBJECT
private slots:
    // 0 the axes, then 4k + r for r rules done on frame k, to 4(n + 1).
    void stepsAreNumberedAsTheWindowReadsThem() {
        const DhConstruction c(example("puma560.json"));
        QCOMPARE(c.steps(), 4 * 7 + 1);
        QVERIFY(DhConstruction::step(0).rule == DhRule::Axes);
        const DhRule order[] = {DhRule::Z, DhRule::Origin, DhRule::X, DhRule::Y};
        for (int k = 0; k <= 6; ++k)
            for (int r = 1; r <= 4; ++r) {
                const DhConstructionStep s = DhConstruction::step(DhConstruction::index(k, r));
                QCOMPARE(s.frame, k);
                QVERIFY(s.rule == order[r - 1]);
            }
        // Row k is known once x_k is placed.
        QCOMPARE(c.rowsFound(DhConstruction::index(1, 2)), 0);
        QCOMPARE(c.rowsFound(DhConstruction::index(1, 3)), 1);
        QCOMPARE(c.rowsFound(DhConstruction::index(6, 4)), 6);
    }

    // The first picture: one line per joint, on that joint's axis at home, and no frame yet.
    void theAxesAreTheJointLines() {
        for (const char* file : {"puma560.json", "puma560_modified.json", "stanford_arm.json", "scara.json"}) {
            const RobotModel robot = example(file);
            const DhConstruction c(robot);
            RobotData data(robot);
            forwardKinematics(robot, data, Eigen::VectorXd::Zero(robot.dof()));
            const std::vector<ConstructionMark> marks = c.marks(0);
            const std::vector<ConstructionMark> lines = ofKind(marks, ConstructionMarkKind::Axis);
            QCOMPARE(int(lines.size()), robot.dof());
            QCOMPARE(int(marks.size()), robot.dof());
            for (int i = 0; i < robot.dof(); ++i) {
                const JointAxis axis{robot.joints[i].dh.type, data.axisPoint[i], data.axis[i]};
                for (const Vector3d& p : lines[i].points) QVERIFY2(distanceToLine(p, axis) < 1e-12, file);
                QVERIFY((lines[i].points[1] - lines[i].points[0]).normalized().dot(data.axis[i]) > 1 - 1e-12);
            }
        }
    }

    // Each origin step of a frame between two skew lines draws their common normal:
    // perpendicular to both, a foot on each, the new origin at one end.
    void theNormalIsCommonToBothLines() {
        int skew = 0;
        for (const char* file : {"puma560.json", "puma560_modified.json", "stanford_arm.json", "ur5.json", "panda.json"}) {
            const DhConstruction c(example(file));
            for (int k = 1; k < c.joints(); ++k) {
                if (c.found().frames[k].pair != AxisPair::Skew) continue;
                const std::vector<ConstructionMark> normals = ofKind(c.marks(DhConstruction::index(k, 2)), ConstructionMarkKind::Normal);
                QCOMPARE(int(normals.size()), 1);
                const Vector3d from = normals[0].points.front(), to = normals[0].points.back();
                const std::vector<int> lines = c.linesInUse(DhConstruction::index(k, 2));
                QCOMPARE(lines, (std::vector<int>{k, k + 1}));
                for (const int line : lines) {
                    const JointAxis& axis = c.axes().axes[line - 1];
                    QVERIFY(std::abs((to - from).normalized().dot(axis.direction.normalized())) < 1e-9);
                    QVERIFY(std::min(distanceToLine(from, axis), distanceToLine(to, axis)) < 1e-12);
                }
                const Vector3d origin = c.found().frames[k].origin;
                QVERIFY(std::min((from - origin).norm(), (to - origin).norm()) < 1e-12);
                ++skew;
            }
        }
        QVERIFY(skew >= 3);  // the PUMA's shoulder offsets, the Stanford arm's, the Panda's
    }

    // After the last rule the frames drawn are the robot's own DH frames at home (its table
    // is the rules'): each origin where T_k^0 puts it, x and z along its columns.
    void theFramesFoundAreTheRobotsOwn() {
        for (const char* file : {"puma560.json", "planar_2r.json"}) {
            const RobotModel robot = example(file);
            const DhConstruction c(robot);
            QVERIFY2(c.rowsDiffering().empty(), file);
            RobotData data(robot);
            forwardKinematics(robot, data, Eigen::VectorXd::Zero(robot.dof()));
            const std::vector<ConstructionMark> marks = c.marks(c.steps() - 1);
            const std::vector<ConstructionMark> origins = ofKind(marks, ConstructionMarkKind::Origin);
            const std::vector<ConstructionMark> xs = ofKind(marks, ConstructionMarkKind::FrameX),
                                                zs = ofKind(marks, ConstructionMarkKind::FrameZ);
            QCOMPARE(int(origins.size()), robot.dof() + 1);
            QCOMPARE(int(xs.size()), robot.dof() + 1);
            for (int k = 0; k <= robot.dof(); ++k) {
                const Eigen::Isometry3d& T = data.T_0i[k];
                QVERIFY((origins[k].points[0] - T.translation()).norm() < 1e-12);
                QVERIFY((xs[k].points[1] - xs[k].points[0]).normalized().dot(T.linear().col(0)) > 1 - 1e-12);
                QVERIFY((zs[k].points[1] - zs[k].points[0]).normalized().dot(T.linear().col(2)) > 1 - 1e-12);
            }
            // Only the frame being placed is named; the finished ones carry their number.
            QCOMPARE(QString::fromStdString(origins.back().label), QString("o%1").arg(QChar(0x2080 + robot.dof())));
            QCOMPARE(QString::fromStdString(origins.front().label), QString("0"));
        }
    }

    // A planar 3R whose second row has d₂ = 0.1 (parallel axes: the rules choose d = 0)
    // is another free choice: its table differs in row 2, said so.
    void anotherFreeChoiceIsNamed() {
        RobotModel robot = example("planar_2r.json");
        robot.joints.push_back(robot.joints.back());
        robot.joints[1].dh.d = 0.1;
        const DhConstruction c(robot);
        const std::vector<int> rows = c.rowsDiffering();
        QVERIFY(!rows.empty());
        QCOMPARE(rows.front(), 2);
        QCOMPARE(c.found().frames[2].pair, AxisPair::Parallel);
    }
};

LL_TEST_APPLESS_MAIN(TestDhConstruction)

}  // namespace test_dh_construction
#include "test_dh_construction.moc"
