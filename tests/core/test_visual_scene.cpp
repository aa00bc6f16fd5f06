// The renderer-neutral 3D description: the DH stick figure follows forward kinematics
// (frames, links, joints, COMs, end effector), prismatic bars follow q, sizes scale
// with the reach, up is −gravity, Lagrangian bodies follow their expressions, the
// bounds hold the motion and the camera sees all of them.
#include "test_registry.hpp"

#include <cmath>

#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/message_error.hpp"
#include "core/model/robot_data.hpp"
#include "core/visual/camera_view.hpp"
#include "core/visual/trajectory_sampler.hpp"
#include "core/pipeline/scene_visual.hpp"
#include "core/visual/visual_scene.hpp"
#include "core/pipeline/scene_simulation.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_visual_scene {

using namespace ll;

namespace {

Scene example(const char* name) { return loadScene(std::string(LL_EXAMPLES_DIR) + "/" + name).scene; }

std::vector<const VisualPart*> partsNamed(const VisualScene& v, const std::string& name) {
    std::vector<const VisualPart*> out;
    for (const VisualPart& p : v.parts)
        if (p.name == name) out.push_back(&p);
    return out;
}

// The two ends of a part drawn along its z axis.
std::pair<Eigen::Vector3d, Eigen::Vector3d> ends(const VisualPart& p) {
    const Eigen::Vector3d half = p.pose.linear().col(2) * p.length / 2;
    return {p.pose.translation() - half, p.pose.translation() + half};
}

}  // namespace

class TestVisualScene : public QObject {
    Q_OBJECT

private slots:
    // At a sampled time, every DH triad is T_0i, the end effector sits on o_n, each
    // COM on p_ci, and link i's segments run from o_{i-1} to o_i.
    void puma560FollowsForwardKinematics() {
        const Scene scene = example("puma560.json");
        SimulationSettings settings = scene.simulation;
        settings.duration = 1.0;
        const Trajectory tr = simulate(scene, settings).trajectory;
        const TrajectorySampler sampler(tr);
        VisualScene visual = visualScene(scene);
        RobotData data(scene.robot);
        Eigen::VectorXd q(6), qd(6);
        for (double t : {0.0, 0.333, 0.71}) {
            sampler.sample(t, q, qd);
            visual.pose(q, t);
            forwardKinematics(scene.robot, data, q);
            QCOMPARE(static_cast<int>(visual.frames.size()), 7);
            for (int k = 0; k <= 6; ++k) QVERIFY(visual.frames[k].pose.isApprox(data.T_0i[k], 1e-14));
            QVERIFY((visual.endEffectorPosition() - data.T_0i[6].translation()).norm() < 1e-14);
            for (int i = 0; i < 6; ++i) {
                const auto com = partsNamed(visual, "COM " + std::to_string(i + 1));
                if (scene.robot.joints[i].link.mass == 0) QVERIFY(com.empty());
                else QVERIFY((com.at(0)->pose.translation() - data.p_ci[i]).norm() < 1e-14);
                // The segments of link i chain from o_{i-1} to o_i.
                const auto links = partsNamed(visual, "link " + std::to_string(i + 1));
                Eigen::Vector3d at = data.T_0i[i].translation();
                for (const VisualPart* link : links) {
                    auto [a, b] = ends(*link);
                    if ((a - at).norm() > (b - at).norm()) std::swap(a, b);
                    QVERIFY((a - at).norm() < 1e-12);
                    at = b;
                }
                QVERIFY((at - data.T_0i[i + 1].translation()).norm() < 1e-12);
            }
        }
        // Link 2 (a = 0.4318, d = 0): one segment along x_2 of length a.
        const auto link2 = partsNamed(visual, "link 2");
        QCOMPARE(static_cast<int>(link2.size()), 1);
        QVERIFY(std::abs(link2[0]->length - 0.4318) < 1e-12);
    }

    // COM markers: volume proportional to mass (r³ ∝ m).
    void comVolumeProportionalToMass() {
        const Scene scene = example("puma560.json");
        const VisualScene visual = visualScene(scene);
        const double r2 = partsNamed(visual, "COM 2").at(0)->radius, r3 = partsNamed(visual, "COM 3").at(0)->radius;
        QVERIFY(std::abs(std::pow(r3 / r2, 3) - 4.8 / 17.4) < 1e-12);
    }

    // The Stanford arm's boom: a sleeve fixed on z_2 and a bar whose length is d3 + q3.
    void prismaticBarFollowsQ() {
        const Scene scene = example("stanford_arm.json");
        VisualScene visual = visualScene(scene);
        Eigen::VectorXd q = scene.initial.q;
        const auto bar = [&] {
            for (const VisualPart& p : visual.parts)
                if (p.shape == PartShape::Bar) return p;
            return VisualPart{};
        };
        const auto sleeve = [&] {
            for (const VisualPart& p : visual.parts)
                if (p.shape == PartShape::Sleeve) return p;
            return VisualPart{};
        };
        const double d3 = scene.robot.joints[2].dh.d;
        for (double q3 : {0.3, 0.6, 1.1}) {
            q[2] = q3;
            visual.pose(q, 0);
            QVERIFY(std::abs(bar().length - std::abs(d3 + q3)) < 1e-12);
            RobotData data(scene.robot);
            forwardKinematics(scene.robot, data, q);
            QVERIFY((sleeve().pose.translation() - data.T_0i[2].translation()).norm() < 1e-12);
            QVERIFY(std::abs(sleeve().pose.linear().col(2).dot(data.T_0i[2].linear().col(2)) - 1) < 1e-12);
        }
    }

