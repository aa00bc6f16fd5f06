// The controller in the window (issue 49): a controlled robot gets the Tracking tab, a
// robot without one does not; the tab plots e and ė, the controller's torque terms (which
// add up to the torque applied), and for PD + g the Lyapunov function with dV/dt over
// −q̇ᵀK_d q̇ and the sentence that names the skew property; a controller whose ĝ is wrong
// says V̇ departs (its payload set by the tab's slider, the gains by the other, each one
// undoable edit); the reference is drawn as the ghost robot, its end effector where the
// 2R's closed-form kinematics puts q_ref; `--tracking` pictures a view and refuses a bad one.
#include <QImage>
#include <QProcess>
#include <QSlider>
#include <QUndoStack>
#include <QTemporaryDir>
#include <QTest>

#include "core/present/message_text.hpp"
#include "core/symbolic/derivation.hpp"
#include "core/visual/visual_scene.hpp"
#include "ui/window/derivation_view.hpp"
#include "test_registry.hpp"
#include "ui/document/scene_document.hpp"
#include "ui/window/ghost_run.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/scene_files.hpp"
#include "ui/window/scene_view.hpp"
#include "ui/window/tracking_pane.hpp"
#include "ui/window/trajectory_chart.hpp"
#include "window_checks.hpp"
#include "window_waits.hpp"

namespace test_tracking_window {

using namespace ll;
using ll::ui::MainWindow;
using Show = ll::ui::TrackingPane::Show;

namespace {

QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }

bool analysed(MainWindow& w) { return test::settled(w, 120) && test::waitUntil([&] { return w.analysis() != nullptr; }, 120000); }

}  // namespace

