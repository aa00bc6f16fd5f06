// The desktop window under a real X server (ctest runs it under xvfb-run): edits go
// through the editor's item model as a keystroke would, and the test reads back the
// model, the derivation, the scene drawn in 3D, the plots and the pixels of the window.
#include "test_registry.hpp"

#include <QApplication>
#include <QFile>
#include <QFileDialog>
#include <QMessageBox>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>
#include <QPainter>
#include <QStatusBar>
#include <QSvgRenderer>

#include <QChart>
#include <QLegend>
#include <QListWidget>
#include <QDockWidget>
#include <QLineSeries>
#include <QValueAxis>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QLineEdit>
#include <QSlider>
#include <QTableView>
#include <QPushButton>

#include "core/io/scene_file.hpp"
#include "core/kinematics/dh_step_through.hpp"
#include "core/kinematics/forward_kinematics.hpp"
#include "core/pipeline/pose_results.hpp"
#include "core/pipeline/scene_derivation.hpp"
#include "ui/paint/derivation_pages.hpp"
#include "ui/window/derivation_panel.hpp"
#include "ui/document/field_list_model.hpp"
#include "ui/document/joint_table_model.hpp"
#include "ui/window/derivation_view.hpp"
#include "ui/paint/composite_frame.hpp"
#include "ui/window/dh_step_panel.hpp"
#include "ui/window/example_gallery.hpp"
#include "ui/window/main_window.hpp"
#include "ui/window/scene_files.hpp"
#include "window_checks.hpp"
#include "window_waits.hpp"
#include "ui/window/ghost_run.hpp"
#include "ui/window/presentation_mode.hpp"
#include "ui/window/export_actions.hpp"
#include "ui/window/autosave.hpp"
#include "ui/window/model_editor.hpp"
#include "ui/document/parameter_rename.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/scene_view.hpp"
#include "ui/window/teach_panel.hpp"
#include "ui/window/trajectory_chart.hpp"
#include "ui/window/work_precision_pane.hpp"

// A namespace of its own: a folder's tests are compiled together (tests/test_registry.hpp).
namespace test_main_window {

using ll::ui::JointTableModel;
using ll::ui::MainWindow;
namespace symbolic = ll::symbolic;
namespace present = ll::present;

using ll::test::checked;
using ll::test::flushEvents;
using ll::test::settled;

namespace {

QString example(const char* name) { return QString(LL_EXAMPLES_DIR "/") + name; }

// Shows the window on an example, without asking before closing, and waits until it settled.
bool shownOn(MainWindow& w, const char* name) {
    w.setAskBeforeClosing(false);
    w.show();
    return w.openFile(example(name), nullptr, true) && settled(w);
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
            if (std::abs(qRed(p) - qRed(background)) + std::abs(qGreen(p) - qGreen(background)) + std::abs(qBlue(p) - qBlue(background)) >
                30)
                ++differing;
        }
    return {double(differing) / std::max(total, 1L), static_cast<int>(colours.size())};
}

// Fraction of pixels that differ by more than a little between two images of one size.
double differing(const QImage& a, const QImage& b) {
    if (a.size() != b.size()) return 1.0;
    long n = 0, total = 0;
    for (int y = 0; y < a.height(); y += 2)
        for (int x = 0; x < a.width(); x += 2) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            ++total;
            n += std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) + std::abs(qBlue(p) - qBlue(q)) > 30;
        }
    return double(n) / std::max(total, 1L);
}

// The GL view's picture after the next frame is drawn.
QImage nextFrame(MainWindow& w) {
    ll::test::nextFrameDrawn(w);
    return w.sceneView().grabView();
}

// Opens an example in a shown window and waits for its simulation and derivation.
bool openShown(MainWindow& w, const char* scene) {
    w.setAskBeforeClosing(false);
    w.resize(1280, 800);
    w.show();
    return QTest::qWaitForWindowExposed(&w) && w.openFile(example(scene), nullptr, true) && settled(w, 120);
}

