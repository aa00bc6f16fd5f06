// URDF in (core/io/urdf_import): the test robots of tests/urdf (written for these tests,
// each with its known DH table in its comment) become scenes whose B(q), C(q, q̇) q̇ and
// g(q) equal KDL's, read from the same file by kdl_parser (an independent route over the
// URDF's own frames, fixed links as segments of their own), at random states, in both
// conventions; the tables are the known ones; what a DH chain cannot hold is refused with
// the joint or link named.
#include "test_registry.hpp"

#include <filesystem>
#include <fstream>
#include <random>

#include <QTemporaryDir>

#include <kdl/chaindynparam.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/tree.hpp>
#include <kdl_parser/kdl_parser.hpp>

#include "core/io/scene_file.hpp"
#include "core/io/urdf_export.hpp"
#include "core/io/urdf_import.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/diagnostics.hpp"
#include "core/pipeline/scene_evaluation.hpp"
#include "core/present/message_text.hpp"
#include "test_support.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_urdf_import {

using namespace ll;

namespace {

std::string urdf(const char* name) { return std::string(LL_SOURCE_DIR) + "/tests/urdf/" + name; }

// max |a − b| / max(1, max |b|)
double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

// B, C q̇ and g at one state.
struct Terms {
    Eigen::MatrixXd B;
    Eigen::VectorXd Cqd, g;
};

// KDL's, from its chain (fails the test when a solver does).
Terms kdlTerms(KDL::ChainDynParam& kdl, const Eigen::VectorXd& q, const Eigen::VectorXd& qd) {
    const unsigned n = static_cast<unsigned>(q.size());
    KDL::JntArray kq(n), kqd(n), c(n), g(n);
    kq.data = q;
    kqd.data = qd;
    KDL::JntSpaceInertiaMatrix H(n);
    if (kdl.JntToMass(kq, H) != 0 || kdl.JntToCoriolis(kq, kqd, c) != 0 || kdl.JntToGravity(kq, g) != 0) qFatal("a KDL solver failed");
    return {H.data, c.data, g.data};
}

// The largest relative difference of ours from `other` over B, C q̇ and g.
double largestDifference(const SceneEvaluation& ours, const Terms& other, const Eigen::VectorXd& qd) {
    return std::max({relative(ours.terms.B, other.B), relative(ours.terms.C * qd, other.Cqd), relative(ours.terms.g, other.g)});
}

// The InputError's first diagnostic as a reader sees it, in English.
std::string refusal(const std::string& xml, const UrdfImportOptions& options = {}) {
    try {
        importUrdf(xml, "robot.urdf", options);
    } catch (const InputError& e) {
        return e.diagnostics().front().field + ": " + present::messageText(e.diagnostics().front().message, present::Language::English);
    }
    return "accepted";
}

}  // namespace