class TestTrackingWindow : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() { test::keepWindowStateIn(dir_); }

    void theTabOfAControlledRobot() {
        auto w = test::openedWindow(example("control/planar_2r_pd_gravity.json"), analysed);
        QVERIFY(w->showPlotTab("tracking"));
        ui::TrackingPane& pane = w->trackingPane();
        QVERIFY(test::waitUntil([&] { return w->analysis() && w->analysis()->control; }, 60000));
        const ControlHistory& history = *w->analysis()->control;
        QVERIFY(history.lyapunov.has_value());
        // e and ė
        pane.setShow(Show::Error);
        QVERIFY(pane.chart().curvePoints() > 100);
        QVERIFY2(pane.note().contains("RMS e"), qPrintable(pane.note()));
        // the controller's terms add up to the torque applied
        pane.setShow(Show::Torque);
        QVERIFY(pane.chart().curvePoints() > 100);
        for (const ControlParts& p : history.parts)
            QVERIFY((p.inertial + p.coriolis + p.gravity + p.proportional + p.derivative - p.tau).cwiseAbs().maxCoeff() <= 1e-12);
        // V, and dV/dt over −q̇ᵀK_d q̇ with the sentence naming the skew property
        pane.setShow(Show::Lyapunov);
        QCOMPARE(pane.show(), Show::Lyapunov);
        pane.setShow(Show::LyapunovRate);
        QCOMPARE(pane.show(), Show::LyapunovRate);
        QVERIFY2(pane.note().contains(QString::fromUtf8("q̇ᵀ(Ḃ − 2C)q̇ = 0")), qPrintable(pane.note()));
        QVERIFY(history.lyapunov->largestDeparture <= 1e-8);

        // The reference as the ghost: its end effector at the 2R's closed form of q_ref,
        // whatever the time shown (a held pose), while the robot itself is elsewhere.
        QVERIFY(w->ghost().showsReference());
        for (double t : {0.0, 0.4, 2.0}) {
            w->playback().setTime(t);
            test::flushEvents();
            const VisualScene* ghost = w->sceneView().ghost();
            QVERIFY(ghost != nullptr);
            const double q1 = 0.5, q2 = -0.3, a1 = 1.0, a2 = 0.8;
            const Eigen::Vector3d expected(a1 * std::cos(q1) + a2 * std::cos(q1 + q2), a1 * std::sin(q1) + a2 * std::sin(q1 + q2), 0);
            QVERIFY2((ghost->endEffectorPosition() - expected).norm() <= 1e-12,
                     qPrintable(QString::number((ghost->endEffectorPosition() - expected).norm())));
        }

        // The payload slider: a controller that believes in 2 kg, one undoable edit; the run
        // follows, V̇ departs and the note says why.
        const auto* old = w->analysis();
        pane.payloadSlider().setValue(20);
        QVERIFY(test::waitUntil([&] { return w->document().validScene().effects.control->model.payloadMass == 2.0; }, 60000));
        QVERIFY(test::waitUntil([&] { return w->analysis() && w->analysis() != old && w->analysis()->control; }, 120000));
        pane.setShow(Show::LyapunovRate);
        QVERIFY(w->analysis()->control->lyapunov->largestDeparture > 1e-2);
        QVERIFY2(pane.note().contains(QString::fromUtf8("ĝ − g")), qPrintable(pane.note()));
        // The gains slider: four steps up doubles K_p and K_d; undo gives them and the payload back.
        pane.payloadSlider().setValue(0);
        QVERIFY(test::waitUntil([&] { return w->document().validScene().effects.control->model.payloadMass == 0.0; }, 60000));
        pane.gainSlider().setValue(4);
        const auto kp = [&] { return w->document().validScene().effects.control->kp; };
        QVERIFY(test::waitUntil([&] { return (kp() - Eigen::Vector2d(200, 200)).norm() <= 1e-12; }, 60000));
        QVERIFY((w->document().validScene().effects.control->kd - Eigen::Vector2d(40, 40)).norm() <= 1e-12);
        w->document().undoStack()->undo();
        QVERIFY(test::waitUntil([&] { return (kp() - Eigen::Vector2d(100, 100)).norm() <= 1e-12; }, 60000));
        QCOMPARE(pane.gainSlider().value(), 0);
        w->document().undoStack()->undo();
        QVERIFY(test::waitUntil([&] { return w->document().validScene().effects.control->model.payloadMass == 2.0; }, 60000));
        QCOMPARE(pane.payloadSlider().value(), 20);
        // Dragging: the scene follows every position the slider passes, before it is let go,
        // and the whole drag is one undo entry back to where it began.
        const auto payload = [&] { return w->document().validScene().effects.control->model.payloadMass; };
        const int before = w->document().undoStack()->index();
        QSlider& slider = pane.payloadSlider();
        slider.setSliderDown(true);
        for (int position : {25, 30, 35}) {
            slider.setSliderPosition(position);
            QVERIFY(test::waitUntil([&] { return payload() == position / 10.0; }, 60000));
            QVERIFY(slider.isSliderDown());
        }
        slider.setSliderDown(false);
        QCOMPARE(w->document().undoStack()->index(), before + 1);
        w->document().undoStack()->undo();
        QVERIFY(test::waitUntil([&] { return payload() == 2.0; }, 60000));
        QCOMPARE(slider.value(), 20);
    }

    // The law as the derivation's step 9, listed after step 8 with its title: K_p, K_d, τ_1,
    // τ_2 with g of step 8 in place, and the closed loop, where g has cancelled.
    void theLawAsStepNine() {
        auto w = test::openedWindow(example("control/planar_2r_pd_gravity.json"), analysed);
        QVERIFY(test::waitUntil([&] { return w->derivationView().document() != nullptr; }, 60000));
        w->showDerivationStep(symbolic::controlStepNumber);
        QCOMPARE(w->derivationView().step(), symbolic::controlStepNumber);
        const present::DisplayStep* step = w->derivationView().document()->step(symbolic::controlStepNumber);
        QVERIFY(step);
        QCOMPARE(QString::fromStdString(present::messageText(step->title, present::Language::English)),
                 QString("Control law: PD with gravity compensation"));
        QStringList names;
        for (const present::DisplayItem& item : step->items) names << QString::fromStdString(item.name);
        QCOMPARE(names, (QStringList{"K_p", "K_d", QString::fromUtf8("τ_1"), QString::fromUtf8("τ_2"), "closed_loop_1", "closed_loop_2"}));
        const QString tau1 = QString::fromStdString(present::renderDisplay(*step->items[2].equation, present::DisplayStyle::Text));
        const QString loop1 = QString::fromStdString(present::renderDisplay(*step->items[4].equation, present::DisplayStyle::Text));
        QVERIFY2(tau1.contains("c12") && tau1.contains("100 e1"), qPrintable(tau1));  // g_1 of step 8 in τ_1
        QVERIFY2(!loop1.contains("c12") && !loop1.contains("9.81") && loop1.contains(QString::fromUtf8("q̈1")), qPrintable(loop1));
        QVERIFY(test::settled(*w, 60));
        QVERIFY(w->derivationView().isVisible());
    }

    // A robot without a controller: no Tracking tab, no reference ghost.
    void noControllerNoTab() {
        auto w = test::openedWindow(example("planar_2r.json"), analysed);
        QVERIFY(!w->showPlotTab("tracking"));  // its tab is hidden
        test::flushEvents();
        QVERIFY(!w->trackingPane().isVisible());
        QVERIFY(!w->ghost().showsReference());
        QVERIFY(w->sceneView().ghost() == nullptr);
    }

    // --tracking VIEW on the command line; a bad view is one line and exit 2.
    void trackingOnTheCommandLine() {
        const QString png = dir_.filePath("tracking.png");
        QProcess p;
        p.start(LL_CLI, {example("control/planar_2r_pd.json"), "--screenshot", png, "--tracking", "rate", "--at", "0.5"});
        QVERIFY(p.waitForFinished(120000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QCOMPARE(QImage(png).size(), QSize(1280, 800));
        p.start(LL_CLI, {example("control/planar_2r_pd.json"), "--screenshot", png, "--tracking", "bogus"});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 2);
        const QByteArray err = p.readAllStandardError();
        QVERIFY2(err.contains("--tracking") && err.contains("bogus") && err.count('\n') == 1, err.constData());
    }
};

LL_TEST_MAIN(TestTrackingWindow)

}  // namespace test_tracking_window
#include "test_tracking_window.moc"
