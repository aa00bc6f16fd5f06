// Step 0 in the window: "Find the DH parameters" places the PUMA 560's frames from its
// joint axes rule by rule (the robot held at home, its own frames hidden, the marks of the
// step drawn, the sentence naming the case, the table filling row by row, in Danish too);
// `--dh-from-axes I,K` pictures a step and refuses a bad one; a URDF robot is drawn by its
// meshes (STL by package://, OBJ by a relative path) with a toggle back to the DH drawing,
// and a mesh that cannot be read leaves the DH drawing with a warning.
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>

#include "test_registry.hpp"
#include "ui/document/app_language.hpp"
#include "ui/window/dh_axes_panel.hpp"
#include "ui/window/dh_step_page.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/scene_files.hpp"
#include "window_checks.hpp"
#include "window_waits.hpp"

namespace test_step_zero_window {

using namespace ll;
using ll::ui::MainWindow;

namespace {

QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }
QString meshbot() { return QString(LL_SOURCE_DIR) + "/tests/urdf/meshbot/urdf/meshbot.urdf"; }

// Pixels of the test robot's magenta upper arm (its STL's colour, lit or shaded).
int magentaPixels(const QImage& image) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (c.red() > 90 && c.green() * 2 < c.red() && c.blue() * 3 > c.red() * 2) ++count;
        }
    return count;
}

std::unique_ptr<MainWindow> importedWindow(const QString& urdf) {
    auto w = std::make_unique<MainWindow>();
    w->setAskBeforeClosing(false);
    w->resize(1280, 800);
    w->show();
    QStringList errors;
    if (!QTest::qWaitForWindowExposed(w.get()) || !w->files().importUrdf(urdf, &errors, true) || !test::settled(*w, 120))
        qFatal("%s was not imported: %s", qPrintable(urdf), qPrintable(errors.join("; ")));
    return w;
}

}  // namespace