class TestUrdfImport : public QObject {
    Q_OBJECT
private slots:
    void sameDynamicsAsKdl_data() {
        QTest::addColumn<QString>("file");
        for (const char* f : {"planar_2r.urdf", "puma_like.urdf", "ur_like.urdf", "stanford_like.urdf", "antiparallel.urdf"})
            QTest::newRow(f) << QString(f);
    }
    void sameDynamicsAsKdl() {
        QFETCH(QString, file);
        const std::string path = urdf(qPrintable(file));
        KDL::Tree tree;
        QVERIFY(kdl_parser::treeFromFile(path, tree));
        std::mt19937 rng(17);
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            UrdfImportOptions options;
            options.convention = convention;
            const UrdfImport imported = importUrdfFile(path, options);
            KDL::Chain chain;
            QVERIFY(tree.getChain(imported.baseLink, imported.tipLink, chain));
            const int n = imported.scene.dof();
            QCOMPARE(int(chain.getNrOfJoints()), n);
            KDL::ChainDynParam kdl(chain, KDL::Vector(0, 0, -9.81));
            double worst = 0;
            for (int trial = 0; trial < 25; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, n, 2.5), qd = test::randomVector(rng, n, 2.0);
                worst = std::max(worst, largestDifference(evaluateScene(imported.scene, q, qd, 0.0, std::nullopt), kdlTerms(kdl, q, qd), qd));
            }
            qInfo("%s (%s): largest relative difference %.2e", qPrintable(file), toString(convention), worst);
            QVERIFY2(worst <= 1e-9, qPrintable(QString::number(worst)));
        }
    }

    // Scene → URDF → scene keeps the dynamics: every example robot written by export-urdf
    // and read back (in both conventions) has the example's B, C q̇ and g at random states,
    // and so does KDL's reading of the written file (so the URDF says what it should to a
    // reader that is not ours). The examples' gravity along −y (the planar 2R) goes through
    // the turned "world" root. The PUMA's motors and the Stanford arm's boom spring have no
    // place in URDF: they are compared without them, and a note each says so.
    void exportedAndImportedKeepsTheDynamics() {
        std::mt19937 rng(23);
        for (const char* file :
             {"planar_2r.json", "puma560.json", "puma560_modified.json", "stanford_arm.json", "scara.json", "ur5.json", "panda.json"}) {
            Scene original = loadScene(std::string(LL_EXAMPLES_DIR) + "/" + file).scene;
            const UrdfExport written = exportUrdf(original);
            std::size_t leftOut = original.effects.springs.size() + original.effects.torques.size();
            for (Joint& joint : original.robot.joints) {
                leftOut += joint.motor.armature() != 0.0;
                joint.motor = {};
            }
            original.effects.springs.clear();
            original.effects.torques.clear();
            QCOMPARE(written.notes.size(), leftOut);
            KDL::Tree tree;
            QVERIFY(kdl_parser::treeFromString(written.xml, tree));
            for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
                UrdfImportOptions options;
                options.convention = convention;
                const UrdfImport back = importUrdf(written.xml, file, options);
                const int n = original.dof();
                QCOMPARE(back.scene.dof(), n);
                KDL::Chain chain;
                QVERIFY(tree.getChain(back.baseLink, back.tipLink, chain));
                KDL::ChainDynParam kdl(chain, KDL::Vector(0, 0, -9.81));
                double worst = 0, worstKdl = 0;
                for (int trial = 0; trial < 10; ++trial) {
                    const Eigen::VectorXd q = test::randomVector(rng, n, 2.5), qd = test::randomVector(rng, n, 2.0);
                    Scene a = original, b = back.scene;
                    a.effects.viscous.clear();  // friction is Q, not B, C or g
                    a.effects.coulomb.clear();
                    b.effects.viscous.clear();
                    b.effects.coulomb.clear();
                    const SceneEvaluation want = evaluateScene(a, q, qd, 0.0, std::nullopt);
                    const SceneEvaluation got = evaluateScene(b, q, qd, 0.0, std::nullopt);
                    worst = std::max(worst, largestDifference(got, {want.terms.B, want.terms.C * qd, want.terms.g}, qd));
                    worstKdl = std::max(worstKdl, largestDifference(want, kdlTerms(kdl, q, qd), qd));
                }
                QVERIFY2(worst <= 1e-9 && worstKdl <= 1e-9,
                         qPrintable(QString("%1 %2: ours %3, KDL %4").arg(file).arg(toString(convention)).arg(worst).arg(worstKdl)));
            }
        }
    }

    // Gravity is the root link's −z, seen from the base link: the planar 2R written by
    // export-urdf hangs under a "world" root turned so that its −y is down; imported from
    // its own "base" link, the scene's gravity is −9.81 along y again, and g(q) the 2R's.
    void gravityFromTheRootSeenFromTheBase() {
        const Scene original = loadScene(std::string(LL_EXAMPLES_DIR) + "/planar_2r.json").scene;
        UrdfImportOptions fromBase;
        fromBase.base = "base";
        const UrdfImport imported = importUrdf(exportUrdf(original).xml, "planar_2r.urdf", fromBase);
        QVERIFY(imported.scene.effects.gravity && (*imported.scene.effects.gravity - Eigen::Vector3d(0, -9.81, 0)).norm() < 1e-12);
        const Eigen::VectorXd q = Eigen::Vector2d(0.4, -1.1), qd = Eigen::Vector2d::Zero();
        const Eigen::VectorXd want = evaluateScene(original, q, qd, 0.0, std::nullopt).terms.g;
        QVERIFY((evaluateScene(imported.scene, q, qd, 0.0, std::nullopt).terms.g - want).norm() < 1e-9 * want.norm());
    }

    // What a DH chain cannot hold, or a file that is no URDF: one line naming it.
    void refusals() {
        const std::string head = R"(<robot name="r"><link name="base"/><link name="a"/><link name="b"/>)";
        const std::string twoBranches = head + R"(<joint name="ja" type="revolute"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/>
            <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
            <joint name="jb" type="continuous"><parent link="base"/><child link="b"/><axis xyz="0 1 0"/></joint></robot>)";
        QVERIFY2(refusal(twoBranches)
                         .find("robot.urdf: the robot branches at link base into a, b: choose the chain's last link with --tip LINK") == 0,
                 refusal(twoBranches).c_str());
        UrdfImportOptions tipB;
        tipB.tip = "b";
        QCOMPARE(refusal(twoBranches, tipB), std::string("accepted"));  // --tip chooses; the other branch is left out
        QCOMPARE(importUrdf(twoBranches, "robot.urdf", tipB).notes.size(), std::size_t(1));
        UrdfImportOptions unknown;
        unknown.tip = "c";
        QCOMPARE(refusal(twoBranches, unknown), std::string("--tip: no link named c (the robot's links: a, b, base)"));
        const std::string floating = head + R"(<joint name="free" type="floating"><parent link="base"/><child link="a"/></joint>
            <joint name="jb" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 1 0"/></joint></robot>)";
        QCOMPARE(refusal(floating),
                 std::string("robot.urdf: joint free is floating: a DH chain has revolute, continuous, prismatic and fixed joints only"));
        const std::string mimic =
            head + R"(<joint name="ja" type="continuous"><parent link="base"/><child link="a"/><axis xyz="0 0 1"/></joint>
            <joint name="jb" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/><mimic joint="ja"/></joint></robot>)";
        QCOMPARE(refusal(mimic),
                 std::string("robot.urdf: joint jb mimics joint ja: it is not a coordinate of its own, which a DH chain needs"));
        const std::string notFinite = head + R"(<joint name="ja" type="continuous"><parent link="base"/><child link="a"/>
            <origin xyz="0 nan 1"/><axis xyz="0 0 1"/></joint>
            <joint name="jb" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 1 0"/></joint></robot>)";
        QVERIFY2(refusal(notFinite).find("robot.urdf: <joint name=\"ja\"> <origin>: value is not finite") == 0 ||
                     refusal(notFinite).find("not a URDF robot") != std::string::npos,
                 refusal(notFinite).c_str());
        const std::string fixedOnly = R"(<robot name="r"><link name="base"/><link name="a"/>
            <joint name="ja" type="fixed"><parent link="base"/><child link="a"/></joint></robot>)";
        QVERIFY2(refusal(fixedOnly).find("no moving joint between links base and a") != std::string::npos, refusal(fixedOnly).c_str());
        QVERIFY2(refusal("<robot name=\"r\"><link name=\"a\"></robot>").find("robot.urdf: not a URDF robot: ") == 0,
                 refusal("<robot>").c_str());
        const std::string xacro = R"(<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro"><xacro:macro name="m"/></robot>)";
        QVERIFY2(refusal(xacro).find("not a URDF robot") != std::string::npos, refusal(xacro).c_str());
        try {
            importUrdf(xacro, "arm.urdf.xacro", {});
        } catch (const InputError& e) {
            QVERIFY(
                present::messageText(e.diagnostics().front().hint, present::Language::English).find("xacro arm.urdf.xacro > robot.urdf") !=
                std::string::npos);
        }
    }

    // Each test robot's known DH table (its file's comment), standard convention: a, |α|
    // (the sign of α at intersecting axes is the rule's free choice), d and θ offsets; the
    // case of every frame; the UR-like's gripper lumped into link 6.
    void knownTables_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QVector<double>>("a");
        QTest::addColumn<QVector<double>>("alpha");
        QTest::addColumn<QVector<double>>("d");
        QTest::addColumn<QVector<double>>("theta");
        QTest::addColumn<QVector<int>>("cases");
        const double h = M_PI / 2, p = M_PI;
        const int skew = int(AxisPair::Skew), cross = int(AxisPair::Intersecting), par = int(AxisPair::Parallel),
                  same = int(AxisPair::Coincident), last = int(AxisPair::Last);
        QTest::newRow("planar 2R") << QString("planar_2r.urdf") << QVector<double>{1, 0.8} << QVector<double>{0, 0} << QVector<double>{0, 0}
                                   << QVector<double>{0, 0} << QVector<int>{par, last};
        QTest::newRow("PUMA-like") << QString("puma_like.urdf") << QVector<double>{0, 0.4318, 0.0203, 0, 0, 0}
                                   << QVector<double>{h, 0, h, h, h, 0} << QVector<double>{0.672, 0, 0.15005, 0.4318, 0, 0.056}
                                   << QVector<double>{0, 0, 0, 0, 0, 0} << QVector<int>{cross, par, skew, cross, cross, last};
        QTest::newRow("UR-like") << QString("ur_like.urdf") << QVector<double>{0, 0.425, 0.392, 0, 0, 0}
                                 << QVector<double>{h, 0, 0, h, h, 0} << QVector<double>{0.089, 0, 0, 0.109, 0.095, 0.082}
                                 << QVector<double>{0, -h, 0, h, 0, 0} << QVector<int>{cross, par, par, cross, cross, last};
        QTest::newRow("Stanford-like") << QString("stanford_like.urdf") << QVector<double>{0, 0, 0, 0, 0, 0}
                                       << QVector<double>{h, h, 0, h, h, 0} << QVector<double>{0.412, 0.154, 0, 0, 0, 0.263}
                                       << QVector<double>{0, 0, 0, 0, 0, 0} << QVector<int>{cross, cross, same, cross, cross, last};
        QTest::newRow("antiparallel") << QString("antiparallel.urdf") << QVector<double>{0.4, 0.3, 0} << QVector<double>{p, p, 0}
                                      << QVector<double>{0, 0, 0.15} << QVector<double>{0, 0, 0} << QVector<int>{par, par, last};
    }
    void knownTables() {
        QFETCH(QString, file);
        QFETCH(QVector<double>, a);
        QFETCH(QVector<double>, alpha);
        QFETCH(QVector<double>, d);
        QFETCH(QVector<double>, theta);
        QFETCH(QVector<int>, cases);
        const UrdfImport imported = importUrdfFile(urdf(qPrintable(file)), {});
        QCOMPARE(imported.scene.dof(), int(a.size()));
        for (int i = 0; i < imported.scene.dof(); ++i) {
            const DhRow& r = imported.dh.rows[static_cast<std::size_t>(i)];
            const QString row = QString("row %1: a %2, α %3, d %4, θ %5").arg(i + 1).arg(r.a).arg(r.alpha).arg(r.d).arg(r.theta);
            QVERIFY2(std::abs(r.a - a[i]) + std::abs(std::abs(r.alpha) - alpha[i]) + std::abs(r.d - d[i]) + std::abs(r.theta - theta[i]) <
                         1e-12,
                     qPrintable(row));
            QCOMPARE(int(imported.dh.frames[static_cast<std::size_t>(i) + 1].pair), cases[i]);
        }
        QCOMPARE(imported.dh.frames[1].antiparallel, file == "antiparallel.urdf");
        if (file == "ur_like.urdf") QVERIFY(std::abs(imported.scene.robot.joints[5].link.mass - (0.19 + 0.6)) < 1e-12);
        if (file == "stanford_like.urdf") QCOMPARE(imported.scene.robot.joints[2].dh.type, JointType::Prismatic);
        if (file == "planar_2r.urdf") {  // the URDF's damping and friction of the elbow as its viscous and Coulomb friction
            QCOMPARE(int(imported.scene.effects.viscous.size()), 1);
            QCOMPARE(imported.scene.effects.viscous[0].joint, 1);
            QCOMPARE(imported.scene.effects.coulomb[0].force, 0.2);
            QVERIFY((imported.scene.robot.joints[0].link.com - Eigen::Vector3d(-0.5, 0, 0)).norm() < 1e-12);
        }
    }

    // The meshbot's look: every link kept on the DH frame of its body, where KDL puts the
    // URDF link at random q (base, upper arm, forearm, the tool fixed to it); its shapes
    // with their sizes and colours, the STL found by package:// in the folder named
    // meshbot above the file, the OBJ by a path relative to it. Saved, a mesh path is
    // relative to the scene file; loaded, absolute again. A package not found is noted
    // and keeps its URL.
    void linksKeepTheirLook() {
        namespace fs = std::filesystem;
        const std::string path = urdf("meshbot/urdf/meshbot.urdf");
        for (DhConvention convention : {DhConvention::Standard, DhConvention::Modified}) {
            UrdfImportOptions options;
            options.convention = convention;
            const UrdfImport imported = importUrdfFile(path, options);
            const std::vector<LinkVisual>& links = imported.scene.robot.links;
            QCOMPARE(int(links.size()), 4);
            const char* names[] = {"base", "upper_arm", "forearm", "tool"};
            const int bodies[] = {0, 1, 2, 2};
            for (int k = 0; k < 4; ++k) {
                QCOMPARE(QString::fromStdString(links[k].name), QString(names[k]));
                QCOMPARE(links[k].body, bodies[k]);
            }
            KDL::Tree tree;
            QVERIFY(kdl_parser::treeFromFile(path, tree));
            std::mt19937 rng(5);
            const RobotModel& robot = imported.scene.robot;
            RobotData data(robot);
            for (int trial = 0; trial < 10; ++trial) {
                const Eigen::VectorXd q = test::randomVector(rng, 2, 3.0);
                forwardKinematics(robot, data, q);
                for (int k = 1; k < 4; ++k) {
                    KDL::Chain chain;
                    QVERIFY(tree.getChain("base", names[k], chain));
                    KDL::ChainFkSolverPos_recursive fk(chain);
                    KDL::JntArray kq(chain.getNrOfJoints());
                    for (unsigned j = 0; j < chain.getNrOfJoints(); ++j) kq(j) = q[j];
                    KDL::Frame kdl;
                    QVERIFY(fk.JntToCart(kq, kdl) >= 0);
                    const Eigen::Isometry3d ours = data.T_0i[static_cast<std::size_t>(links[k].body)] * links[k].frame;
                    for (int r = 0; r < 3; ++r) {
                        QVERIFY(std::abs(ours.translation()[r] - kdl.p(r)) < 1e-12);
                        for (int c = 0; c < 3; ++c) QVERIFY(std::abs(ours.linear()(r, c) - kdl.M(r, c)) < 1e-12);
                    }
                }
            }
            const LinkShape &base = links[0].shapes.at(0), &upper = links[1].shapes.at(0), &fore = links[2].shapes.at(0),
                            &tool = links[3].shapes.at(0);
            QCOMPARE(base.kind, LinkShape::Kind::Cylinder);
            QVERIFY((base.size - Eigen::Vector3d(0.08, 0.08, 0.1)).norm() < 1e-15);
            QVERIFY((base.origin.translation() - Eigen::Vector3d(0, 0, -0.05)).norm() < 1e-15);
            QVERIFY(std::abs(base.rgba[0] - 0.55) < 1e-6 && std::abs(base.rgba[3] - 1) < 1e-6);
            QCOMPARE(upper.kind, LinkShape::Kind::Mesh);
            QCOMPARE(fs::path(upper.mesh), fs::canonical(urdf("meshbot/meshes/upper_arm.stl")));
            QVERIFY(std::abs(upper.rgba[0] - 0.85) < 1e-6 && std::abs(upper.rgba[1] - 0.1) < 1e-6);
            QCOMPARE(fore.kind, LinkShape::Kind::Mesh);
            QCOMPARE(fs::path(fore.mesh), fs::canonical(urdf("meshbot/meshes/forearm.obj")));
            QCOMPARE(tool.kind, LinkShape::Kind::Sphere);
            QCOMPARE(tool.size.x(), 0.03);
            QVERIFY(imported.notes.empty());

            QTemporaryDir dir;
            const std::string saved = dir.filePath("arm.json").toStdString();
            saveScene(imported.scene, saved);
            std::ifstream file(saved);
            const std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
            QVERIFY(text.find("meshes/upper_arm.stl") != std::string::npos);
            QVERIFY(text.find("\"mesh\": \"/") == std::string::npos);  // relative to the scene file, not absolute
            const LoadedScene loaded = loadScene(saved);
            QCOMPARE(int(loaded.scene.robot.links.size()), 4);
            QCOMPARE(loaded.scene.robot.links[1].shapes.at(0).mesh, upper.mesh);
            QVERIFY(loaded.scene.robot.links[2].frame.isApprox(links[2].frame, 1e-14));
            QCOMPARE(loaded.scene.robot.links[0].shapes.at(0).rgba, base.rgba);
        }
        const std::string lost = "<robot name='r'><link name='a'/><joint name='j' type='revolute'><parent link='a'/><child link='b'/>"
                                 "<axis xyz='0 0 1'/><limit lower='-1' upper='1' effort='1' velocity='1'/></joint>"
                                 "<link name='b'><visual><geometry><mesh filename='package://nowhere/b.stl'/></geometry></visual></link></robot>";
        const UrdfImport imported = importUrdf(lost, "/tmp/robot.urdf", {});
        QCOMPARE(imported.scene.robot.links.at(1).shapes.at(0).mesh, std::string("package://nowhere/b.stl"));
        QCOMPARE(int(imported.notes.size()), 1);
        QVERIFY(present::messageText(imported.notes[0], present::Language::English).find("no folder named nowhere") != std::string::npos);
    }

    // A scene's "links" checked as every other field: one line naming the field.
    void badLinksAreRefused() {
        const std::string head = R"({"format": "lagrangelab-scene/1", "name": "x", "robot": {"convention": "standard", "joints": [
            {"a": 1, "alpha": 0, "d": 0, "theta": 0, "mass": 1}], "links": )";
        const std::pair<const char*, const char*> cases[] = {
            {R"([{"body": 2}])", "robot.links[0].body"},  // fields 0-based inside, shown 1-based (one_based.hpp)
            {R"([{"body": 1, "shapes": [{"box": [1, 0, 1]}]}])", "robot.links[0].shapes[0].box[1]"},
            {R"([{"body": 1, "shapes": [{"box": [1, 1, 1], "sphere": 1}]}])", "robot.links[0].shapes[0]"},
            {R"([{"body": 1, "shapes": [{"sphere": 0.1, "rgba": [1, 0, 2, 1]}]}])", "robot.links[0].shapes[0].rgba[2]"},
            {R"({"body": 1})", "robot.links"}};
        for (const auto& [links, field] : cases) {
            try {
                parseScene(head + links + "}}");
                QFAIL(links);
            } catch (const InputError& e) {
                QCOMPARE(QString::fromStdString(e.diagnostics().front().field), QString(field));
            }
        }
    }
};

LL_TEST_APPLESS_MAIN(TestUrdfImport)

}  // namespace test_urdf_import
#include "test_urdf_import.moc"
