// The desktop window under a real X server (ctest runs it under xvfb-run): edits go
// through the editor's item model as a keystroke would, and the test reads back the
// model, the derivation, the scene drawn in 3D, the plots and the pixels of the window.
#include <QtTest>

#include <QApplication>
#include <QFile>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>

#include "core/io/scene_file.hpp"
#include "ui/derivation_panel.hpp"
#include "ui/joint_table_model.hpp"
#include "ui/derivation_view.hpp"
#include "ui/main_window.hpp"
#include "ui/playback_bar.hpp"
#include "ui/scene_view.hpp"
#include "ui/teach_panel.hpp"
#include "ui/trajectory_chart.hpp"

using ll::ui::JointTableModel;
using ll::ui::MainWindow;

namespace {

QString example(const char* name) { return QString(LL_EXAMPLES_DIR "/") + name; }

// Waits (processing events) until the window shows a simulation and a derivation of its
// newest valid scene.
bool settled(MainWindow& w, int seconds = 60) {
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < seconds * 1000) {
        QTest::qWait(20);
        if (w.result() && !w.liveSimulation().busy() && !w.derivationPanel().busy() && w.result()->request == w.liveSimulation().latestRequest())
            return true;
    }
    return false;
}

// Waits until the newest edit has been checked (diagnostics and valid scene up to date).
bool checked(MainWindow& w) {
    QElapsedTimer clock;
    clock.start();
    while (w.document().validating()) {
        if (clock.elapsed() > 30000) return false;
        QTest::qWait(5);
    }
    return true;
}

// Distance between the origins of DH frames 0 and 1 of the drawn scene at q = 0.
double drawnFirstLink(const MainWindow& w) {
    ll::VisualScene& visual = *w.result()->visual;
    visual.pose(Eigen::VectorXd::Zero(visual.dof()), 0);
    return (visual.frames[1].pose.translation() - visual.frames[0].pose.translation()).norm();
}

