// The OSG builder and the headless renderer in-process, with no display: the end
// effector of the planar 2R arm drawn at time t sits where forward kinematics of the
// trajectory sampled at t puts it — in the node's transform, and in the picture (its
// red sphere at the projected pixel).
#include <QtTest>

#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/robot_data.hpp"
#include "core/visual/trajectory_sampler.hpp"
#include "core/pipeline/scene_visual.hpp"
#include "core/visual/visual_scene.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "ui/headless_renderer.hpp"
#include "ui/osg_scene.hpp"

using namespace ll;

class TestOsgScene : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { qunsetenv("DISPLAY"); }

    void endEffectorDrawnWhereForwardKinematicsPutsIt() {
        const Scene scene = loadScene(LL_EXAMPLES_DIR "/planar_2r.json").scene;
        SimulationSettings settings = scene.simulation;
        settings.duration = 2.0;
        const Trajectory tr = simulate(scene, settings).trajectory;
        const TrajectorySampler sampler(tr);
        VisualScene visual = visualScene(scene);
        visual.fitToMotion(tr);
        ui::OsgSceneOptions options;
        options.frames = false;  // nothing in front of the tip
        options.trail = false;
        ui::OsgScene graph(visual, options);
        ui::HeadlessRenderer gl(480, 360, 4);
        gl.setScene(graph.root());
        const CameraView view = cameraView(visual, parseCameraSpec("20,25"), gl.aspect());
        ui::applyCameraView(*gl.camera(), view, gl.aspect());
        qInfo("renderer: %s", gl.rendererName().c_str());

        RobotData data(scene.robot);
        Eigen::VectorXd q(2), qd(2);
        QImage image;
        for (double t : {0.0, 0.77, 1.5}) {
            sampler.sample(t, q, qd);
            visual.pose(q, t);
            graph.update(visual);
            forwardKinematics(scene.robot, data, q);
            const osg::Matrixd drawn = graph.partTransform(visual.endEffector)->getMatrix();
            const Eigen::Vector3d tip = data.T_0i[2].translation();
            QVERIFY((Eigen::Vector3d(drawn.getTrans().x(), drawn.getTrans().y(), drawn.getTrans().z()) - tip).norm() < 1e-12);

            gl.render(image);
            QCOMPARE(image.size(), QSize(480, 360));
            // Project the tip with the camera and look for the red sphere around it.
            const osg::Matrixd toWindow = gl.camera()->getViewMatrix() * gl.camera()->getProjectionMatrix() *
                                          gl.camera()->getViewport()->computeWindowMatrix();
            const osg::Vec3d pixel = osg::Vec3d(tip.x(), tip.y(), tip.z()) * toWindow;
            const int x = int(std::lround(pixel.x())), y = 360 - 1 - int(std::lround(pixel.y()));
            int red = 0;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const QColor c = image.pixelColor(std::clamp(x + dx, 0, 479), std::clamp(y + dy, 0, 359));
                    red += c.red() > 120 && c.red() > c.green() + 60 && c.red() > c.blue() + 50;
                }
            QVERIFY2(red >= 5, qPrintable(QString("t = %1: tip at pixel (%2, %3), %4 red pixels").arg(t).arg(x).arg(y).arg(red)));
        }
    }
};

QTEST_GUILESS_MAIN(TestOsgScene)
#include "test_osg_scene.moc"