    // The same pendulum at 5 cm and at 2 m looks the same: every size scales by 40.
    void sizesScaleWithReach() {
        Scene small = example("simple_pendulum.json");
        Scene large = small;
        small.robot.joints[0].dh.a = 0.05;
        large.robot.joints[0].dh.a = 2.0;
        const VisualScene a = visualScene(small), b = visualScene(large);
        QCOMPARE(a.parts.size(), b.parts.size());
        for (size_t p = 0; p < a.parts.size(); ++p) {
            QCOMPARE(a.parts[p].name, b.parts[p].name);
            QVERIFY(std::abs(b.parts[p].radius / a.parts[p].radius - 40) < 1e-9);
        }
        QVERIFY(std::abs(b.frames[0].axisLength / a.frames[0].axisLength - 40) < 1e-9);
    }

    void upIsMinusGravity() {
        QVERIFY(visualScene(example("puma560.json")).up.isApprox(Eigen::Vector3d::UnitZ()));
        QVERIFY(visualScene(example("double_pendulum.json")).up.isApprox(Eigen::Vector3d::UnitY()));
        Scene none = example("puma560.json");
        none.effects.gravity.reset();
        QVERIFY(visualScene(none).up.isApprox(Eigen::Vector3d::UnitZ()));
        // Lagrangian scenes have no gravity vector: x–y plane drawings get y up.
        QVERIFY(visualScene(example("elastic_pendulum.json")).up.isApprox(Eigen::Vector3d::UnitY()));
        QVERIFY(visualScene(example("mass_spring_pair_lagrangian.json")).up.isApprox(Eigen::Vector3d::UnitZ()));
    }

    // The mass–spring pair typed as a Lagrangian: its five bodies, posed by their
    // expressions (marker 1 on the rim of disc 1 at angle θ1).
    void lagrangianBodiesFollowTheirExpressions() {
        const Scene scene = example("mass_spring_pair_lagrangian.json");
        VisualScene visual = visualScene(scene);
        QCOMPARE(static_cast<int>(visual.parts.size()), 5);
        Eigen::VectorXd q(2);
        q << 0.7, -0.4;
        visual.pose(q, 0.0);
        const VisualPart& marker = *partsNamed(visual, "marker 1").at(0);
        QVERIFY((marker.pose.translation() - Eigen::Vector3d(0.3 * std::cos(0.7), 0.3 * std::sin(0.7), 0.03)).norm() < 1e-12);
        const VisualPart& disc2 = *partsNamed(visual, "inertia 2").at(0);
        QVERIFY(disc2.pose.linear().isApprox(Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix(), 1e-12));
        QCOMPARE(disc2.shape, PartShape::Cylinder);
        const VisualPart& shaft = *partsNamed(visual, "shaft").at(0);
        QVERIFY(std::abs(shaft.length - 0.7) < 1e-12);
        QCOMPARE(visual.endEffector, 3);  // the trail follows the last sphere (marker 2)
    }