// Counts the paint events of the widget it filters.
struct PaintCounter : QObject {
    int count = 0;
    bool eventFilter(QObject*, QEvent* e) override {
        if (e->type() == QEvent::Paint) ++count;
        return false;
    }
};

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

}  // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
    QTemporaryDir dir_{qEnvironmentVariableIsSet("LL_TEST_KEEP") ? "/tmp/ll-test-main-window-XXXXXX" : QDir::tempPath() + "/ll-XXXXXX"};

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        dir_.setAutoRemove(!qEnvironmentVariableIsSet("LL_TEST_KEEP"));  // LL_TEST_KEEP=1: keep the screenshots to look at
        // Recovery copies and recent files go to the temporary folder, not the user's.
        ll::test::keepWindowStateIn(dir_);
    }

    // An edit that makes the robot larger refits a camera the user has not moved (a1 = 1.5
    // on the 2R left the view before); a camera the user zoomed is kept.
    void cameraRefitsWhenAnEditResizesTheRobot() {
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.show();
        QVERIFY(w.openFile(example("planar_2r.json"), nullptr, true));
        QVERIFY(settled(w));
        const double d0 = w.sceneView().cameraDistance(), r0 = w.sceneView().visualScene()->bounds.radius();
        JointTableModel& model = w.editor().joints();
        QVERIFY(model.setData(model.index(0, JointTableModel::A), "1.5", Qt::EditRole));
        QVERIFY(checked(w));
        QVERIFY(settled(w));
        const double r1 = w.sceneView().visualScene()->bounds.radius();
        QVERIFY2(r1 > 1.1 * r0, qPrintable(QString("%1 -> %2").arg(r0).arg(r1)));
        // The distance glides to its new fit (0.3 s).
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(w.sceneView().cameraDistance() / d0 - r1 / r0) < 0.05, 3000);
        const double d1 = w.sceneView().cameraDistance();
        QVERIFY2(std::abs(d1 / d0 - r1 / r0) < 0.05,
                 qPrintable(QString("distance %1 -> %2, radius %3 -> %4").arg(d0).arg(d1).arg(r0).arg(r1)));
        // The user zooms in: the next resize keeps that camera.
        w.sceneView().zoomBy(0.5);
        QVERIFY(w.sceneView().cameraMovedByUser());
        const double zoomed = w.sceneView().cameraDistance();
        QVERIFY(model.setData(model.index(0, JointTableModel::A), "2.5", Qt::EditRole));
        QVERIFY(checked(w));
        QVERIFY(settled(w));
        QVERIFY(w.sceneView().visualScene()->bounds.radius() > 1.1 * r1);
        QCOMPARE(w.sceneView().cameraDistance(), zoomed);
        // Fit (F) refits and forgets the user's move.
        w.sceneView().fit();
        QVERIFY(!w.sceneView().cameraMovedByUser() && w.sceneView().cameraDistance() > zoomed);
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

        JointTableModel& model = w.editor().joints();
        QVERIFY(model.setData(model.index(0, JointTableModel::A), "1.5", Qt::EditRole));
        QVERIFY(checked(w));
        QCOMPARE(w.document().validScene().robot.joints[0].dh.a, 1.5);
        QCOMPARE(model.data(model.index(0, JointTableModel::A), Qt::DisplayRole).toString(), QString("1.5"));
        QVERIFY(settled(w));
        QVERIFY(std::abs(drawnFirstLink(w) - 1.5) < 1e-12);
        const QString after = w.derivationPanel().text();
        QVERIFY(after != before);
        // Step 0's DH matrix holds the typed number as typed (1.5, not 3/2), where it held a1.
        const QString step0 = after.section("Step 1.", 0, 0);
        QVERIFY2(step0.contains("1.5") && !step0.contains("3/2"), qPrintable(step0));
        QVERIFY(!step0.contains("a1"));
        // The energy changed with the arm: B grows with a1, so E_kin does along the motion.
        QVERIFY(w.energyChart().curvePoints() > 100);
        // The JSON tab, filled when it is shown, has the edit.
        auto* json = w.findChild<QPlainTextEdit*>("scene-json");
        QVERIFY(json);
        for (QTabWidget* tabs : w.findChildren<QTabWidget*>())
            for (int i = 0; i < tabs->count(); ++i)
                if (tabs->tabText(i) == "JSON") tabs->setCurrentIndex(i);
        QTRY_VERIFY(json->isVisible());
        const auto shown = ll::ui::SceneJson::parse(json->toPlainText().toStdString());
        QCOMPARE(shown["robot"]["joints"][0]["a"].get<double>(), 1.5);
    }

    // One frame per edit: the edited cell is painted together with the edit's result, not
    // in a window frame of its own before it (each frame of a window holding a GL view is
    // composed through llvmpipe: two frames doubled the 2R's edit latency).
    void anEditAndItsResultShareOneFrame() {
        MainWindow w;
        QVERIFY(openShown(w, "planar_2r.json"));
        w.setEditHoldLimit(20000);  // the hold ends with the result, however long a loaded machine takes
        auto* table = w.findChild<QTableView*>("dh-table");
        QVERIFY(table);
        PaintCounter paints;
        table->viewport()->installEventFilter(&paints);
        int cellPaintsBeforeResult = -1;
        const auto connection = connect(&w, &MainWindow::resultShown, this, [&] {
            if (cellPaintsBeforeResult < 0) cellPaintsBeforeResult = paints.count;
        });
        JointTableModel& model = w.editor().joints();
        QVERIFY(model.setData(model.index(0, JointTableModel::A), "1.25", Qt::EditRole));
        QVERIFY(checked(w));  // first the check: before it nothing is busy yet, and settled() would pass at once
        QVERIFY(settled(w));
        QVERIFY(ll::test::nextFrameDrawn(w));  // the frame after the result
        disconnect(connection);
        QCOMPARE(cellPaintsBeforeResult, 0);
        QVERIFY2(paints.count >= 1, "the edited cell was never painted");
        // An invalid edit has no result to wait for: its marked cell is painted at once.
        paints.count = 0;
        QVERIFY(model.setData(model.index(0, JointTableModel::A), "-", Qt::EditRole));
        QVERIFY(checked(w));
        QTRY_VERIFY_WITH_TIMEOUT(paints.count >= 1, 5000);  // long before the 20 s limit: released by the check
    }

    // An invalid cell is marked with the core's message; the last valid model stays.
    void invalidCellShowsItsErrorAndKeepsTheLastValidModel() {
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.show();
        QVERIFY(w.openFile(example("planar_2r.json"), nullptr, true));
        QVERIFY(settled(w));
        const int request = w.result()->request;
        JointTableModel& model = w.editor().joints();
        const QModelIndex mass = model.index(1, JointTableModel::Mass);
        QVERIFY(model.setData(mass, "-2", Qt::EditRole));
        QVERIFY(checked(w));
        QVERIFY(w.document().hasErrors());
        const QString tip = model.data(mass, Qt::ToolTipRole).toString();
        QVERIFY2(tip.startsWith("error:") && tip.contains("-2"), qPrintable(tip));
        QCOMPARE(model.data(mass, Qt::BackgroundRole).value<QBrush>().color(), QColor(255, 190, 190));
        QVERIFY(w.editor().diagnosticLines().join('\n').contains("robot.joints[1].mass"));
        // The cell shows what was typed; the model on screen is still the valid one.
        QCOMPARE(model.data(mass, Qt::DisplayRole).toString(), QString("-2"));
        QCOMPARE(w.document().validScene().robot.joints[1].link.mass, 1.5);
        QVERIFY(ll::test::idle(w));  // no run of the invalid scene comes
        QCOMPARE(w.result()->request, request);
        QCOMPARE(w.result()->scene->robot.joints[1].link.mass, 1.5);
        // An unknown parameter in an expression names it.
        QVERIFY(model.setData(model.index(0, JointTableModel::A), "a9*2", Qt::EditRole));
        QVERIFY(checked(w));
        QVERIFY2(model.data(model.index(0, JointTableModel::A), Qt::ToolTipRole).toString().contains("a9"),
                 qPrintable(model.data(model.index(0, JointTableModel::A), Qt::ToolTipRole).toString()));
        QCOMPARE(w.document().validScene().robot.joints[0].dh.a, 1.0);
    }

    // The editor names a field as JSON counts it with its joint in words, and an absurd
    // magnitude as such (not as a singular B), in the cell's tip and the checks list.
    void absurdMagnitudesAreNamedInTheEditor_data() {
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("typed");
        QTest::addColumn<QString>("expected");
        QTest::newRow("d = 1e300") << int(JointTableModel::D) << "1e300"
                                   << "robot.joints[0].d (joint 1): absurdly large length 1e+300 m";
        QTest::newRow("a = 1e-12") << int(JointTableModel::A) << "1e-12"
                                   << "robot.joints[0].a (joint 1): absurdly small length 1e-12 m";
        QTest::newRow("mass = 1e10") << int(JointTableModel::Mass) << "1e10"
                                     << "robot.joints[0].mass (joint 1): absurdly large mass 1e+10 kg";
        QTest::newRow("mass = 1e-12") << int(JointTableModel::Mass) << "1e-12"
                                      << "robot.joints[0].mass (joint 1): absurdly small mass 1e-12 kg";
        QTest::newRow("Izz = 1e10") << int(JointTableModel::Izz) << "1e10"
                                    << "robot.joints[0].inertia.zz (joint 1): absurdly large inertia";
        QTest::newRow("Izz = 1e-20") << int(JointTableModel::Izz) << "1e-20"
                                     << "robot.joints[0].inertia.zz (joint 1): absurdly small inertia";
    }
    void absurdMagnitudesAreNamedInTheEditor() {
        QFETCH(int, column);
        QFETCH(QString, typed);
        QFETCH(QString, expected);
        MainWindow w;
        QVERIFY(shownOn(w, "planar_2r.json"));
        JointTableModel& model = w.editor().joints();
        const QModelIndex cell = model.index(0, column);
        QVERIFY(model.setData(cell, typed, Qt::EditRole));
        QVERIFY(checked(w));
        const QString lines = w.editor().diagnosticLines().join('\n');
        QVERIFY2(lines.contains(expected), qPrintable(lines));
        QVERIFY2(!lines.contains("B(q)"), qPrintable(lines));
        const QString tip = model.data(cell, Qt::ToolTipRole).toString();
        QVERIFY2(tip.startsWith("error: absurdly"), qPrintable(tip));
        QVERIFY(w.document().undoStack()->canUndo());
    }

    // Gravity typed beyond any physical range, in the Initial & gravity tab: named as such.
    void absurdGravityIsNamedInTheEditor() {
        MainWindow w;
        QVERIFY(shownOn(w, "planar_2r.json"));
        ll::ui::FieldListModel& fields = w.editor().initialState();
        int gravityY = -1;
        for (int r = 0; r < fields.rowCount(); ++r)
            if (fields.row(r).field == "effects.gravity[1]") gravityY = r;
        QVERIFY(gravityY >= 0);
        for (const auto& [typed, expected] : {std::pair{"-1e4", "effects.gravity: absurdly large gravity 10000 m/s²"},
                                              {"-1e-9", "effects.gravity: absurdly small gravity 1e-09 m/s²"}}) {
            QVERIFY(fields.setData(fields.index(gravityY, ll::ui::FieldListModel::Value), typed, Qt::EditRole));
            QVERIFY(checked(w));
            const QString lines = w.editor().diagnosticLines().join('\n');
            QVERIFY2(lines.contains(QString::fromUtf8(expected)) && !lines.contains("B(q)"), qPrintable(lines));
        }
    }

    // One value that makes B singular is named in the checks list: link 2's point mass
    // moved onto joint 2's axis (com x := -a2) makes joint 2 move nothing.
    void theEditThatMadeBSingularIsNamed() {
        const QString path = dir_.filePath("point_masses.json");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(R"json({"format": "lagrangelab-scene/1", "name": "two point masses", "robot": {"convention": "standard", "joints": [
            {"type": "revolute", "a": 1, "mass": 1, "com": [-0.5, 0, 0]},
            {"type": "revolute", "a": 1.5, "mass": 1, "com": [-0.75, 0, 0]}]}, "effects": {"gravity": [0, -9.81, 0]}})json");
        f.close();
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.show();
        QVERIFY(w.openFile(path, nullptr, true));
        QVERIFY(w.editor().joints().setData(w.editor().joints().index(1, JointTableModel::ComX), "-1.5", Qt::EditRole));
        QVERIFY(checked(w));
        const QString lines = w.editor().diagnosticLines().join('\n');
        QVERIFY2(lines.contains("robot.joints[1] (joint 2): joint 2 moves no mass or inertia"), qPrintable(lines));
        QVERIFY2(lines.contains("hint: it happened with your edit of robot.joints[1].com[0] (joint 2)"), qPrintable(lines));
    }

    // File → Import URDF…: the PUMA-like test robot opens as a new, unsaved scene whose
    // DH table is the known one (tests/urdf/puma_like.urdf), simulated and derived like any
    // other; a file that is not URDF is refused with its name and the open scene kept.
    void aUrdfRobotIsImported() {
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.show();
        QVERIFY(w.openFile(QString(LL_EXAMPLES_DIR) + "/planar_2r.json", nullptr, true));
        QStringList errors;
        QVERIFY(!w.files().importUrdf(QString(LL_EXAMPLES_DIR) + "/planar_2r.json", &errors, true));
        QVERIFY2(errors.join('\n').contains("planar_2r.json: not a URDF robot"), qPrintable(errors.join('\n')));
        QCOMPARE(w.document().validScene().dof(), 2);  // kept
        QVERIFY2(w.files().importUrdf(QString(LL_SOURCE_DIR) + "/tests/urdf/puma_like.urdf", &errors, true), qPrintable(errors.join('\n')));
        QVERIFY(checked(w));
        const ll::Scene& scene = w.document().validScene();
        QCOMPARE(scene.dof(), 6);
        QVERIFY(std::abs(scene.robot.joints[1].dh.a - 0.4318) < 1e-12 && std::abs(scene.robot.joints[0].dh.d - 0.672) < 1e-12);
        QVERIFY(w.document().path().isEmpty());
        QVERIFY(w.document().isModified());  // unsaved: closing asks
        QVERIFY(ll::test::waitUntil([&] { return w.result() && w.result()->visual && w.result()->visual->dof() == 6; }, 60000));
    }

    // A parameter typed over in one cell and still used in another is pointed out: the
    // 2R's a = "a1" of joint 1 typed as 1.2 leaves a1 in link 1's COM (lc1-a1); typing over
    // the mass m1, used nowhere else, says nothing; undo takes the hint away.
    void aParameterLeftInUseIsPointedOut() {
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.show();
        QVERIFY(w.openFile(QString(LL_EXAMPLES_DIR) + "/planar_2r.json", nullptr, true));
        const auto hints = [&] { return w.editor().diagnosticLines().filter("hint:").join('\n'); };
        QVERIFY(w.editor().joints().setData(w.editor().joints().index(0, JointTableModel::A), "1.2", Qt::EditRole));
        QVERIFY(checked(w));
        QVERIFY2(hints().contains("hint: a1 is no longer in robot.joints[0].a (joint 1) but still in robot.joints[0].com[0] (joint 1)"),
                 qPrintable(w.editor().diagnosticLines().join('\n')));
        w.document().undoStack()->undo();
        QVERIFY(checked(w));
        QVERIFY2(hints().isEmpty(), qPrintable(hints()));
        QVERIFY(w.editor().joints().setData(w.editor().joints().index(0, JointTableModel::Mass), "2", Qt::EditRole));
        QVERIFY(checked(w));
        QVERIFY2(hints().isEmpty(), qPrintable(hints()));
    }

    // Every system lists its own steps: a typed Lagrangian 0, 6, 7, 8 with its own titles
    // (Previous/Next skip the steps it has not; the Text tab counts them), a robot its nine;
    // the editor opens on the tab that describes the scene.
    void everySystemListsItsOwnSteps() {
        MainWindow w;
        QVERIFY(shownOn(w, "mass_spring_pair_lagrangian.json"));
        QTRY_VERIFY_WITH_TIMEOUT(w.derivationView().listedSteps().size() == 4, 30000);
        const QStringList rows = w.derivationView().listedSteps();
        QVERIFY2(rows[0].startsWith("Step 0: Generalized coordinates") && rows[1].startsWith("Step 6:") && rows[2].startsWith("Step 7:") &&
                     rows[3].startsWith("Step 8:"),
                 qPrintable(rows.join(" | ")));
        QVERIFY2(rows[0].contains("steps 1–5 are a robot's"), qPrintable(rows[0]));  // why it goes from 0 to 6 (issue 51)
        QCOMPARE(w.editor().currentTabName(), QString("Lagrangian"));
        w.derivationView().showStep(0);
        w.derivationView().nextStep();
        QCOMPARE(w.derivationView().step(), 6);
        w.derivationView().showStep(3);  // a step it has not: the next it has
        QCOMPARE(w.derivationView().step(), 6);
        w.derivationPanel().showStep(0);
        w.derivationPanel().nextStep();
        QCOMPARE(w.derivationPanel().step(), 6);
        QCOMPARE(int(w.derivationPanel().steps().size()), 4);

        QVERIFY(w.openFile(example("planar_2r.json"), nullptr, true));
        QVERIFY(settled(w));
        QTRY_VERIFY_WITH_TIMEOUT(w.derivationView().listedSteps().size() >= 9, 30000);
        QVERIFY(w.derivationView().listedSteps()[1].startsWith("Step 1: Kinematic model"));
        QVERIFY(!w.derivationView().listedSteps()[0].contains("robot's"));
        QCOMPARE(w.editor().currentTabName(), QString("DH"));
    }

    // Undo and redo restore the typed text, the valid model and the simulation.
    void undoAndRedoRestore() {
        MainWindow w;
        QVERIFY(shownOn(w, "planar_2r.json"));
        JointTableModel& model = w.editor().joints();
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
            JointTableModel& model = w.editor().joints();
            model.setDegrees(true);
            model.setData(model.index(1, JointTableModel::Alpha), "90", Qt::EditRole);  // degrees: stored as "90°"
            QVERIFY(checked(w));
            model.setData(model.index(0, JointTableModel::Mass), "m1*1.25", Qt::EditRole);
            QVERIFY(checked(w));
            QString error;
            QVERIFY2(w.files().saveTo(path, &error), qPrintable(error));
            QVERIFY(!w.document().isModified());
            model.setData(model.index(0, JointTableModel::D), "0.1", Qt::EditRole);
            QVERIFY(checked(w));
            QVERIFY(w.files().saveTo(path, &error));
            QVERIFY(QFile::exists(path + ".bak"));  // the previous save is the recovery copy
        }
        const ll::LoadedScene loaded = ll::loadScene(path.toStdString());
        QCOMPARE(loaded.scene.robot.joints[1].dh.alpha, M_PI / 2);
        QCOMPARE(loaded.scene.robot.joints[0].link.mass, 2.5);
        QCOMPARE(loaded.scene.robot.joints[0].dh.d, 0.1);
        QCOMPARE(QString::fromStdString(loaded.scene.expressions.at("robot.joints[1].alpha")), QString("90°"));
        const ll::LoadedScene backup = ll::loadScene((path + ".bak").toStdString());
        QCOMPARE(backup.scene.robot.joints[0].dh.d, 0.0);
        MainWindow again;
        again.setAskBeforeClosing(false);
        QVERIFY(again.openFile(path, nullptr, true));
        QCOMPARE(again.document().validScene().robot.joints[0].link.mass, 2.5);
        QCOMPARE(again.editor().joints().data(again.editor().joints().index(1, JointTableModel::Alpha), Qt::DisplayRole).toString(),
                 QString("90°"));
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
            w->editor().joints().setData(w->editor().joints().index(0, JointTableModel::A), "1.2", Qt::EditRole);
            QVERIFY(checked(*w));
            w->autosave().write();  // what the 5 s autosave timer does
            QVERIFY(QFile::exists(w->autosave().ownFile()));
            // The crash: the window goes away without closing (no closeEvent, no save).
            delete w;
        }
        QCOMPARE(ll::loadScene(path.toStdString()).scene.robot.joints[0].dh.a, 1.0);  // never saved
        MainWindow next;
        next.setAskBeforeClosing(false);
        QVERIFY(next.openFile(path, nullptr, true));
        const std::vector<ll::ui::RecoveryCopy> left = next.autosave().leftBehind();
        QCOMPARE(int(left.size()), 1);
        QVERIFY(next.autosave().restore(left[0]));
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
        QVERIFY(next.files().saveTo(path));
        QCOMPARE(ll::loadScene(path.toStdString()).scene.robot.joints[0].dh.a, 1.2);
        QVERIFY(next.autosave().ownFile().isEmpty() && next.autosave().leftBehind().empty());  // a save discards the recovery copy
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
        w.editor().joints().setData(w.editor().joints().index(0, JointTableModel::A), "1.1", Qt::EditRole);
        QVERIFY(checked(w));
        const std::string text = w.document().text();
        const int edits = w.document().undoStack()->count();
        QStringList errors;
        QVERIFY(!w.openFile(bad, &errors, true));
        QVERIFY2(errors.size() >= 2, qPrintable(errors.join('\n')));
        for (const QString& e : errors) QVERIFY2(e.startsWith(bad + ": "), qPrintable(e));
        QVERIFY2(errors.join('\n').contains("robot.joints[1].type"), qPrintable(errors.join('\n')));
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
        flushEvents();
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
        flushEvents();
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
        QVERIFY(w.sceneView().trailPoints() >= 1);  // the motion's trail, up to the playback time
        w.teach(q);
        QCOMPARE(w.sceneView().trailPoints(), std::size_t(0));  // a teach pose is not on the motion's path
        // Planar 2R (examples/planar_2r.json: q1 from the horizontal, gravity −y):
        // E_pot = g (m1 lc1 s1 + m2 (a1 s1 + lc2 s12)); at q = (0, π/2): 9.81·1.5·0.4.
        const QString readout = w.teachPanel().readout();
        QVERIFY2(readout.contains("E_pot(q) = 5.886 J"), qPrintable(readout));
        // The drawn end effector is at (a1, a2) = (1, 0.8).
        const Eigen::Vector3d tip = w.result()->visual->endEffectorPosition();
        QVERIFY2((tip - Eigen::Vector3d(1.0, 0.8, 0)).norm() < 1e-3,
                 qPrintable(QString("%1 %2 %3").arg(tip.x()).arg(tip.y()).arg(tip.z())));
        // The typeset derivation gains a last step, its results at the pose, in the closed forms
        // of the 2R (examples/planar_2r.json's description) at c2 = 0, c12 = 0:
        // b11 = I1 + m1 lc1² + I2 + m2 (a1² + lc2² + 2 a1 lc2 c2) = 1/6 + 0.5 + 0.08 + 1.5·1.16,
        // b12 = I2 + m2 (lc2² + a1 lc2 c2) = 0.32, g1 = (m1 lc1 + m2 a1) g c1 + m2 lc2 g c12 = 2.5·9.81.
        const auto cell = [&](const std::string& name, int i, int j) {
            const present::DisplayStep* pose = w.derivationView().poseResults();
            if (!pose) return QString("no results step");
            for (const present::DisplayItem& item : pose->items)
                if (item.name == name && item.value && i < int(item.value->rows.size()))
                    return QString::fromStdString(present::renderDisplay(*item.value->rows[i][j], present::DisplayStyle::Text));
            return QString("no ") + QString::fromStdString(name);
        };
        QCOMPARE(cell("B", 0, 0), QString("2.487"));
        QCOMPARE(cell("B", 0, 1), QString("0.32"));
        QCOMPARE(cell("B", 1, 1), QString("0.32"));
        QVERIFY2(std::abs(cell("g", 0, 0).toDouble() - 24.525) < 0.006, qPrintable(cell("g", 0, 0)));
        QCOMPARE(cell("g", 1, 0), QString("0"));  // cos(π/2)'s rounding residue is not shown as 10⁻¹⁶
        w.showDerivationStep(ll::poseStepNumber);
        QCOMPARE(w.derivationView().step(), ll::poseStepNumber);
        q << 0.0, 0.0;  // stretched out: b11 = 1/6 + 0.5 + 0.08 + 1.5·(1 + 0.16 + 0.8)
        w.teach(q);
        QCOMPARE(cell("B", 0, 0), QString("3.687"));
        QCOMPARE(w.derivationView().step(), ll::poseStepNumber);
    }

    // One edit, one derivation: the typeset and text tabs show the same result of one
    // deriveDocument call (they used to derive twice, one after the other on the lock).
    void oneEditDerivesOnce() {
        MainWindow w;
        QVERIFY(openShown(w, "planar_2r.json"));
        QVERIFY(ll::test::idle(w));
        const long before = ll::documentDerivations();
        JointTableModel& model = w.editor().joints();
        QVERIFY(model.setData(model.index(0, JointTableModel::A), "1.5", Qt::EditRole));
        QVERIFY(checked(w));
        QVERIFY(settled(w));
        QVERIFY(ll::test::idle(w));  // anything else that would derive has had its chance
        QCOMPARE(ll::documentDerivations() - before, 1L);
        QVERIFY(w.derivation() && w.derivation()->display);
        QCOMPARE(w.derivationView().document().get(), w.derivation()->display.get());
        QCOMPARE(w.derivationPanel().text(), w.derivation()->text);
        QVERIFY(w.derivationPanel().text().section("Step 1.", 0, 0).contains("1.5"));
        // An invalid edit stops nothing for good: the valid scene's derivation is shown.
        // a1 = 5/4 is checked and starts deriving; the bad mass typed next stops that
        // derivation (its check needs the GiNaC lock), and once the mass is found bad the
        // valid scene, a1 = 5/4, is derived again and shown. The start delay keeps the
        // first derivation running while the mass is typed (the 2R derives in milliseconds
        // on a fast machine, and CI's once finished before the test looked).
        w.liveDerivation().setStartDelay(3000);
        QVERIFY(model.setData(model.index(0, JointTableModel::A), "1.25", Qt::EditRole));
        QVERIFY(checked(w));
        QVERIFY(w.liveDerivation().busy());
        w.liveDerivation().setStartDelay(0);  // the derivation after the stop starts at once
        const int runsBefore = w.liveDerivation().runs();
        QVERIFY(model.setData(model.index(1, JointTableModel::Mass), "-1", Qt::EditRole));
        QVERIFY(checked(w));
        QVERIFY(w.document().hasErrors());
        QTRY_VERIFY_WITH_TIMEOUT(!w.liveDerivation().busy(), 60000);
        QVERIFY(!w.derivation()->stopped);
        QCOMPARE(w.liveDerivation().runs(), runsBefore + 1);  // derived again once, after the stop
        QVERIFY2(w.derivationPanel().text().section("Step 1.", 0, 0).contains("1.25"), qPrintable(w.derivationPanel().text().left(400)));
    }

    // A ghost run with explicit Euler: a second, translucent robot in the 3D view and its
    // energy dashed in the plot, drifting where dopri5's stays put.
    void ghostRunShowsAnotherIntegrator() {
        MainWindow w;
        QVERIFY(openShown(w, "double_pendulum.json"));
        w.playback().pause();
        w.playback().setTime(3.0);
        const QImage alone = nextFrame(w);
        w.ghost().setIntegrator("euler");
        QTRY_VERIFY_WITH_TIMEOUT(w.ghost().result() != nullptr, 60000);
        QCOMPARE(QString::fromStdString(w.ghost().result()->simulation.stats.integrator), QString("euler"));
        // The classic lesson: Euler's energy drifts by orders of magnitude more.
        const double drift = w.ghost().result()->simulation.stats.maxRelEnergyError;
        const double reference = w.result()->simulation.stats.maxRelEnergyError;
        QVERIFY2(drift > 100 * reference && drift > 1e-3, qPrintable(QString("euler %1, dopri5 %2").arg(drift).arg(reference)));
        w.playback().setTime(3.0);
        const QImage withGhost = nextFrame(w);
        QVERIFY2(differing(alone, withGhost) > 0.002, qPrintable(QString("%1 of the view changed").arg(differing(alone, withGhost))));
        // The energy plot: a dashed E of the ghost, named after its integrator.
        QLineSeries* dashed = nullptr;
        for (QAbstractSeries* a : w.energyChart().chart()->series())
            if (auto* line = qobject_cast<QLineSeries*>(a); line && line->pen().style() == Qt::DashLine && line->name().contains("euler"))
                dashed = line;
        QVERIFY(dashed);
        QVERIFY(dashed->count() > 50);
        w.screenshot().save(dir_.filePath("ghost.png"));
        w.ghost().setIntegrator("");
        QVERIFY(!w.ghost().result());
        int dashedLeft = 0;
        for (QAbstractSeries* a : w.energyChart().chart()->series())
            if (auto* line = qobject_cast<QLineSeries*>(a); line && line->name().contains("euler")) ++dashedLeft;
        QCOMPARE(dashedLeft, 0);
        QVERIFY(differing(alone, nextFrame(w)) < 0.002);
    }

    // Every curve of the energy plot in a colour of its own (E − W is not E's purple),
    // where a scene does work on the system (the mass–spring pair driven by a torque).
    void energyCurvesHaveColoursOfTheirOwn() {
        MainWindow w;
        QVERIFY(openShown(w, "mass_spring_pair_torque.json"));
        QStringList names;
        QSet<QRgb> colours;
        for (QAbstractSeries* a : w.energyChart().chart()->series())
            if (auto* line = qobject_cast<QLineSeries*>(a); line && line->count() > 0) {
                names << line->name();
                colours.insert(line->pen().color().rgb());
            }
        QVERIFY2(names.contains("E − W") && names.contains("W"), qPrintable(names.join(", ")));
        QCOMPARE(int(colours.size()), int(names.size()));
    }

    // The work–precision tab runs the sweep on a worker with a progress bar that moves.
    void workPrecisionTabRunsWithProgress() {
        MainWindow w;
        QVERIFY(openShown(w, "simple_pendulum.json"));
        ll::ui::WorkPrecisionPane& pane = w.workPrecisionPane();
        auto* bar = pane.findChild<QProgressBar*>();
        QVERIFY(bar);
        QSet<int> seen;
        connect(bar, &QProgressBar::valueChanged, this, [&](int v) { seen.insert(v); });
        QSignalSpy done(&pane, &ll::ui::WorkPrecisionPane::finished);
        pane.run();
        QVERIFY(done.wait(300000));
        QVERIFY(pane.hasResult());
        QCOMPARE(bar->value(), 1000);
        QVERIFY2(seen.size() >= 5, qPrintable(QString("%1 progress values").arg(seen.size())));
        const QString png = dir_.filePath("wp.png");
        QString error;
        QVERIFY2(pane.saveImage(png, &error), qPrintable(error));
        const QImage image(png);
        QVERIFY(!image.isNull());
        QVERIFY(content(image, image.rect().adjusted(60, 40, -60, -60)).second > 4);
        w.screenshot().save(dir_.filePath("work_precision_tab.png"));
        // Open large: the plot in its own window, most of the screen, drawn.
        QWidget* large = pane.openLarge();
        QVERIFY(large && QTest::qWaitForWindowExposed(large));
        const QRect screen = large->screen()->availableGeometry();
        QVERIFY2(large->width() >= screen.width() * 0.85 && large->height() >= screen.height() * 0.75,
                 qPrintable(QString("%1x%2").arg(large->width()).arg(large->height())));
        const QImage shown = large->grab().toImage();
        QVERIFY(content(shown, shown.rect().adjusted(60, 40, -60, -60)).second > 4);
        shown.save(dir_.filePath("work_precision_large.png"));
        large->close();
    }

    // Presentation mode: full screen, larger fonts, the model hidden; space, the arrows
    // and F work wherever the focus is, and Escape leaves.
    void presentationModeKeys() {
        MainWindow w;
        QVERIFY(openShown(w, "planar_2r.json"));
        w.playback().pause();
        const double font = QApplication::font().pointSizeF();
        auto axisFont = [&] {
            return static_cast<QValueAxis*>(w.energyChart().chart()->axes(Qt::Horizontal).front())->labelsFont().pointSizeF();
        };
        const double chartFont = axisFont();
        w.presentationMode().setOn(true);
        QTRY_VERIFY(w.isFullScreen());
        QVERIFY(w.presentationMode().on());
        QCOMPARE(QApplication::font().pointSizeF(), font * 1.6);
        QVERIFY(!w.findChild<QDockWidget*>("model")->isVisible());
        QVERIFY(ll::test::nextFrameDrawn(w));  // laid out for presenting, the camera refitted
        w.screenshot().save(dir_.filePath("presentation.png"));
        // The plots grow with the window: Qt Charts keeps its own fonts.
        QCOMPARE(axisFont(), chartFont * 1.4);
        const auto energyCurves = w.energyChart().chart()->series();
        QVERIFY(!energyCurves.isEmpty());
        QCOMPARE(static_cast<QLineSeries*>(energyCurves.back())->pen().widthF(), 1.8 * 1.4);
        // The focus on a push button, which would take the space as a click.
        auto* next = w.derivationView().findChild<QPushButton*>();
        QVERIFY(next);
        next->setFocus();
        const int step = w.derivationView().step();
        QTest::keyClick(next, Qt::Key_Right);
        QCOMPARE(w.derivationView().step(), step + 1);
        QTest::keyClick(next, Qt::Key_Left);
        QCOMPARE(w.derivationView().step(), step);
        QVERIFY(!w.playback().isPlaying());
        QTest::keyClick(next, Qt::Key_Space);
        QVERIFY(w.playback().isPlaying());
        QTest::keyClick(next, Qt::Key_Space);
        QVERIFY(!w.playback().isPlaying());
        w.playback().setTime(0);
        // Zoom in with the wheel, then F fits the view again (fitted first at this size:
        // the fit of the smaller window before full screen kept its distance).
        QTest::keyClick(next, Qt::Key_F);
        const QImage before = nextFrame(w);
        const QPoint centre = w.sceneView().rect().center();
        QWheelEvent wheel(centre, w.sceneView().mapToGlobal(centre), QPoint(), QPoint(0, 600), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(w.sceneView().surface(), &wheel);
        const QImage zoomed = nextFrame(w);
        QVERIFY2(differing(before, zoomed) > 0.01, qPrintable(QString::number(differing(before, zoomed))));
        QTest::keyClick(next, Qt::Key_F);
        const QImage refitted = nextFrame(w);
        QVERIFY2(differing(before, refitted) < 0.002, qPrintable(QString::number(differing(before, refitted))));
        QTest::keyClick(next, Qt::Key_Escape);
        QTRY_VERIFY(!w.isFullScreen());
        QVERIFY(!w.presentationMode().on());
        QCOMPARE(QApplication::font().pointSizeF(), font);
        QVERIFY(w.findChild<QDockWidget*>("model")->isVisible());
    }

    // Presentation mode on a projector's 1280×720 and 1920×1080: the 3D view takes at least
    // half the window, the robot at least 60 % of the view's height (its projection through
    // the view's camera at the shown pose), and the derivation and the energy plot stand
    // beside the view, not under it.
    void presentationGivesTheRobotTheScreen_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QSize>("size");
        for (const char* scene : {"puma560.json", "panda.json"})
            for (QSize size : {QSize(1280, 720), QSize(1920, 1080)})
                QTest::newRow(qPrintable(QString("%1 %2x%3").arg(scene).arg(size.width()).arg(size.height()))) << QString(scene) << size;
    }
    void presentationGivesTheRobotTheScreen() {
        QFETCH(QString, scene);
        QFETCH(QSize, size);
        MainWindow w;
        QVERIFY(openShown(w, qPrintable(scene)));
        w.playback().pause();
        const QSize docked = w.size();
        w.presentationMode().setSize(size);
        w.presentationMode().setOn(true);
        QTRY_COMPARE(w.size(), size);
        QVERIFY(ll::test::nextFrameDrawn(w));  // laid out for presenting, the camera refitted
        ll::ui::SceneView& view = w.sceneView();
        const double share = double(view.width()) * view.height() / (double(w.width()) * w.height());
        const double robot = view.sceneHeightInView();
        qInfo("%s: 3D view %dx%d (%.0f %% of the window), robot %.0f %% of its height", qPrintable(scene), view.width(), view.height(),
              100 * share, 100 * robot);
        QVERIFY2(share >= 0.5, qPrintable(QString::number(share)));
        QVERIFY2(robot >= 0.6, qPrintable(QString::number(robot)));
        QVERIFY2(robot <= 1.0, qPrintable(QString::number(robot)));  // and all of it in view
        const int viewRight = view.mapTo(&w, QPoint(view.width(), 0)).x();
        for (const char* dock : {"derivation", "plots"}) {
            auto* d = w.findChild<QDockWidget*>(dock);
            QVERIFY(d && d->isVisible());
            QVERIFY2(d->x() >= viewRight, dock);
        }
        // Played through, the robot never leaves the picture: the camera backs away as the
        // motion needs (a falling Panda), never closer.
        const double aspect = double(view.width()) / view.height();
        double last = (view.camera().eye - view.camera().centre).norm();
        std::vector<Eigen::Vector4d> extent;
        for (int k = 0; k <= 40; ++k) {
            w.playback().setTime(w.playback().endTime() * k / 40);
            const double distance = (view.camera().eye - view.camera().centre).norm();
            view.visualScene()->currentExtent(extent);
            QVERIFY2(ll::distanceToHold(view.camera(), extent, aspect) <= distance * (1 + 1e-9), qPrintable(QString::number(k)));
            QVERIFY(distance >= last * (1 - 1e-12));
            last = distance;
        }
        // Leaving: the camera that framed the wide view (backed away for the whole motion)
        // is refitted to the docked view, so the robot is not left small in it.
        w.presentationMode().setOn(false);
        QTRY_COMPARE(w.size(), docked);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs((view.camera().eye - view.camera().centre).norm() - last) > 1e-9, 5000);
        QVERIFY(ll::test::nextFrameDrawn(w));
        const double docked_robot = view.sceneHeightInView();
        qInfo("%s after presenting: 3D view %dx%d, robot %.0f %% of its height", qPrintable(scene), view.width(), view.height(),
              100 * docked_robot);
        w.screenshot().save(dir_.filePath(QString("after_presenting_%1_%2.png").arg(scene).arg(size.width())));
        QVERIFY2(docked_robot >= 0.4, qPrintable(QString::number(docked_robot)));
        QVERIFY2(docked_robot <= 1.0, qPrintable(QString::number(docked_robot)));
    }

    // A camera the lecturer moved while presenting stays as they left it.
    void leavingPresentationKeepsAMovedCamera() {
        MainWindow w;
        QVERIFY(openShown(w, "planar_2r.json"));
        w.playback().pause();
        const QSize docked = w.size();
        w.presentationMode().setSize(QSize(1280, 720));
        w.presentationMode().setOn(true);
        QTRY_COMPARE(w.size(), QSize(1280, 720));
        QVERIFY(ll::test::nextFrameDrawn(w));
        ll::ui::SceneView& view = w.sceneView();
        view.zoomBy(0.5);
        const double moved = (view.camera().eye - view.camera().centre).norm();
        w.presentationMode().setOn(false);
        QTRY_COMPARE(w.size(), docked);
        for (int k = 0; k < 5; ++k) flushEvents();
        QVERIFY(view.cameraMovedByUser());
        QCOMPARE((view.camera().eye - view.camera().centre).norm(), moved);
    }

    // File → Examples → Gallery: every example of examples/ with its picture (320×200, with
    // a drawing on it: scripts/lab thumbnails was run for each), and choosing one opens it.
    void galleryShowsEveryExampleWithItsPicture() {
        MainWindow w;
        QVERIFY(openShown(w, "planar_2r.json"));
        ll::ui::ExampleGallery gallery(&w);
        const QStringList files = QDir(LL_EXAMPLES_DIR).entryList({"*.json"}, QDir::Files, QDir::Name);
        QStringList expected;
        for (const QString& f : files) expected << ":/examples/" + f;
        QCOMPARE(gallery.examples(), expected);
        for (int row = 0; row < files.size(); ++row) {
            QVERIFY2(gallery.hasPicture(row), qPrintable(files[row] + ": no picture (run scripts/lab thumbnails)"));
            const QImage picture(":/thumbnails/" + QFileInfo(files[row]).completeBaseName() + ".png");
            QCOMPARE(picture.size(), QSize(320, 200));
            QVERIFY2(content(picture, picture.rect()).first > 0.02, qPrintable(files[row]));
        }
        gallery.show();
        QVERIFY(QTest::qWaitForWindowExposed(&gallery));
        gallery.grab().save(dir_.filePath("gallery.png"));  // LL_TEST_KEEP=1: to look at
        QSignalSpy chosen(&gallery, &ll::ui::ExampleGallery::chosen);
        const int panda = static_cast<int>(files.indexOf("panda.json"));
        QVERIFY(panda >= 0);
        gallery.list().setCurrentRow(panda);
        emit gallery.list().itemActivated(gallery.list().item(panda));
        QCOMPARE(chosen.size(), 1);
        QCOMPARE(chosen.front().front().toString(), QString(":/examples/panda.json"));
    }

    // The plots lay their ticks out for the space they get: at the window's default size
    // and in presentation mode, the labels of neighbouring ticks (as Qt Charts writes
    // them, in the axis' font) do not overlap on either axis of either plot.
    void plotTickLabelsDoNotOverlap() {
        MainWindow w;
        QVERIFY(openShown(w, "double_pendulum.json"));
        w.playback().pause();
        const auto check = [](ll::ui::TrajectoryChart& chart, const char* where) {
            const QRectF area = chart.chart()->plotArea();
            // The legend beside the plot when it is narrow next to the plot, below otherwise;
            // never over the plot area.
            QLegend* legend = chart.chart()->legend();
            const QRectF legendBox = legend->geometry();
            QVERIFY2(!legendBox.intersects(area), where);
            if (legend->alignment() == Qt::AlignRight && chart.height() >= 200) QVERIFY2(legendBox.width() <= 0.25 * chart.width(), where);
            QVERIFY2(area.width() > 50 && area.height() > 30, where);
            for (Qt::Orientation o : {Qt::Horizontal, Qt::Vertical}) {
                auto* axis = static_cast<QValueAxis*>(chart.chart()->axes(o).front());
                // The tick values: evenly spread (tickCount) or every interval from the anchor.
                QList<double> ticks;
                if (axis->tickType() == QValueAxis::TicksDynamic) {
                    QVERIFY(axis->tickInterval() > 0);
                    const double first = axis->tickAnchor() +
                                         std::ceil((axis->min() - axis->tickAnchor()) / axis->tickInterval() - 1e-9) * axis->tickInterval();
                    for (double v = first; v <= axis->max() + 1e-9 * axis->tickInterval(); v += axis->tickInterval()) ticks << v;
                } else {
                    for (int k = 0; k < axis->tickCount(); ++k)
                        ticks << axis->min() + k * (axis->max() - axis->min()) / (axis->tickCount() - 1);
                }
                const int n = static_cast<int>(ticks.size());
                QVERIFY(n >= 2);
                const QFontMetricsF fm(axis->labelsFont());
                const QString format = axis->labelFormat().isEmpty() ? "%.1f" : axis->labelFormat();
                double widest = 0;
                for (double v : ticks) widest = std::max(widest, fm.horizontalAdvance(QString::asprintf(format.toLatin1().constData(), v)));
                const double spacing =
                    (o == Qt::Horizontal ? area.width() : area.height()) * (ticks[1] - ticks[0]) / (axis->max() - axis->min());
                const double needed = o == Qt::Horizontal ? widest : fm.height();
                if (o == Qt::Horizontal && axis->tickType() == QValueAxis::TicksDynamic) {  // round seconds
                    const double interval = axis->tickInterval(), mantissa = interval / std::pow(10.0, std::floor(std::log10(interval)));
                    QVERIFY2(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 2.5) < 1e-9 ||
                                 std::abs(mantissa - 5) < 1e-9,
                             qPrintable(QString("%1: time ticks every %2 s").arg(where).arg(interval)));
                }
                QVERIFY2(spacing > needed, qPrintable(QString("%1 %2: %3 ticks %4 px apart, labels %5 px")
                                                          .arg(where)
                                                          .arg(o == Qt::Horizontal ? "x" : "y")
                                                          .arg(n)
                                                          .arg(spacing)
                                                          .arg(needed)));
            }
        };
        flushEvents();
        check(w.energyChart(), "energy");
        for (QTabWidget* tabs : w.findChildren<QTabWidget*>())  // the joints' tab, so its plot is laid out
            for (QWidget* p = &w.jointsChart(); p; p = p->parentWidget())
                if (tabs->indexOf(p) >= 0) tabs->setCurrentWidget(p);
        flushEvents();
        check(w.jointsChart(), "joints");
        w.presentationMode().setOn(true);
        QTRY_VERIFY(w.isFullScreen());
        flushEvents();
        check(w.energyChart(), "energy presenting");
        w.presentationMode().setOn(false);
        // A small plot (a narrow dock) at presentation scale: fewer ticks, still apart.
        ll::ui::TrajectoryChart small(ll::ui::TrajectoryChart::Kind::Energy);
        small.setScale(1.4);
        small.setTrajectory(w.result()->simulation.trajectory);
        small.resize(420, 150);
        small.show();
        QVERIFY(QTest::qWaitForWindowExposed(&small));
        flushEvents();
        check(small, "small");
    }

    // The window remembers its size and its docks between runs.
    void windowRemembersItsLayout() {
        QString before;
        const auto layout = [](MainWindow& w) {
            QStringList out{QString("window %1x%2").arg(w.width()).arg(w.height())};
            for (QDockWidget* dock : w.findChildren<QDockWidget*>())
                out << QString("%1 %2x%3").arg(dock->objectName()).arg(dock->width()).arg(dock->height());
            return out.join("; ");
        };
        {
            MainWindow w;
            w.rememberLayout();
            QVERIFY(openShown(w, "planar_2r.json"));
            w.resize(1150, 720);
            flushEvents();
            w.resizeDocks({w.findChild<QDockWidget*>("plots")}, {300}, Qt::Vertical);
            flushEvents();
            before = layout(w);
            QVERIFY(w.close());
        }
        MainWindow again;  // as the program starts it: its default size, then what was remembered
        again.setAskBeforeClosing(false);
        again.resize(1280, 800);
        again.rememberLayout();
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again) && again.openFile(example("planar_2r.json"), nullptr, true) && settled(again, 120));
        QTRY_COMPARE_WITH_TIMEOUT(layout(again), before, 5000);
    }

    // Leaving presentation mode puts every dock and the window back exactly where they were
    // (the docks stayed resized before).
    void leavingPresentationRestoresTheLayout() {
        MainWindow w;
        QVERIFY(openShown(w, "planar_2r.json"));
        w.playback().pause();
        w.resize(1100, 700);  // smaller than the screen, so full screen resizes it
        flushEvents();
        const auto layout = [&] {
            QStringList out{QString("window %1x%2").arg(w.width()).arg(w.height())};
            for (QDockWidget* dock : w.findChildren<QDockWidget*>())  // a hidden dock (the Lesson's) has no place to keep
                out << (dock->isVisible() ? QString("%1 %2,%3 %4x%5")
                                                .arg(dock->objectName())
                                                .arg(dock->x())
                                                .arg(dock->y())
                                                .arg(dock->width())
                                                .arg(dock->height())
                                          : dock->objectName() + " hidden");
            return out.join("; ");
        };
        const QString before = layout();
        w.presentationMode().setOn(true);
        QTRY_VERIFY(w.isFullScreen());
        flushEvents();
        QVERIFY2(layout() != before, "presentation mode changed nothing");
        w.presentationMode().setOn(false);
        QTRY_VERIFY(!w.isFullScreen());
        QTRY_COMPARE_WITH_TIMEOUT(layout(), before, 5000);
    }

    // The mouse over a joint in the 3D view (the GL view's own native window) selects its
    // DH row and lights the joint up; a click makes the row's cell current.
    void hoveringAJointSelectsItsRow() {
        MainWindow w;
        QVERIFY(openShown(w, "planar_2r.json"));
        w.playback().pause();
        nextFrame(w);
        ll::ui::SceneView& view = w.sceneView();
        QPoint at;
        int joint = -1;
        for (int y = 2; y < view.height() && joint < 0; y += 5)
            for (int x = 2; x < view.width() && joint < 0; x += 5)
                if ((joint = view.jointAt({x, y})) >= 0) at = {x, y};
        QVERIFY2(joint >= 0, "no joint found under any point of the view");
        auto* table = w.findChild<QTableView*>("dh-table");
        QVERIFY(table);
        table->clearSelection();
        QMouseEvent move(QEvent::MouseMove, QPointF(at), view.surface()->mapToGlobal(QPointF(at)), Qt::NoButton, Qt::NoButton,
                         Qt::NoModifier);
        QApplication::sendEvent(view.surface(), &move);
        QVERIFY(table->selectionModel()->isRowSelected(joint, {}));
        QMouseEvent press(QEvent::MouseButtonPress, QPointF(at), view.surface()->mapToGlobal(QPointF(at)), Qt::LeftButton, Qt::LeftButton,
                          Qt::NoModifier);
        QApplication::sendEvent(view.surface(), &press);
        QCOMPARE(table->currentIndex().row(), joint);
    }

    // A scene file dropped on the window opens.
    void droppingASceneFileOpensIt() {
        MainWindow w;
        QVERIFY(openShown(w, "planar_2r.json"));
        const QString path = dir_.filePath("dropped.lagrange");
        QFile::remove(path);
        QVERIFY(QFile::copy(example("scara.json"), path));
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(path)});
        const QPoint at = w.rect().center();
        QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &drop);
        QTRY_COMPARE_WITH_TIMEOUT(w.document().path(), path, 30000);
        QCOMPARE(w.document().validScene().robot.dof(), ll::loadScene(path.toStdString()).scene.robot.dof());
        QVERIFY(settled(w));
        QCOMPARE(QString::fromStdString(w.result()->scene->name), QString::fromStdString(ll::loadScene(path.toStdString()).scene.name));
    }

    // Opening a file checks it on a worker: the window's event loop keeps running.
    void openingChecksOnAWorker() {
        MainWindow w;
        QVERIFY(openShown(w, "planar_2r.json"));
        int ticks = 0;
        QTimer timer;
        timer.setInterval(0);
        connect(&timer, &QTimer::timeout, this, [&] { ++ticks; });
        timer.start();
        QVERIFY(w.openFile(example("puma560.json"), nullptr, true));
        timer.stop();
        QVERIFY2(ticks > 0, "the GUI thread did not process events while the file was checked");
        QCOMPARE(w.document().validScene().robot.dof(), 6);
    }

    // File ▸ Export ▸ Derivation through its dialog, as a user does it: the SVG filter
    // chosen and a name typed without an extension; the pages are written under that
    // name with the filter's extension.
    void exportDialogTakesTheFiltersExtension() {
        MainWindow w;
        QVERIFY(openShown(w, "planar_2r.json"));
        QAction* action = nullptr;
        for (QAction* a : w.findChildren<QAction*>())
            if (a->text().startsWith(MainWindow::tr("Derivation (PDF"))) action = a;
        QVERIFY(action);
        QVERIFY(QDir().mkpath(dir_.filePath("dialog")));
        const QString stem = dir_.filePath("dialog/slides");
        QString chosen, refused;
        int polls = 0;
        QTimer poll;
        poll.setInterval(50);
        connect(&poll, &QTimer::timeout, [&] {
            QWidget* modal = QApplication::activeModalWidget();
            if (auto* box = qobject_cast<QMessageBox*>(modal)) {  // a refusal: noted and closed, never waited on
                refused = box->text();
                box->reject();
                return;
            }
            auto* dialog = qobject_cast<QFileDialog*>(modal);
            if (!dialog || !chosen.isEmpty()) {
                if (++polls > 200) poll.stop();  // no dialog: the test fails below
                return;
            }
            for (const QString& filter : dialog->nameFilters())
                if (filter.startsWith("SVG")) chosen = filter;
            dialog->selectNameFilter(chosen);
            dialog->setDirectory(QFileInfo(stem).absolutePath());
            // Typed into the name box, as a user types it (selectFile lost the race with the
            // filter's own rename of the proposed name when the whole suite ran).
            auto* name = dialog->findChild<QLineEdit*>("fileNameEdit");
            if (name) name->setText(QFileInfo(stem).fileName());
            else dialog->selectFile(stem);
            static_cast<QDialog*>(dialog)->accept();  // QFileDialog::accept, through QDialog (protected in QFileDialog)
        });
        poll.start();
        QSignalSpy exported(&w.exports(), &ll::ui::ExportActions::finished);
        action->trigger();  // returns when the dialog is accepted
        QVERIFY2(chosen.startsWith("SVG") && chosen.contains("(*.svg)"), qPrintable(chosen));
        QVERIFY2(refused.isEmpty(), qPrintable(refused));
        QVERIFY(exported.wait(60000));
        QCOMPARE(exported.back().at(0).toString(), stem + ".svg");
        QCOMPARE(exported.back().at(1).toString(), QString());
        QVERIFY(QSvgRenderer(stem + ".svg").isValid());
        QVERIFY(QFileInfo::exists(stem + "-2.svg"));
        QVERIFY(!QFileInfo::exists(stem));
    }

    // Exports: the plot as PNG, SVG and CSV, the derivation as PDF (typeset, as `derive
    // --format pdf`) and LaTeX, the animation by the offscreen renderer.
    void exportsWriteValidFiles() {
        MainWindow w;
        QVERIFY(openShown(w, "planar_2r.json"));
        QString error;
        const QString png = dir_.filePath("energy.png"), svg = dir_.filePath("energy.svg"), csv = dir_.filePath("energy.csv");
        QVERIFY2(w.exports().plotTo(png, &error), qPrintable(error));
        QVERIFY2(w.exports().plotTo(svg, &error), qPrintable(error));
        QVERIFY2(w.exports().plotTo(csv, &error), qPrintable(error));
        const QImage plot(png);
        QVERIFY(!plot.isNull());
        QVERIFY(content(plot, plot.rect().adjusted(60, 20, -150, -40)).first > 0.005);
        const QByteArray svgText = readAll(svg);
        QVERIFY(svgText.contains("<svg") && (svgText.contains("<path") || svgText.contains("<polyline")));
        const QList<QByteArray> rows = readAll(csv).trimmed().split('\n');
        QCOMPARE(rows.front(), QByteArray("t [s],Ekin [J],Epot [J],E [J],W [J]"));
        QCOMPARE(static_cast<std::size_t>(rows.size() - 1), w.result()->simulation.trajectory.size());
        // E = Ekin + Epot in every row.
        for (const QByteArray& row : rows.mid(1)) {
            const QList<QByteArray> v = row.split(',');
            QVERIFY(std::abs(v[1].toDouble() + v[2].toDouble() - v[3].toDouble()) < 1e-9 * (1 + std::abs(v[3].toDouble())));
        }
        QVERIFY(!w.exports().plotTo(dir_.filePath("missing/energy.png"), &error));
        QVERIFY(!error.isEmpty());

        QSignalSpy exported(&w.exports(), &ll::ui::ExportActions::finished);
        const QString pdf = dir_.filePath("derivation.pdf"), tex = dir_.filePath("derivation.tex");
        const long derivations = ll::documentDerivations();
        QVERIFY2(w.exports().derivationTo(pdf, &error), qPrintable(error));
        QVERIFY(exported.wait(60000));
        QCOMPARE(exported.back().at(1).toString(), QString());
        QVERIFY(readAll(pdf).startsWith("%PDF-"));
        QVERIFY2(w.exports().derivationTo(tex, &error), qPrintable(error));
        QVERIFY(exported.wait(60000));
        const QByteArray latex = readAll(tex);
        QVERIFY(latex.startsWith("\\documentclass") && latex.contains("\\end{document}"));
        QCOMPARE(ll::documentDerivations(), derivations);  // the document on screen, not derived anew
        if (!QStandardPaths::findExecutable("pdftotext").isEmpty()) {
            QProcess text;
            text.start("pdftotext", {pdf, "-"});
            QVERIFY(text.waitForFinished(30000));
            const QString words = QString::fromUtf8(text.readAllStandardOutput());
            QVERIFY2(words.contains("Step 7") && words.contains("B(q)"), qPrintable(words.left(300)));
        }
        QVERIFY(!w.exports().derivationTo(dir_.filePath("derivation.doc"), &error));
        // Typeset pages as SVG and PNG, a file per page, as many as the PDF has; each
        // opens and shows ink.
        const int pdfPages = static_cast<int>(ll::ui::paginate(*w.derivation()->display).pages.size());
        for (const char* suffix : {"svg", "png"}) {
            const QString file = dir_.filePath(QString("slides/derivation.%1").arg(suffix));
            QVERIFY(QDir().mkpath(dir_.filePath("slides")));
            // Two pages of an earlier, longer SVG export are there already: named, kept.
            const bool older = QString(suffix) == "svg";
            if (older)
                for (int k : {pdfPages + 1, pdfPages + 2}) {
                    QFile stale(dir_.filePath(QString("slides/derivation-%1.svg").arg(k)));
                    QVERIFY(stale.open(QIODevice::WriteOnly) && stale.write("<svg/>") == 6);
                }
            QVERIFY2(w.exports().derivationTo(file, &error), qPrintable(error));
            QVERIFY(exported.wait(60000));
            QCOMPARE(exported.back().at(1).toString(), QString());
            const QStringList written = QDir(dir_.filePath("slides")).entryList({QString("*.%1").arg(suffix)});
            QCOMPARE(written.size(), pdfPages + (older ? 2 : 0));
            // The status bar names the first page and the last (and the older pages).
            const QString status = w.statusBar()->currentMessage();
            QVERIFY2(status.contains(file) && status.contains(QString("derivation-%1.%2").arg(pdfPages).arg(suffix)), qPrintable(status));
            QCOMPARE(
                status.contains(
                    QString(
                        "2 page files of an earlier, longer export remain beside it, not deleted: derivation-%1.svg … derivation-%2.svg")
                        .arg(pdfPages + 1)
                        .arg(pdfPages + 2)),
                older);
            if (older) QCOMPARE(readAll(dir_.filePath(QString("slides/derivation-%1.svg").arg(pdfPages + 2))), QByteArray("<svg/>"));
            QImage page;
            if (QString(suffix) == "png") {
                page = QImage(file);
            } else {
                QSvgRenderer svg(file);
                QVERIFY(svg.isValid());
                page = QImage(842, 595, QImage::Format_RGB32);
                page.fill(Qt::white);
                QPainter painter(&page);
                svg.render(&painter);
            }
            QVERIFY(!page.isNull());
            int dark = 0;
            for (int y = 0; y < page.height(); ++y)
                for (int x = 0; x < page.width(); ++x) dark += qGray(page.pixel(x, y)) < 128;
            QVERIFY2(dark > 500, qPrintable(QString("%1: %2 dark pixels").arg(suffix).arg(dark)));
        }

        // The animation: 0.5 s at 30 fps as a folder of frames, then as MP4.
        const QString frames = dir_.filePath("frames/");
        QVERIFY2(w.exports().animationTo(frames, &error, 0.5, false), qPrintable(error));
        QVERIFY(exported.wait(120000));
        QCOMPARE(exported.back().at(1).toString(), QString());
        const QStringList files = QDir(frames).entryList({"*.png"}, QDir::Files, QDir::Name);
        QVERIFY2(files.size() >= 15, qPrintable(files.join(' ')));
        const QImage first(frames + files.front()), last(frames + files.back());
        QCOMPARE(first.size(), QSize(1280, 720));
        QVERIFY(differing(first, last) > 0.001);  // the arm moved
        if (!QStandardPaths::findExecutable("ffprobe").isEmpty()) {
            const QString mp4 = dir_.filePath("animation.mp4");
            QVERIFY2(w.exports().animationTo(mp4, &error, 0.5, false), qPrintable(error));
            QVERIFY(exported.wait(120000));
            QCOMPARE(exported.back().at(1).toString(), QString());
            QProcess probe;
            probe.start("ffprobe", {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                                    "stream=nb_read_frames,width,height", "-of", "csv=p=0", mp4});
            QVERIFY(probe.waitForFinished(30000));
            const QStringList fields = QString::fromUtf8(probe.readAllStandardOutput()).trimmed().split(',');
            QCOMPARE(fields.size(), 3);
            QCOMPARE(fields[0], QString("1280"));
            QCOMPARE(fields[1], QString("720"));
            QCOMPARE(fields[2].toInt(), files.size());
        }
        // The slide (File → Export → Video for slides): 1920×1080 frames whose equation
        // panel holds the derivation step shown, inked, beside the moving plot.
        w.showDerivationStep(8);
        const QString slides = dir_.filePath("slide-frames/");
        QVERIFY2(w.exports().animationTo(slides, &error, 0.3, false, QSize(1920, 1080)), qPrintable(error));
        QVERIFY(exported.wait(120000));
        QCOMPARE(exported.back().at(1).toString(), QString());
        const QStringList slideFiles = QDir(slides).entryList({"*.png"}, QDir::Files, QDir::Name);
        QVERIFY(slideFiles.size() >= 8);
        const QImage slide(slides + slideFiles.front()), lastSlide(slides + slideFiles.back());
        QCOMPARE(slide.size(), QSize(1920, 1080));
        const ll::ui::CompositeLayout layout = ll::ui::CompositeLayout::forSize(slide.size());
        long ink = 0;
        for (int y = layout.equation.top(); y <= layout.equation.bottom(); ++y)
            for (int x = layout.equation.left(); x <= layout.equation.right(); ++x) ink += qGray(slide.pixel(x, y)) < 100;
        QVERIFY2(ink > 2000, qPrintable(QString::number(ink)));
        QVERIFY(differing(slide.copy(layout.plot), lastSlide.copy(layout.plot)) > 0.0005);

        // The lab report (File → Export → Lab report): every file of the bundle in the
        // folder, the scene as edited in the window.
        const QString report = dir_.filePath("lab-report");
        QVERIFY2(w.exports().labReportTo(report, &error, false), qPrintable(error));
        QVERIFY(exported.wait(300000));
        QCOMPARE(exported.back().at(1).toString(), QString());
        for (const char* f : {"derivation.pdf", "trajectory.csv", "energy.svg", "joints.svg", "slide.mp4", "index.md"})
            QVERIFY2(QFileInfo(report + "/" + f).size() > 0, f);
        QFile copied(report + "/" + QFileInfo(w.document().path()).fileName());
        QVERIFY(copied.open(QIODevice::ReadOnly));
        QCOMPARE(copied.readAll().toStdString(), w.document().text());
    }

    // Parameters are added and removed as undoable edits; removing one in use is an error
    // that keeps the last valid model.
    // Renaming a parameter rewrites every expression that uses it, whole names only, in
    // one undoable edit; prose and other names stay.
    void renamingAParameterRewritesItsUses() {
        QCOMPARE(ll::ui::renamedInExpression("a1/2+a10*a1^2-1e1", "a1", "L1"), std::string("L1/2+a10*L1^2-1e1"));
        QCOMPARE(ll::ui::renamedInExpression("1e1+e1", "e1", "k"), std::string("1e1+k"));
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.show();
        QVERIFY(w.openFile(example("planar_2r.json"), nullptr, true));
        QVERIFY(settled(w));
        const std::string description = w.document().value("/description").get<std::string>();
        QString error;
        QVERIFY(!w.editor().renameParameter("a1", "a2", &error));  // taken
        QVERIFY2(error.contains("a2"), qPrintable(error));
        QVERIFY(!w.editor().renameParameter("a1", "1x", &error));  // not a name
        QVERIFY2(w.editor().renameParameter("a1", "L1", &error), qPrintable(error));
        QVERIFY(checked(w));
        QVERIFY(!w.document().hasErrors());
        QCOMPARE(w.document().value("/robot/joints/0/a").get<std::string>(), std::string("L1"));
        QCOMPARE(w.document().value("/robot/joints/0/com/0").get<std::string>(), std::string("lc1-L1"));
        QCOMPARE(w.document().value("/parameters").begin().key(), std::string("L1"));  // in its place, first
        QCOMPARE(w.document().value("/parameters/L1").get<double>(), 1.0);
        QVERIFY(w.document().value("/parameters/a1").is_null());
        QCOMPARE(w.document().value("/description").get<std::string>(), description);  // prose untouched
        QCOMPARE(w.document().validScene().robot.joints[0].dh.a, 1.0);
        QVERIFY(settled(w));
        const QString step0 = w.derivationPanel().text().section("Step 1.", 0, 0);
        QVERIFY2(step0.contains("L1") && !step0.contains("a1"), qPrintable(step0));
        w.document().undoStack()->undo();
        QVERIFY(checked(w));
        QCOMPARE(w.document().value("/robot/joints/0/a").get<std::string>(), std::string("a1"));
        QVERIFY(w.document().value("/parameters/L1").is_null());
    }

    void parametersAddAndRemove() {
        MainWindow w;
        w.setAskBeforeClosing(false);
        QVERIFY(w.openFile(example("planar_2r.json"), nullptr, true));
        const auto value = [&](const std::string& name) {
            for (const auto& [n, v] : w.document().validScene().parameters)
                if (n == name) return v;
            return std::nan("");
        };
        QString error;
        QVERIFY2(w.editor().addParameter("m3", "0.75", &error), qPrintable(error));
        QVERIFY(checked(w));
        QCOMPARE(value("m3"), 0.75);
        QVERIFY(!w.editor().addParameter("m3", "1", &error));
        QVERIFY(error.contains("m3"));
        QVERIFY(!w.editor().addParameter("3m", "1", &error));
        // Using it: the mass of link 2 becomes m3.
        w.editor().joints().setData(w.editor().joints().index(1, JointTableModel::Mass), "m3", Qt::EditRole);
        QVERIFY(checked(w));
        QCOMPARE(w.document().validScene().robot.joints[1].link.mass, 0.75);
        // Removing a parameter in use: the loader names it, the valid model stays.
        w.editor().removeParameter("m3");
        QVERIFY(checked(w));
        QVERIFY(w.document().hasErrors());
        QVERIFY2(w.editor().diagnosticLines().join('\n').contains("m3"), qPrintable(w.editor().diagnosticLines().join('\n')));
        QCOMPARE(w.document().validScene().robot.joints[1].link.mass, 0.75);
        w.document().undoStack()->undo();
        QVERIFY(checked(w));
        QVERIFY(!w.document().hasErrors());
        QCOMPARE(value("m3"), 0.75);
        // Unused: removed cleanly; undo brings it back.
        w.editor().removeParameter("m2");
        QVERIFY(checked(w));
        QVERIFY(!w.document().hasErrors());
        QVERIFY(std::isnan(value("m2")));
        w.document().undoStack()->undo();
        QVERIFY(checked(w));
        QCOMPARE(value("m2"), 1.5);
        QCOMPARE(w.document().undoStack()->count(), 3);  // add, use, remove m2 (the undone removal of m3 was dropped)
    }

    // A student's session, driven by keyboard and mouse events only: open the 2R from the
    // example gallery, type a new a1 in the DH table, undo and redo with the keys, play,
    // scrub in the energy plot, pose the arm with a teach slider, export the plot. Each
    // stage is saved as a screenshot (LL_TEST_KEEP=1 keeps them to look at).
    void aStudentsSession() {
        MainWindow w;
        w.setAskBeforeClosing(false);
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();  // shortcuts (Ctrl+Z) go to the active window only
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(w.openFile(":/examples/planar_2r.json", nullptr, true));
        QVERIFY(settled(w, 120));
        const auto shot = [&](const char* name) {
            QVERIFY(ll::test::nextFrameDrawn(w));  // the window repainted before the screen is grabbed
            w.screenshot().save(dir_.filePath(QString("student-%1.png").arg(name)));
        };
        shot("1-opened");
        // The DH table: select joint 1's a, type 1.2, Enter.
        QTableView* dh = nullptr;
        for (QTableView* t : w.findChildren<QTableView*>())
            if (t->model() == &w.editor().joints() && !t->isColumnHidden(JointTableModel::A) && t->isVisible()) dh = t;
        QVERIFY(dh);
        dh->setFocus();
        dh->setCurrentIndex(w.editor().joints().index(0, JointTableModel::A));
        QTest::keyClick(dh, '1');  // any key opens the cell's editor with that key typed
        auto* editor = dh->viewport()->findChild<QLineEdit*>();
        QVERIFY(editor && editor->isVisible());
        QTest::keyClicks(editor, ".2");
        QCOMPARE(editor->text(), QString("1.2"));
        QTest::keyClick(editor, Qt::Key_Return);  // the delegate commits by a queued call
        QTRY_COMPARE_WITH_TIMEOUT(w.document().validScene().robot.joints[0].dh.a, 1.2, 30000);
        QVERIFY(settled(w));
        QVERIFY(w.derivationPanel().text().section("Step 1.", 0, 0).contains("1.2"));
        QVERIFY(w.windowTitle().contains('*'));
        shot("2-edited");
        // Ctrl+Z, Ctrl+Shift+Z.
        dh->setFocus();
        QTest::keyClick(dh, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(checked(w));
        QCOMPARE(w.document().validScene().robot.joints[0].dh.a, 1.0);
        QVERIFY(!w.windowTitle().contains('*'));
        QTest::keyClick(dh, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(checked(w));
        QCOMPARE(w.document().validScene().robot.joints[0].dh.a, 1.2);
        QVERIFY(settled(w));
        // Play from the toolbar for a second of wall time.
        QAction* play = nullptr;
        for (QAction* a : w.findChildren<QAction*>())
            if (a->text().contains("Play") && !a->text().contains("pause")) play = a;
        QVERIFY(play);
        w.playback().restart();
        w.playback().pause();
        play->trigger();
        QVERIFY(w.playback().isPlaying());
        QVERIFY2(ll::test::waitUntil([&] { return w.playback().time() > 0.2; }, 20000), qPrintable(QString::number(w.playback().time())));
        shot("3-playing");
        // Scrub: a click in the energy plot at 60 % of its width pauses there.
        auto& chart = w.energyChart();
        const QRectF area = chart.chart()->plotArea();
        const QPoint at = chart.mapFromScene(QPointF(area.left() + 0.6 * area.width(), area.center().y()));
        QTest::mouseClick(chart.viewport(), Qt::LeftButton, {}, at);
        QVERIFY(!w.playback().isPlaying());
        const double end = w.result()->simulation.trajectory.t.back();
        QVERIFY2(std::abs(w.playback().time() - 0.6 * end) < 0.02 * end, qPrintable(QString::number(w.playback().time())));
        shot("4-scrubbed");
        // Teach: the tab, then joint 2's slider moved by the keyboard.
        w.teach(w.teachPanel().pose());
        auto sliders = w.teachPanel().findChildren<QSlider*>();
        QCOMPARE(sliders.size(), 2);
        const QString readout = w.teachPanel().readout();
        sliders[1]->setFocus();
        for (int k = 0; k < 10; ++k) QTest::keyClick(sliders[1], Qt::Key_PageUp);
        QVERIFY(w.teachPanel().pose()[1] != 0);
        QVERIFY(w.teachPanel().readout() != readout);
        shot("5-teach");
        QString error;
        QVERIFY2(w.exports().plotTo(dir_.filePath("student-energy.png"), &error), qPrintable(error));
        QVERIFY(!QImage(dir_.filePath("student-energy.png")).isNull());
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
        // --size is checked like render's: no window of any size asked for.
        for (const char* size : {"99999x10", "0x600", "-5x-5", "800x600junk"}) {
            p.start(LL_CLI, {example("planar_2r.json"), "--screenshot", png, "--size", size});
            QVERIFY(p.waitForFinished(60000));
            QCOMPARE(p.exitCode(), 2);
            const QByteArray err = p.readAllStandardError();
            QVERIFY2(err.startsWith(QByteArray("error: --size ") + size + ":") && err.count('\n') == 1, err.constData());
        }
        // --dh-step I,K and --present picture the step-through and presentation mode.
        const QString dh = dir_.filePath("dh.png"), present = dir_.filePath("present.png");
        p.start(LL_CLI, {example("puma560.json"), "--screenshot", dh, "--dh-step", "2,3"});
        QVERIFY(p.waitForFinished(120000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QCOMPARE(QImage(dh).size(), QSize(1280, 800));
        p.start(LL_CLI, {example("planar_2r.json"), "--screenshot", present, "--present", "--size", "1024x576"});
        QVERIFY(p.waitForFinished(120000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QCOMPARE(QImage(present).size(), QSize(1024, 576));
        for (const char* bad : {"3,1", "0,1", "1,5", "1", "1,2,3", "a,b"}) {
            p.start(LL_CLI, {example("planar_2r.json"), "--screenshot", png, "--dh-step", bad});
            QVERIFY(p.waitForFinished(60000));
            QCOMPARE(p.exitCode(), 2);
            const QByteArray err = p.readAllStandardError();
            QVERIFY2(err.startsWith(QByteArray("error: --dh-step: '") + bad + "'"), err.constData());
        }
        p.start(LL_CLI, {example("mass_spring_pair_lagrangian.json"), "--screenshot", png, "--dh-step", "1,1"});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 2);
    }

    // The DH step-through in the window: the moving frame the 3D view draws is frame i−1
    // carried by the motions done (frame i−1 with none, T_i^0 of forward kinematics after
    // all four, ≤ 1e-12), the DH table's current cell is the parameter to come, Next runs
    // through every row's motions, and leaving the tab takes the frame away.
    void dhStepThroughDrawsTheMovingFrame() {
        MainWindow w;
        QVERIFY(openShown(w, "puma560.json"));
        w.playback().pause();
        w.playback().setTime(0.7);
        QVERIFY(w.showPlotTab("dh-steps"));
        ll::ui::SceneView& view = w.sceneView();
        ll::ui::DhStepPanel& panel = w.dhStepPanel();
        const ll::Scene& scene = w.document().validScene();
        ll::RobotData data(scene.robot);
        ll::forwardKinematics(scene.robot, data, view.shownPose());
        auto* table = w.findChild<QTableView*>("dh-table");
        const int columns[] = {ll::ui::JointTableModel::Theta, ll::ui::JointTableModel::D, ll::ui::JointTableModel::A,
                               ll::ui::JointTableModel::Alpha};  // standard: rot_z θ, trans_z d, trans_x a, rot_x α
        for (int joint = 0; joint < scene.dof(); ++joint) {
            for (int done = 0; done <= 4; ++done) {
                panel.setStep(joint, done);
                Eigen::Isometry3d frame;
                QVERIFY(view.dhStepFrame(frame));
                if (done == 0) QVERIFY((frame.matrix() - data.T_0i[joint].matrix()).cwiseAbs().maxCoeff() <= 1e-12);
                if (done == 4) QVERIFY((frame.matrix() - data.T_0i[joint + 1].matrix()).cwiseAbs().maxCoeff() <= 1e-12);
                QCOMPARE(table->currentIndex().row(), joint);
                if (done < 4) QCOMPARE(table->currentIndex().column(), columns[done]);
            }
        }
        // Animate carries the next motion out over a second: the frame passes through the
        // motion's middle (rot_z by part of θ2: not yet at its end), then the motion is done.
        panel.setStep(1, 0);
        panel.animate();
        QTRY_VERIFY_WITH_TIMEOUT(panel.fraction() > 0.2 && panel.fraction() < 0.8, 3000);
        QVERIFY(panel.done() == 0);
        {
            Eigen::Isometry3d midway;
            QVERIFY(view.dhStepFrame(midway));
            const Eigen::Isometry3d before = data.T_0i[1];
            const Eigen::Isometry3d after = ll::steppedFrame(scene.robot, data, view.shownPose(), 1, 1);
            QVERIFY((midway.matrix() - before.matrix()).norm() > 1e-6 && (midway.matrix() - after.matrix()).norm() > 1e-6);
        }
        QTRY_COMPARE_WITH_TIMEOUT(panel.done(), 1, 3000);
        QCOMPARE(panel.fraction(), 0.0);
        panel.setStep(0, 0);
        int presses = 0;
        while (!(panel.joint() == scene.dof() - 1 && panel.done() == 4) && presses < 100) panel.next(), ++presses;
        QCOMPARE(presses, 4 * scene.dof());
        QVERIFY(panel.productText().contains("A<sub>6</sub>"));
        // The static view: every parameter drawn, only while the tab is shown.
        panel.setShowDimensions(true);
        QVERIFY(view.showDimensions());
        QVERIFY(w.showPlotTab("energy"));
        QVERIFY(!view.showDimensions());
        Eigen::Isometry3d frame;
        QVERIFY(!view.dhStepFrame(frame));
        QVERIFY(w.showPlotTab("dh-steps"));
        QVERIFY(view.showDimensions());
    }
};

LL_TEST_MAIN(TestMainWindow)

}  // namespace test_main_window
#include "test_main_window.moc"