class TestStepZeroWindow : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() { test::keepWindowStateIn(dir_); }

    // The rules on the PUMA 560: the robot stands at home while the page is shown (the
    // playback paused and its time kept), none of its own frames drawn, the marks of the
    // step over it; every step's sentence is there and the frames between skew axes say
    // so; the table's rows appear as their frames are placed and end as the scene's own.
    void findingTheParametersRuleByRule() {
        auto w = test::openedWindow(example("puma560.json"), [](MainWindow& m) { return test::settled(m, 120); });
        w->playback().setTime(1.3);
        w->playback().play();
        QVERIFY(w->showPlotTab("dh-steps"));
        ui::DhStepPage& page = w->dhStepPage();
        ui::DhAxesPanel& panel = *page.axes();
        page.setCurrentWidget(&panel);
        test::flushEvents();
        QVERIFY(!w->playback().isPlaying());
        QVERIFY(w->sceneView().shownPose().isZero(0.0));
        QCOMPARE(panel.steps(), 4 * 7 + 1);
        panel.setStep(0);
        QCOMPARE(int(w->sceneView().construction().size()), 6);  // the six joint lines, nothing else yet
        QVERIFY(panel.sentenceText().contains("joint axes"));
        int skewSentences = 0;
        for (int k = 1; k < panel.steps(); ++k) {
            panel.next();
            QCOMPARE(panel.step(), k);
            QVERIFY(!panel.sentenceText().isEmpty());
            if (panel.sentenceText().contains("skew")) ++skewSentences;
            // Row r is in the table from x_r on (a cell of row r+1 still waits).
            const int rows = k >= 7 ? std::min(6, (k - 3) / 4) : 0;
            QCOMPARE(panel.tableText().count("…"), 4 * (6 - rows));
            QVERIFY(!w->sceneView().construction().empty());
        }
        QVERIFY(skewSentences >= 1);  // the PUMA's z₁, z₂ (joints 2 and 3 are parallel; 3 and 4 skew)
        QVERIFY(panel.sentenceText().contains("is the one the rules give"));
        QVERIFY(w->sceneView().shownPose().isZero(0.0));
        w->playback().setTime(2.0);  // scrubbing (or a new run) keeps the robot at home here
        test::flushEvents();
        QVERIFY(w->sceneView().shownPose().isZero(0.0));
        // Back to row by row: the marks go, the playback's pose comes back.
        page.setCurrentWidget(page.rows());
        test::flushEvents();
        QVERIFY(w->sceneView().construction().empty());
        QVERIFY(!w->sceneView().shownPose().isZero(0.0));
    }

    // The same page in Danish: the sentences and buttons are translated.
    void theRulesInDanish() {
        auto w = test::openedWindow(example("planar_2r.json"), [](MainWindow& m) { return test::settled(m, 120); });
        QVERIFY(ui::installLanguage(present::Language::Danish));
        test::flushEvents();
        QVERIFY(w->showPlotTab("dh-steps"));
        w->dhStepPage().setCurrentWidget(w->dhStepPage().axes());
        ui::DhAxesPanel& panel = *w->dhStepPage().axes();
        panel.setStep(0);
        QVERIFY2(panel.sentenceText().contains("Leddenes akser"), qPrintable(panel.sentenceText()));
        panel.setStep(DhConstruction::index(1, 2));  // o₁ of the 2R: parallel axes
        QVERIFY2(panel.sentenceText().contains("parallelle"), qPrintable(panel.sentenceText()));
        QCOMPARE(w->dhStepPage().tabText(0), QString("Find DH-parametrene"));
        QVERIFY(ui::installLanguage(present::Language::English));
    }

    // --dh-from-axes I,K: the window at frame I after K rules; one line and exit 2 for a
    // step the robot has not, or a typed Lagrangian.
    void dhFromAxesOnTheCommandLine() {
        const QString png = dir_.filePath("axes.png");
        QProcess p;
        p.start(LL_CLI, {example("stanford_arm.json"), "--screenshot", png, "--dh-from-axes", "3,2"});
        QVERIFY(p.waitForFinished(120000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QCOMPARE(QImage(png).size(), QSize(1280, 800));
        for (const char* bad : {"7,0", "-1,0", "2,5", "2", "a,b"}) {
            p.start(LL_CLI, {example("stanford_arm.json"), "--screenshot", png, "--dh-from-axes", bad});
            QVERIFY(p.waitForFinished(60000));
            QCOMPARE(p.exitCode(), 2);
            const QByteArray err = p.readAllStandardError();
            QVERIFY2(err.startsWith(QByteArray("error: --dh-from-axes: '") + bad + "'") && err.count('\n') == 1, err.constData());
        }
        p.start(LL_CLI, {example("mass_spring_pair_lagrangian.json"), "--screenshot", png, "--dh-from-axes", "0,0"});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 2);
    }

    // The imported meshbot drawn by its meshes: the magenta STL upper arm on screen; the
    // toggle gives the DH drawing back (no magenta), and on again. Its URDF link frames
    // are drawn over the frames the rules find.
    void anImportedRobotIsDrawnByItsMeshes() {
        auto w = importedWindow(meshbot());
        ui::SceneView& view = w->sceneView();
        QVERIFY(view.showsLook());
        QVERIFY(test::nextFrameDrawn(*w));
        const int withMeshes = magentaPixels(view.grabView());
        QVERIFY2(withMeshes > 500, qPrintable(QString::number(withMeshes)));
        view.setShowLook(false);
        QVERIFY(!view.showsLook());
        QVERIFY(test::nextFrameDrawn(*w));
        QCOMPARE(magentaPixels(view.grabView()), 0);
        view.setShowLook(true);
        QVERIFY(view.showsLook());
        QVERIFY(w->showPlotTab("dh-steps"));
        w->dhStepPage().setCurrentWidget(w->dhStepPage().axes());
        int overlay = 0;
        for (const ConstructionMark& m : view.construction())
            if (m.kind == ConstructionMarkKind::OverlayFrame && !m.label.empty()) ++overlay;
        QCOMPARE(overlay, 4);  // base, upper_arm, forearm, tool
    }

    // The upper arm's STL missing: the window says which mesh it could not read and draws
    // the robot as its DH table.
    void aMeshNotReadLeavesTheDhDrawing() {
        QTemporaryDir copy;
        QVERIFY(QDir().mkpath(copy.filePath("meshbot/urdf")) && QDir().mkpath(copy.filePath("meshbot/meshes")));
        QVERIFY(QFile::copy(meshbot(), copy.filePath("meshbot/urdf/meshbot.urdf")));
        QVERIFY(
            QFile::copy(QString(LL_SOURCE_DIR) + "/tests/urdf/meshbot/meshes/forearm.obj", copy.filePath("meshbot/meshes/forearm.obj")));
        auto w = importedWindow(copy.filePath("meshbot/urdf/meshbot.urdf"));
        QVERIFY(!w->sceneView().showsLook());
        const QString status = w->statusBar()->currentMessage();
        QVERIFY2(status.contains("upper_arm.stl") && status.contains("no such file"), qPrintable(status));
        QVERIFY(test::nextFrameDrawn(*w));
        QCOMPARE(magentaPixels(w->sceneView().grabView()), 0);
    }
};

LL_TEST_MAIN(TestStepZeroWindow)

}  // namespace test_step_zero_window
#include "test_step_zero_window.moc"