    // After fitToMotion the bounds hold every part at every sample and the ground is
    // below all of them (a robot's: at its base, under the pedestal, which the motion may
    // pass: then below every part at the initial pose); the fitted camera sees every
    // part at every sample.
    void boundsHoldTheMotionAndTheCameraSeesThem() {
        for (const char* file : {"double_pendulum.json", "puma560.json"}) {
            const Scene scene = example(file);
            const Trajectory tr = simulate(scene).trajectory;
            VisualScene visual = visualScene(scene);
            visual.fitToMotion(tr, static_cast<int>(tr.size()));
            const bool planar = looksPlanar(visual);
            const VisualPart& pedestal = visual.parts.front();
            const bool atBase = pedestal.role == PartRole::Pedestal &&
                                std::abs(visual.up.dot(visual.ground.centre) -
                                         (visual.up.dot(pedestal.pose.translation()) - pedestal.length / 2 - 0.01 * visual.scale)) < 1e-12;
            QCOMPARE(atBase, std::string(file) == "puma560.json");          // the pendulum hangs below its pivot: the ground below all
            QCOMPARE(planar, std::string(file) == "double_pendulum.json");  // `auto` looks at a planar pendulum from the front
            std::vector<CameraView> views;
            for (const char* name : {"auto", "iso", "top", "side", "20,-35", "-120,60"})
                views.push_back(cameraView(visual, parseCameraSpec(name), 16.0 / 9.0));
            for (size_t k = 0; k < tr.size(); k += 7) {
                visual.pose(tr.q[k], tr.t[k]);
                for (const VisualPart& p : visual.parts) {
                    // Both ends of every part (rods, joints) or its centre (spheres), with its radius.
                    const auto [a, b] = ends(p);
                    for (const Eigen::Vector3d& e : {a, b}) {
                        QVERIFY((e.array() - p.radius >= visual.bounds.min.array() - 1e-12).all());
                        QVERIFY((e.array() + p.radius <= visual.bounds.max.array() + 1e-12).all());
                        // (atBase checked the pedestal's own bottom; its ends' spheres of the disc's radius would not fit)
                        if (!atBase || (k == 0 && p.role != PartRole::Pedestal))
                            QVERIFY(visual.up.dot(e) - p.radius >= visual.up.dot(visual.ground.centre));
                        for (const CameraView& view : views) {
                            const Eigen::Vector3d forward = (view.centre - view.eye).normalized();
                            const Eigen::Vector3d right = forward.cross(view.up).normalized(), up = right.cross(forward);
                            const double tanY = std::tan(view.fovy * M_PI / 360), tanX = tanY * 16.0 / 9.0;
                            const Eigen::Vector3d v = e - view.eye;
                            const double depth = v.dot(forward);
                            QVERIFY2(depth > p.radius && std::abs(v.dot(right)) + p.radius <= depth * tanX * (1 + 1e-9) &&
                                         std::abs(v.dot(up)) + p.radius <= depth * tanY * (1 + 1e-9),
                                     file);
                        }
                    }
                }
            }
        }
    }

    // The fit is tight: the PUMA 560's motion, seen iso, fills the picture's height or
    // width (at least 70 %; 77 % measured), rather than a box around it that a slanted view sees as
    // much larger than the robot.
    void fittedCameraFramesTheRobot() {
        const Scene scene = example("puma560.json");
        const Trajectory tr = simulate(scene).trajectory;
        VisualScene visual = visualScene(scene);
        visual.fitToMotion(tr);
        const double aspect = 16.0 / 9.0;
        const CameraView view = cameraView(visual, parseCameraSpec("iso"), aspect);
        const Eigen::Vector3d forward = (view.centre - view.eye).normalized();
        const Eigen::Vector3d right = forward.cross(view.up).normalized(), up = right.cross(forward);
        const double tanY = std::tan(view.fovy * M_PI / 360), tanX = tanY * aspect;
        double lowX = 1, highX = -1, lowY = 1, highY = -1;  // in units of the half picture
        for (size_t k = 0; k < tr.size(); ++k) {
            visual.pose(tr.q[k], tr.t[k]);
            for (const VisualPart& p : visual.parts) {
                const auto [a, b] = ends(p);
                for (const Eigen::Vector3d& e : {a, b}) {
                    const Eigen::Vector3d v = e - view.eye;
                    const double depth = v.dot(forward);
                    const double x = v.dot(right) / (depth * tanX), y = v.dot(up) / (depth * tanY);
                    const double rx = p.radius / (depth * tanX), ry = p.radius / (depth * tanY);
                    lowX = std::min(lowX, x - rx), highX = std::max(highX, x + rx);
                    lowY = std::min(lowY, y - ry), highY = std::max(highY, y + ry);
                }
            }
        }
        QVERIFY2(std::max((highX - lowX) / 2, (highY - lowY) / 2) >= 0.7,
                 qPrintable(QString("x %1..%2, y %3..%4").arg(lowX).arg(highX).arg(lowY).arg(highY)));
    }

    // Frames whose origins coincide at every pose share one label (the PUMA's wrist
    // frames 4, 5, 6); frames that do not keep their own.
    void coincidentFramesShareALabel() {
        const VisualScene puma = visualScene(example("puma560.json"));
        QStringList labels;
        for (const VisualFrame& f : puma.frames) labels << QString::fromStdString(f.label);
        QCOMPARE(labels, QStringList({"0", "1", "2", "3", "4,5,6", "", ""}));
        const VisualScene planar = visualScene(example("planar_2r.json"));
        for (size_t k = 0; k < planar.frames.size(); ++k) QCOMPARE(planar.frames[k].label, std::to_string(k));
    }

    void cameraSpecs() {
        QCOMPARE(parseCameraSpec("top").preset, CameraSpec::Preset::Top);
        const CameraSpec s = parseCameraSpec("30,-10,4.5");
        QCOMPARE(s.preset, CameraSpec::Preset::Angles);
        QCOMPARE(s.azimuth, 30.0);
        QCOMPARE(s.elevation, -10.0);
        QCOMPARE(s.distance, 4.5);
        for (const char* bad : {"", "diagonal", "30", "30,95", "1,2,3,4", "30,x", "30,10,-1", "nan,0"})
            QVERIFY_THROWS_EXCEPTION(MessageError, parseCameraSpec(bad));
    }
};

LL_TEST_APPLESS_MAIN(TestVisualScene)

}  // namespace test_visual_scene
#include "test_visual_scene.moc"