// Fraction of pixels of `image` inside `rect` that differ from the colour at its corner
// (the background) by more than a little, and how many distinct colours there are.
std::pair<double, int> content(const QImage& image, const QRect& rect) {
    const QRgb background = image.pixel(rect.topLeft() + QPoint(3, 3));
    long differing = 0, total = 0;
    QSet<QRgb> colours;
    for (int y = rect.top(); y <= rect.bottom(); y += 2)
        for (int x = rect.left(); x <= rect.right(); x += 2) {
            const QRgb p = image.pixel(x, y);
            ++total;
            colours.insert(p & 0xf0f0f0);
            if (std::abs(qRed(p) - qRed(background)) + std::abs(qGreen(p) - qGreen(background)) + std::abs(qBlue(p) - qBlue(background)) > 30)
                ++differing;
        }
    return {double(differing) / std::max(total, 1L), static_cast<int>(colours.size())};
}

}  // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        // Recovery copies and recent files go to the temporary folder, not the user's.
        qputenv("LAGRANGELAB_RECOVERY_DIR", dir_.filePath("recovery").toLocal8Bit());
        QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir_.filePath("settings"));
    }

    // A DH cell edit reaches the model, the derivation and the drawn 3D scene.
    void editingADhCellChangesModelDerivationAndScene() {
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.show();
        QVERIFY(w.openFile(example("planar_2r.json"), nullptr, true));
        QVERIFY(settled(w));
        QCOMPARE(w.document().validScene().robot.joints[0].dh.a, 1.0);
        QVERIFY(std::abs(drawnFirstLink(w) - 1.0) < 1e-12);
        const QString before = w.derivationPanel().text();
        QVERIFY2(before.contains("DH = "), qPrintable(before.left(300)));

        JointTableModel& model = w.jointModel();
        QVERIFY(model.setData(model.index(0, JointTableModel::A), "1.5", Qt::EditRole));
        QVERIFY(checked(w));
        QCOMPARE(w.document().validScene().robot.joints[0].dh.a, 1.5);
        QCOMPARE(model.data(model.index(0, JointTableModel::A), Qt::DisplayRole).toString(), QString("1.5"));
        QVERIFY(settled(w));
        QVERIFY(std::abs(drawnFirstLink(w) - 1.5) < 1e-12);
        const QString after = w.derivationPanel().text();
        QVERIFY(after != before);
        // Step 0's DH matrix holds the typed number as an exact rational, where it held a1.
        const QString step0 = after.section("Step 1.", 0, 0);
        QVERIFY2(step0.contains("3/2"), qPrintable(step0));
        QVERIFY(!step0.contains("a1"));
        // The energy changed with the arm: B grows with a1, so E_kin does along the motion.
        QVERIFY(w.energyChart().curvePoints() > 100);
    }

    // An invalid cell is marked with the core's message; the last valid model stays.
    void invalidCellShowsItsErrorAndKeepsTheLastValidModel() {
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.show();
        QVERIFY(w.openFile(example("planar_2r.json"), nullptr, true));
        QVERIFY(settled(w));
        const int request = w.result()->request;
        JointTableModel& model = w.jointModel();
        const QModelIndex mass = model.index(1, JointTableModel::Mass);
        QVERIFY(model.setData(mass, "-2", Qt::EditRole));
        QVERIFY(checked(w));
        QVERIFY(w.document().hasErrors());
        const QString tip = model.data(mass, Qt::ToolTipRole).toString();
        QVERIFY2(tip.startsWith("error:") && tip.contains("-2"), qPrintable(tip));
        QCOMPARE(model.data(mass, Qt::BackgroundRole).value<QBrush>().color(), QColor(255, 190, 190));
        QVERIFY(w.diagnosticLines().join('\n').contains("robot.joints[2].mass"));
        // The cell shows what was typed; the model on screen is still the valid one.
        QCOMPARE(model.data(mass, Qt::DisplayRole).toString(), QString("-2"));
        QCOMPARE(w.document().validScene().robot.joints[1].link.mass, 1.5);
        QTest::qWait(200);
        QCOMPARE(w.result()->request, request);
        QCOMPARE(w.result()->scene->robot.joints[1].link.mass, 1.5);
        // An unknown parameter in an expression names it.
        QVERIFY(model.setData(model.index(0, JointTableModel::A), "a9*2", Qt::EditRole));
        QVERIFY(checked(w));
        QVERIFY2(model.data(model.index(0, JointTableModel::A), Qt::ToolTipRole).toString().contains("a9"),
                 qPrintable(model.data(model.index(0, JointTableModel::A), Qt::ToolTipRole).toString()));
        QCOMPARE(w.document().validScene().robot.joints[0].dh.a, 1.0);
    }

    // Undo and redo restore the typed text, the valid model and the simulation.
    void undoAndRedoRestore() {
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.show();
        QVERIFY(w.openFile(example("planar_2r.json"), nullptr, true));
        QVERIFY(settled(w));
        JointTableModel& model = w.jointModel();
        const QModelIndex alpha = model.index(1, JointTableModel::D);
        model.setData(alpha, "0.25", Qt::EditRole);
        QVERIFY(checked(w));
        QCOMPARE(w.document().validScene().robot.joints[1].dh.d, 0.25);
        model.addJoint(1);
        QVERIFY(checked(w));
        QCOMPARE(w.document().validScene().robot.dof(), 3);
        QCOMPARE(w.document().validScene().initial.q.size(), 3);
        QVERIFY(settled(w));
        QCOMPARE(w.result()->simulation.trajectory.n, 3);
        QCOMPARE(w.document().undoStack()->count(), 2);
        w.document().undoStack()->undo();
        QVERIFY(checked(w));
        QCOMPARE(w.document().validScene().robot.dof(), 2);
        w.document().undoStack()->undo();
        QVERIFY(checked(w));
        QCOMPARE(w.document().validScene().robot.joints[1].dh.d, 0.0);
        QCOMPARE(model.data(alpha, Qt::DisplayRole).toString(), QString("0"));
        QVERIFY(!w.document().isModified());
        QVERIFY(settled(w));
        QCOMPARE(w.result()->simulation.trajectory.n, 2);
        w.document().undoStack()->redo();
        QVERIFY(checked(w));
        QCOMPARE(w.document().validScene().robot.joints[1].dh.d, 0.25);
        w.document().undoStack()->redo();
        QVERIFY(checked(w));
        QCOMPARE(w.document().validScene().robot.dof(), 3);
        QVERIFY(w.document().isModified());
    }

    // What is saved loads back the same, through the window and through the loader.
    void saveAndLoadRoundTrip() {
        const QString path = dir_.filePath("roundtrip.json");
        {
            MainWindow w;
            w.setAskBeforeClosing(false);
            QVERIFY(w.openFile(example("planar_2r.json"), nullptr, true));
            JointTableModel& model = w.jointModel();
            model.setDegrees(true);
            model.setData(model.index(1, JointTableModel::Alpha), "90", Qt::EditRole);  // degrees: stored as "90°"
            QVERIFY(checked(w));
            model.setData(model.index(0, JointTableModel::Mass), "m1*1.25", Qt::EditRole);
            QVERIFY(checked(w));
            QString error;
            QVERIFY2(w.saveTo(path, &error), qPrintable(error));
            QVERIFY(!w.document().isModified());
            model.setData(model.index(0, JointTableModel::D), "0.1", Qt::EditRole);
            QVERIFY(checked(w));
            QVERIFY(w.saveTo(path, &error));
            QVERIFY(QFile::exists(path + ".bak"));  // the previous save is the recovery copy
        }
        const ll::LoadedScene loaded = ll::loadScene(path.toStdString());
        QCOMPARE(loaded.scene.robot.joints[1].dh.alpha, M_PI / 2);
        QCOMPARE(loaded.scene.robot.joints[0].link.mass, 2.5);
        QCOMPARE(loaded.scene.robot.joints[0].dh.d, 0.1);
        QCOMPARE(QString::fromStdString(loaded.scene.expressions.at("robot.joints[2].alpha")), QString("90°"));
        const ll::LoadedScene backup = ll::loadScene((path + ".bak").toStdString());
        QCOMPARE(backup.scene.robot.joints[0].dh.d, 0.0);
        MainWindow again;
        again.setAskBeforeClosing(false);
        QVERIFY(again.openFile(path, nullptr, true));
        QCOMPARE(again.document().validScene().robot.joints[0].link.mass, 2.5);
        QCOMPARE(again.jointModel().data(again.jointModel().index(1, JointTableModel::Alpha), Qt::DisplayRole).toString(), QString("90°"));
        QVERIFY(!again.document().isModified());
    }

    // Unsaved edits survive a crash: the autosaved copy restores them on the next start.
    void autosaveRecoveryRestoresUnsavedEdits() {
        const QString path = dir_.filePath("crash.json");
        QFile::copy(example("planar_2r.json"), path);
        QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
        {
            auto* w = new MainWindow;
            w->setAskBeforeClosing(false);
            QVERIFY(w->openFile(path, nullptr, true));
            w->jointModel().setData(w->jointModel().index(0, JointTableModel::A), "1.2", Qt::EditRole);
            QVERIFY(checked(*w));
            w->writeRecovery();  // what the 5 s autosave timer does
            QVERIFY(MainWindow::hasRecovery());
            // The crash: the window goes away without closing (no closeEvent, no save).
            delete w;
        }
        QVERIFY(MainWindow::hasRecovery());
        QCOMPARE(ll::loadScene(path.toStdString()).scene.robot.joints[0].dh.a, 1.0);  // never saved
        MainWindow next;
        next.setAskBeforeClosing(false);
        QVERIFY(next.restoreRecovery());
        QVERIFY(checked(next));
        QCOMPARE(next.document().validScene().robot.joints[0].dh.a, 1.2);
        QCOMPARE(next.document().path(), path);
        QVERIFY(next.document().isModified());
        // Undo goes back to the file as saved; saving writes the restored edits there.
        next.document().undoStack()->undo();
        QVERIFY(checked(next));
        QCOMPARE(next.document().validScene().robot.joints[0].dh.a, 1.0);
        next.document().undoStack()->redo();
        QVERIFY(checked(next));
        QVERIFY(next.saveTo(path));
        QCOMPARE(ll::loadScene(path.toStdString()).scene.robot.joints[0].dh.a, 1.2);
        QVERIFY(!MainWindow::hasRecovery());  // a save discards the recovery copy
    }

    // A scene that fails to load shows its error lines and loses nothing open.
    void aFailingSceneShowsItsErrorsAndLosesNothing() {
        const QString bad = dir_.filePath("bad.json");
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"({"format": "lagrangelab-scene/1", "name": "bad", "robot": {"convention": "standard",
  "joints": [{"type": "revolute", "a": 1, "mass": -3, "com": [0, 0, 0]}, {"type": "hinge", "a": "l7"}]},
  "initial": {"q": [0, 0], "qd": [0, 0]}})");
        f.close();
        MainWindow w;
        w.setAskBeforeClosing(false);
        QVERIFY(w.openFile(example("planar_2r.json"), nullptr, true));
        w.jointModel().setData(w.jointModel().index(0, JointTableModel::A), "1.1", Qt::EditRole);
        QVERIFY(checked(w));
        const std::string text = w.document().text();
        const int edits = w.document().undoStack()->count();
        QStringList errors;
        QVERIFY(!w.openFile(bad, &errors, true));
        QVERIFY2(errors.size() >= 2, qPrintable(errors.join('\n')));
        for (const QString& e : errors) QVERIFY2(e.startsWith(bad + ": "), qPrintable(e));
        QVERIFY2(errors.join('\n').contains("robot.joints[2].type"), qPrintable(errors.join('\n')));
        QCOMPARE(w.document().text(), text);
        QCOMPARE(w.document().undoStack()->count(), edits);
        QVERIFY(w.document().isModified());
        QCOMPARE(w.document().validScene().robot.joints[0].dh.a, 1.1);
        QVERIFY(!w.openFile(dir_.filePath("missing.json"), &errors, true));
        QCOMPARE(w.document().text(), text);
    }

    // Screenshots of several examples: a non-blank 3D view, curves in the plot and text in
    // the derivation.
    void screenshotsOfExamplesHaveContent_data() {
        QTest::addColumn<QString>("scene");
        QTest::newRow("double pendulum") << "double_pendulum.json";
        QTest::newRow("PUMA 560") << "puma560.json";
        QTest::newRow("cart-pole") << "cart_pole.json";
        QTest::newRow("elastic pendulum (Lagrangian)") << "elastic_pendulum.json";
    }
    void screenshotsOfExamplesHaveContent() {
        QFETCH(QString, scene);
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openFile(example(scene.toUtf8().constData()), nullptr, true));
        QVERIFY(settled(w, 120));
        w.playback().setTime(1.0);
        const long frames = w.sceneView().framesDrawn();
        QTRY_VERIFY(w.sceneView().framesDrawn() > frames);
        QTest::qWait(100);
        const QImage shot = w.screenshot();
        QVERIFY(shot.width() >= 1000 && shot.height() >= 700);
        shot.save(dir_.filePath(scene + ".png"));
        // The 3D view: its rectangle in the window, a robot and a grid on the background.
        const QRect view(w.sceneView().mapTo(&w, QPoint(0, 0)), w.sceneView().size());
        const auto [drawn, colours] = content(shot, view.adjusted(2, 2, -2, -2));
        QVERIFY2(drawn > 0.01 && colours > 8, qPrintable(QString("%1 of the view drawn, %2 colours").arg(drawn).arg(colours)));
        // The GL framebuffer itself agrees (the screenshot did not just catch a frame of UI).
        const QImage gl = w.sceneView().grabView();
        const auto [glDrawn, glColours] = content(gl, gl.rect().adjusted(2, 2, -2, -2));
        QVERIFY2(glDrawn > 0.01 && glColours > 8, qPrintable(QString("GL: %1 drawn, %2 colours").arg(glDrawn).arg(glColours)));
        // The energy plot: curves drawn in the chart's rectangle.
        QVERIFY(w.energyChart().curvePoints() > 100);
        const QRect chart(w.energyChart().mapTo(&w, QPoint(0, 0)), w.energyChart().size());
        const auto [plotted, plotColours] = content(shot, chart.adjusted(80, 20, -150, -40));
        QVERIFY2(plotted > 0.005 && plotColours > 3, qPrintable(QString("plot: %1 drawn, %2 colours").arg(plotted).arg(plotColours)));
        // The derivation: all steps, with the equations of motion.
        const QString text = w.derivationPanel().text();
        QVERIFY2(text.contains("Step 8.") && text.count('\n') > 20, qPrintable(text.left(400)));
        // What the dock shows: the typeset step (its tab is in front), the kinetic energy
        // and B of step 7 drawn on its page.
        w.showDerivationStep(7);
        QTRY_VERIFY_WITH_TIMEOUT(!w.derivationView().isDeriving() && w.derivationView().document(), 120000);
        QCOMPARE(w.derivationView().step(), 7);
        QVERIFY(w.derivationView().isVisible());
        QTest::qWait(100);
        const QImage page = w.screenshot();
        const QRect pane(w.derivationView().mapTo(&w, QPoint(0, 0)), w.derivationView().size());
        const auto [typeset, inks] = content(page, pane.adjusted(4, pane.height() / 3, -20, -20));
        QVERIFY2(typeset > 0.01 && inks > 1, qPrintable(QString("typeset pane: %1 drawn").arg(typeset)));
    }

    // Teach mode poses the robot and evaluates E_pot, g and B at the pose.
    void teachModePosesAndEvaluates() {
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.show();
        QVERIFY(w.openFile(example("planar_2r.json"), nullptr, true));
        QVERIFY(settled(w));
        Eigen::VectorXd q(2);
        q << 0.0, M_PI / 2;
        w.teach(q);
        // Planar 2R (examples/planar_2r.json: q1 from the horizontal, gravity −y):
        // E_pot = g (m1 lc1 s1 + m2 (a1 s1 + lc2 s12)); at q = (0, π/2): 9.81·1.5·0.4.
        const QString readout = w.teachPanel().readout();
        QVERIFY2(readout.contains("E_pot(q) = 5.886 J"), qPrintable(readout));
        // The drawn end effector is at (a1, a2) = (1, 0.8).
        const Eigen::Vector3d tip = w.result()->visual->endEffectorPosition();
        QVERIFY2((tip - Eigen::Vector3d(1.0, 0.8, 0)).norm() < 1e-3, qPrintable(QString("%1 %2 %3").arg(tip.x()).arg(tip.y()).arg(tip.z())));
    }

    // The command a README picture comes from: `lagrangelab SCENE --screenshot FILE`.
    void screenshotCommandWritesTheWindow() {
        const QString png = dir_.filePath("cli.png");
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("LAGRANGELAB_RECOVERY_DIR", dir_.filePath("cli-recovery"));
        p.setProcessEnvironment(env);
        p.start(LL_CLI, {example("planar_2r.json"), "--screenshot", png, "--play", "0.5", "--step", "7"});
        QVERIFY(p.waitForFinished(120000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QImage image(png);
        QCOMPARE(image.size(), QSize(1280, 800));
        QVERIFY(content(image, QRect(450, 120, 400, 300)).first > 0.01);
        // Bad options: one line naming the option, exit 2.
        p.start(LL_CLI, {example("planar_2r.json"), "--screenshot", dir_.filePath("x.jpg")});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(p.readAllStandardError().startsWith("error: --screenshot"));
        p.start(LL_CLI, {example("planar_2r.json"), "--screenshot", png, "--step", "12"});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 2);
    }
};

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
