// The OSG builder and the headless renderer in-process, with no display: the end
// effector of the planar 2R arm drawn at time t sits where forward kinematics of the
// trajectory sampled at t puts it — in the node's transform, and in the picture (its
// red sphere at the projected pixel).
#include "test_registry.hpp"

#include "core/io/scene_file.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/model/robot_data.hpp"
#include "core/visual/trajectory_sampler.hpp"
#include "core/pipeline/scene_visual.hpp"
#include "core/visual/frame_labels.hpp"
#include "core/visual/visual_scene.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "ui/paint/headless_renderer.hpp"
#include "ui/paint/osg_scene.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_osg_scene {

using namespace ll;

namespace {

// A scene drawn headless from the default camera at `size` with its frame labels as
// `render` sizes them: the boxes where the labels are first placed, and the picture after
// the graph has placed them (render()).
struct LabelledRender {
    LabelledRender(VisualScene scene, QSize size)
        : visual(std::move(scene)), size(size), options(labelOptions(size)), graph(visual, options), gl(size.width(), size.height(), 0) {
        gl.setScene(graph.root());
        view = cameraView(visual, CameraSpec{}, gl.aspect());
        ui::applyCameraView(*gl.camera(), view, gl.aspect());
        boxes = frameLabelBoxes(visual, view, size.width(), size.height(), options.labelPixels);
    }
    static ui::OsgSceneOptions labelOptions(QSize size) {
        ui::OsgSceneOptions o;
        o.labelPixels = std::max(10.0, size.height() / 40.0);  // as render sets them
        o.trail = false;
        return o;
    }
    QImage render() {
        graph.placeLabels(visual, view, size.width(), size.height());
        QImage image;
        gl.render(image);
        return image;
    }
    VisualScene visual;
    QSize size;
    ui::OsgSceneOptions options;
    ui::OsgScene graph;
    ui::HeadlessRenderer gl;
    CameraView view;
    std::vector<LabelBox> boxes;
};

// The dark pixels inside a label's box: its ink, where the renderer drew it.
int inkIn(const QImage& image, const LabelBox& box) {
    int ink = 0;
    for (int y = int(box.top); y < int(box.bottom); ++y)
        for (int x = int(box.left); x < int(box.right); ++x)
            if (x >= 0 && y >= 0 && x < image.width() && y < image.height()) ink += qGray(image.pixel(x, y)) < 70;
    return ink;
}

}  // namespace

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
            const osg::Matrixd toWindow =
                gl.camera()->getViewMatrix() * gl.camera()->getProjectionMatrix() * gl.camera()->getViewport()->computeWindowMatrix();
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

    // Depth cues: the ground of a robot lies at its base (the pedestal stands on it; the
    // motion, and a centre of mass hanging below, do not move it), and each centre of mass has a drop line from its centre
    // straight down (along −up) to a foot on that plane, at every pose.
    void dropLinesStandOnTheGroundAtTheBase() {
        for (const char* file : {"/puma560.json", "/panda.json", "/scara.json", "/stanford_arm.json"}) {
            const Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + file).scene;
            VisualScene visual = visualScene(scene);
            // The pedestal's lowest point: the bottom of its disc (its axis is vertical in these).
            const VisualPart& pedestal = visual.parts.front();
            QCOMPARE(int(pedestal.role), int(PartRole::Pedestal));
            QVERIFY(std::abs(std::abs(pedestal.pose.linear().col(2).dot(visual.up)) - 1) < 1e-12);
            const double lowest = visual.up.dot(pedestal.pose.translation()) - pedestal.length / 2;
            SimulationSettings settings = scene.simulation;
            settings.duration = 2.0;
            const Trajectory tr = simulate(scene, settings).trajectory;
            visual.fitToMotion(tr);
            const double ground = visual.up.dot(visual.ground.centre);
            double below = 1e300;  // the lowest point of what the motion covers
            for (int c = 0; c < 8; ++c)
                below = std::min(below, visual.up.dot(Eigen::Vector3d(c & 1 ? visual.bounds.max.x() : visual.bounds.min.x(),
                                                                      c & 2 ? visual.bounds.max.y() : visual.bounds.min.y(),
                                                                      c & 4 ? visual.bounds.max.z() : visual.bounds.min.z())));
            if (lowest <= visual.up.dot(visual.bounds.centre())) QVERIFY2(std::abs(ground - (lowest - 0.01 * visual.scale)) < 1e-12, file);
            else  // most of it hangs below the base (the Stanford arm's centre of mass 3): below all
                QVERIFY2(std::abs(ground - (below - 0.01 * visual.scale)) < 1e-12 && QByteArray(file) == "/stanford_arm.json", file);
            int coms = 0;
            for (const VisualPart& part : visual.parts) coms += part.role == PartRole::CentreOfMass;
            QCOMPARE(int(visual.dropLines.size()), coms);
            QVERIFY(coms > 0);
            const TrajectorySampler sampler(tr);
            Eigen::VectorXd q(scene.dof()), qd(scene.dof());
            for (double t : {0.0, 0.9, 2.0}) {
                sampler.sample(t, q, qd);
                visual.pose(q, t);
                std::size_t k = 0;
                for (const VisualPart& part : visual.parts) {
                    if (part.role != PartRole::CentreOfMass) continue;
                    const auto& [top, foot] = visual.dropLines[k++];
                    QVERIFY((top - part.pose.translation()).norm() < 1e-12);
                    QVERIFY(std::abs(visual.up.dot(foot) - ground) < 1e-12);
                    QVERIFY(((top - foot) - visual.up.dot(top - foot) * visual.up).norm() < 1e-12);  // straight down
                }
            }
        }
    }

    // The frame labels of the Panda and the PUMA at their initial poses, as `render`
    // frames them at 1280×720 and 1920×1080 and 640×480: no two of their boxes overlap,
    // and each box holds its label's ink in the rendered picture (so the boxes are where
    // the renderer draws).
    void frameLabelsDoNotOverlap_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QSize>("size");
        QTest::addColumn<double>("d4");  // the PUMA's d4 made small: frames 3 and 4 nearly meet, their labels must move apart
        for (const char* f : {"/panda.json", "/puma560.json"})
            for (QSize s : {QSize(1280, 720), QSize(1920, 1080), QSize(640, 480)})
                QTest::newRow(qPrintable(QString("%1 %2x%3").arg(f + 1).arg(s.width()).arg(s.height()))) << QString(f) << s << -1.0;
        QTest::newRow("puma560 d4 = 0.02 m, 1280x720") << QString("/puma560.json") << QSize(1280, 720) << 0.02;
        QTest::newRow("puma560 d4 = 0.02 m, 640x480") << QString("/puma560.json") << QSize(640, 480) << 0.02;
    }
    void frameLabelsDoNotOverlap() {
        QFETCH(QString, file);
        QFETCH(QSize, size);
        QFETCH(double, d4);
        Scene scene = loadScene(std::string(LL_EXAMPLES_DIR) + file.toStdString()).scene;
        if (d4 > 0) scene.robot.joints[3].dh.d = d4;
        LabelledRender r(visualScene(scene), size);
        std::vector<LabelBox>& boxes = r.boxes;
        bool overlapped = false;  // before they are moved apart
        for (std::size_t a = 0; a < boxes.size(); ++a)
            for (std::size_t b = a + 1; b < boxes.size(); ++b) overlapped = overlapped || boxes[a].overlaps(boxes[b]);
        QCOMPARE(overlapped, d4 > 0);  // the examples' labels sit apart as placed; the squeezed PUMA's do not
        separateLabels(boxes, size.width(), size.height());
        const QImage image = r.render();
        QVERIFY(boxes.size() >= 4);
        int moved = 0;
        for (const LabelBox& b : boxes) moved += b.moved();
        QCOMPARE(moved > 0, d4 > 0);
        for (std::size_t a = 0; a < boxes.size(); ++a) {
            for (std::size_t b = a + 1; b < boxes.size(); ++b)
                QVERIFY2(!boxes[a].overlaps(boxes[b]),
                         qPrintable(QString("\"%1\" and \"%2\"")
                                        .arg(QString::fromStdString(boxes[a].text), QString::fromStdString(boxes[b].text))));
            const int ink = inkIn(image, boxes[a]);
            QVERIFY2(ink >= 5,
                     qPrintable(QString("label \"%1\": %2 dark pixels in its box").arg(QString::fromStdString(boxes[a].text)).arg(ink)));
        }
    }

    // A typed system's world frame sits inside its lower body (the mass–spring pair's
    // discs turn about it): its label "world" would read as that disc's name, so it is
    // moved off every body's box, with a leader line, and drawn where it was moved to.
    void worldLabelStaysOffTheBodies() {
        const QSize size(1280, 720);
        LabelledRender r(visualScene(loadScene(std::string(LL_EXAMPLES_DIR) + "/mass_spring_pair_lagrangian.json").scene), size);
        std::vector<LabelBox>& boxes = r.boxes;
        const std::vector<LabelBox> bodies = bodyBoxes(r.visual, r.view, size.width(), size.height());
        QVERIFY(bodies.size() >= 2);  // the two discs, and what the scene draws besides
        const auto onABody = [&](const LabelBox& label) {
            return std::any_of(bodies.begin(), bodies.end(), [&](const LabelBox& b) { return label.overlaps(b); });
        };
        QCOMPARE(int(boxes.size()), 1);
        QCOMPARE(boxes[0].text, std::string("world"));
        QVERIFY(onABody(boxes[0]));  // where it belongs: on the lower disc
        separateLabels(boxes, size.width(), size.height(), bodies);
        QVERIFY(boxes[0].moved());
        QVERIFY(!onABody(boxes[0]));
        QVERIFY(boxes[0].left >= 0 && boxes[0].top >= 0 && boxes[0].right <= size.width() && boxes[0].bottom <= size.height());
        const int ink = inkIn(r.render(), boxes[0]);
        QVERIFY2(ink >= 5, qPrintable(QString("%1 dark pixels in the moved label's box").arg(ink)));
        // a robot's labels are not kept off its links (their frames are on them)
        const VisualScene puma = visualScene(loadScene(std::string(LL_EXAMPLES_DIR) + "/puma560.json").scene);
        QVERIFY(bodyBoxes(puma, cameraView(puma, CameraSpec{}, r.gl.aspect()), size.width(), size.height()).empty());
    }
};

LL_TEST_GUILESS_MAIN(TestOsgScene)

}  // namespace test_osg_scene
#include "test_osg_scene.moc"
