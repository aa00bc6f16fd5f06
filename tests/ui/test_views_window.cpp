// Views and lessons in the window (issue 48). A view saved from a window in some state and
// opened in the same window after everything was changed (another scene, language, tab,
// camera, toggles) gives the same screen pixel for pixel (the status line, which shows the
// run's wall-clock time, is left out) and the same view again, field by field: a picked
// entry with the Torques tab in Danish with Spong's notation and a moved camera, the teach
// pose with its results, the DH step-through row by row and from the axes, the Tracking
// tab, presentation mode. A view that no longer fits its scene (an entry gone, a step it
// has not, a scene that is not there) opens as far as it can and says what it could not.
// A lesson of 10 views over 5 scenes walked with the clicker's keys in presentation mode
// shows on each view exactly the still `lagrangelab lesson` exported for it, steps through
// a view's derivation steps, shows the speaker's note, and leaving returns to where the
// lecturer was; the same lesson exports as a PDF of 10 pages and as the one view's video
// that plays, of as many frames as its play range holds.
#include <QDir>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QProcess>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include "core/io/lesson_file.hpp"
#include "core/io/window_view.hpp"
#include "pdf_streams.hpp"
#include "test_registry.hpp"
#include "ui/window/derivation_panel.hpp"
#include "ui/window/derivation_view.hpp"
#include "ui/window/dh_step_page.hpp"
#include "ui/window/dh_step_panel.hpp"
#include "ui/window/entry_linking.hpp"
#include "ui/window/language_menu.hpp"
#include "ui/window/lesson_mode.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/presentation_mode.hpp"
#include "ui/window/scene_view.hpp"
#include "ui/window/torque_pane.hpp"
#include "ui/window/view_state.hpp"
#include "window_checks.hpp"
#include "window_waits.hpp"

namespace test_views_window {

using namespace ll;
using ll::ui::MainWindow;

namespace {

QString example(const char* name) { return QString(LL_EXAMPLES_DIR) + "/" + name; }

// The window once every result and layout pass is in and its last change drawn.
QImage shown(MainWindow& w) {
    test::idle(w);
    test::waitUntil([&] { return !w.views().restoring(); }, 120000);
    test::idle(w);
    test::nextFrameDrawn(w);
    // The plots repaint what they changed a little later: grabbed until it stops changing.
    QImage last = w.screenshot();
    for (int k = 0; k < 40; ++k) {
        QTest::qWait(50);
        QImage now = w.screenshot();
        if (now == last) break;
        last = std::move(now);
    }
    return last;
}

// The pixels that differ between two screenshots of the window above its status line
// (which shows the run's wall-clock time); −1 when the sizes differ.
long differingPixels(const QImage& a, const QImage& b, int rows) {
    if (a.size() != b.size()) return -1;
    const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
    long differ = 0;
    for (int r = 0; r < std::min(rows, x.height()); ++r)
        for (int c = 0; c < x.width(); ++c) differ += x.pixel(c, r) != y.pixel(c, r);
    return differ;
}

// Where a failing comparison leaves its pictures to be looked at.
QString kept(const QString& name) {
    const QString folder = QDir::temp().filePath("test_views_window-failed");
    QDir().mkpath(folder);
    return folder + "/" + name;
}

int rowsAboveStatus(MainWindow& w) { return w.statusBar()->isVisible() ? w.statusBar()->geometry().top() : w.height(); }

// The view's JSON with the camera's numbers rounded to 1e-9 m (a restored camera is the
// same camera, its eye computed back from angles).
scene_json::Json comparable(WindowView v) {
    if (v.camera) {
        for (Eigen::Vector3d* p : {&v.camera->eye, &v.camera->target, &v.camera->up})
            *p = (*p * 1e9).array().round().matrix() / 1e9;
        v.camera->fov = std::round(v.camera->fov * 1e9) / 1e9;
    }
    return windowViewJson(v);
}

}  // namespace

class TestViewsWindow : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // `setUp` puts the window in a state; that state saved as a view, everything changed,
    // and the view opened again must show the same screen and give the same view back.
    void roundTrip(const QString& scene, const std::function<void(MainWindow&)>& setUp, const QString& file) {
        auto w = test::openedWindow(scene, [](MainWindow& m) { return test::settled(m, 120); });
        w->language().set({present::Language::English, present::Notation::Notes});  // not the last test's
        setUp(*w);
        const QImage before = shown(*w);
        const WindowView saved = w->views().capture();
        const QString path = dir_.filePath(file);
        saveWindowView(saved, path.toStdString());

        // Everything else: another scene, English with the notes' letters, the Energy tab,
        // the camera refitted, the toggles flipped, out of presentation mode.
        w->presentationMode().setOn(false);
        QVERIFY(w->openFile(example("double_pendulum.json"), nullptr, true));
        QVERIFY(test::settled(*w, 120));
        w->language().set({present::Language::English, present::Notation::Notes});
        w->showPlotTab("joints");
        w->sceneView().setStandardView("top");
        w->sceneView().setShowFrames(!w->sceneView().showFrames());
        w->playback().setSpeed(5);
        shown(*w);

        QStringList problems{"not restored"};
        connect(&w->views(), &ui::ViewState::restored, w.get(), [&](const QStringList& p) { problems = p; });
        w->views().restore(loadWindowView(path.toStdString()));
        const QImage after = shown(*w);
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join('\n')));
        const long differ = differingPixels(before, after, rowsAboveStatus(*w));
        if (differ != 0) {
            before.save(kept(file + ".before.png"));
            after.save(kept(file + ".after.png"));
        }
        QVERIFY2(differ == 0, qPrintable(QString("%1: %2 pixels differ (%3)").arg(file).arg(differ).arg(kept(file))));
        WindowView again = w->views().capture();
        w->presentationMode().setOn(false);  // the application's font back for the next test's window
        QCOMPARE(QString::fromStdString(comparable(again).dump()), QString::fromStdString(comparable(saved).dump()));
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        test::keepWindowStateIn(dir_);
    }

    void aPickedEntryInDanishWithAMovedCamera() {
        roundTrip(
            example("planar_2r.json"),
            [](MainWindow& w) {
                w.language().set({present::Language::Danish, present::Notation::Spong});
                QVERIFY(test::settled(w, 120));
                w.showDerivationStep(7);
                QVERIFY(w.linking().selectEntry("b11"));
                w.playback().setTime(1.3);
                w.playback().setSpeed(2);
                w.playback().setLoop(false);
                w.showPlotTab("torques");
                w.torquePane().setJoint(1);
                w.sceneView().setStandardView("side");
                w.sceneView().zoomBy(0.7);
                w.sceneView().setShowLabels(false);
                w.sceneView().setShowTrail(false);
                w.derivationView().setZoom(1.25);
            },
            "danish_b11.json");
    }

    void theTeachPoseWithItsResults() {
        roundTrip(
            example("planar_2r.json"),
            [](MainWindow& w) {
                w.teach((Eigen::VectorXd(2) << 0.4, -0.9).finished());
                w.showDerivationStep(10);
            },
            "teach.json");
    }

    void theDhStepThroughRowByRow() {
        roundTrip(
            example("puma560.json"),
            [](MainWindow& w) {
                w.showPlotTab("dh-steps");
                w.dhStepPage().setCurrentWidget(w.dhStepPage().rows());
                w.dhStepPanel().setStep(2, 3);
                w.dhStepPanel().setShowDimensions(true);
                w.showDerivationStep(1);
            },
            "dh_rows.json");
    }

    void theTrackingTabInPresentationMode() {
        roundTrip(
            example("control/planar_2r_pd_gravity.json"),
            [](MainWindow& w) {
                w.presentationMode().setSize(w.size());
                w.presentationMode().setOn(true);
                shown(w);
                QVERIFY(test::waitUntil([&] { return w.analysis() != nullptr; }, 120000));
                w.showPlotTab("tracking");
                w.showDerivationStep(9);
                w.playback().setTime(0.7);
                w.linking().pickLink(1);
            },
            "tracking_presented.json");
    }

    // A view of an entry an edit removed, of a step its scene has not, of a scene gone:
    // shown as far as it can be, each thing it could not restore said.
    void aViewThatNoLongerFits() {
        auto w = test::openedWindow(example("planar_2r.json"), [](MainWindow& m) { return test::settled(m, 120); });
        WindowView view;
        view.scenePath = example("planar_2r.json").toStdString();
        view.pick.entry = "b33";  // a 3-link robot's, saved before a link was removed
        view.derivation.step = 9;  // the control law: this scene has no controller
        view.playback.time = 2.5;
        QStringList problems;
        connect(&w->views(), &ui::ViewState::restored, w.get(), [&](const QStringList& p) { problems = p; });
        w->views().restore(view);
        shown(*w);
        QCOMPARE(problems.size(), 2);
        QVERIFY2(problems[0].contains("b33"), qPrintable(problems[0]));
        QVERIFY2(problems[1].contains("9") && problems[1].contains("0 to 8"), qPrintable(problems[1]));
        QCOMPARE(w->playback().time(), 2.5);  // the rest is restored
        QVERIFY(w->selection().entry() == nullptr);

        view.scenePath = dir_.filePath("gone.json").toStdString();
        view.pick.entry = "b22";
        view.derivation.step = 7;
        w->views().restore(view);
        shown(*w);
        QVERIFY2(problems.size() >= 2 && problems[0].contains("gone.json") && !problems.join('\n').contains("b22"),
                 qPrintable(problems.join('\n')));  // the scene, and why
        QVERIFY(w->selection().entry() && w->selection().entry()->id == "b22");  // on the scene open now
    }

    // The example lesson exported as stills, then walked by the clicker's keys: each view
    // equal to its still.
    void aLessonWalkedByKeysIsItsStills() {
        const QString lesson = example("lessons/euler_lagrange_intro.lesson");
        const QString stills = dir_.filePath("stills");
        QProcess p;
        p.start(LL_CLI, {"lesson", lesson, "--out", stills, "--format", "png", "--size", "1280x720"});
        QVERIFY(p.waitForFinished(600000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        const QStringList files = QDir(stills).entryList({"*.png"}, QDir::Files, QDir::Name);
        QCOMPARE(files.size(), 10);

        // The lecturer's window at the projector's 1280×720, as the export's.
        auto w = std::make_unique<MainWindow>();
        w->setAskBeforeClosing(false);
        w->resize(1280, 720);
        w->presentationMode().setSize(QSize(1280, 720));
        w->show();
        QVERIFY(w->openFile(example("simple_pendulum.json"), nullptr, true) && test::settled(*w, 120));
        w->showDerivationStep(3);
        const WindowView before = w->views().capture();
        QVERIFY(w->lessons().open(lesson));
        int shownIndex = -1;
        connect(&w->lessons(), &ui::LessonMode::viewShown, w.get(), [&](int i, const QStringList&) { shownIndex = i; });
        w->lessons().present(0);
        w->activateWindow();  // the keys' shortcuts go to the active window
        QVERIFY(QTest::qWaitForWindowActive(w.get()));
        const Lesson read = loadLesson(lesson.toStdString());
        for (int i = 0; i < 10; ++i) {
            QVERIFY2(test::waitUntil([&] { return shownIndex == i; }, 120000), qPrintable(QString("view %1").arg(i + 1)));
            const QImage screen = shown(*w);
            const QImage still(QDir(stills).filePath(files[i]));
            const long differ = differingPixels(screen, still, screen.height());
            if (differ != 0) {
                screen.save(kept(QString("walked-%1.png").arg(i + 1)));
                still.save(kept(QString("exported-%1.png").arg(i + 1)));
            }
            QVERIFY2(differ == 0, qPrintable(QString("view %1: %2 pixels differ from %3").arg(i + 1).arg(differ).arg(files[i])));
            const WindowView& view = read.views[std::size_t(i)].view;
            // The speaker's window: N shows it with this view's note and the next title.
            if (i == 2) {
                QTest::keyClick(w.get(), Qt::Key_N);
                QVERIFY(w->lessons().speakerNotes() && w->lessons().speakerNotes()->isVisible());
                const QList<QLabel*> labels = w->lessons().speakerNotes()->findChildren<QLabel*>();
                QString all;
                for (QLabel* l : labels) all += l->text() + "\n";
                QVERIFY2(all.contains(QString::fromStdString(view.note)) && all.contains("Next: The torques"), qPrintable(all));
                QTest::keyClick(w.get(), Qt::Key_N);
                QVERIFY(!w->lessons().speakerNotes()->isVisible());
            }
            // A view stepped through: → goes through its steps before the next view.
            if (view.derivation.through) {
                for (int s = (*view.derivation.through)[0] + 1; s <= (*view.derivation.through)[1]; ++s) {
                    QTest::keyClick(w.get(), Qt::Key_Right);
                    QCOMPARE(w->derivationPanel().step(), s);
                    QCOMPARE(w->lessons().current(), i);
                }
            }
            if (i < 9) QTest::keyClick(w.get(), i % 2 ? Qt::Key_PageDown : Qt::Key_Right);
        }
        // Page Up goes back a view; Escape leaves, back where the lecturer was.
        QTest::keyClick(w.get(), Qt::Key_PageUp);
        QVERIFY(test::waitUntil([&] { return shownIndex == 8; }, 120000));
        QTest::keyClick(w.get(), Qt::Key_Escape);
        shown(*w);
        QVERIFY(!w->presentationMode().on());
        QCOMPARE(QFileInfo(w->document().path()).fileName(), QString("simple_pendulum.json"));
        QCOMPARE(w->derivationView().step(), *before.derivation.step);
    }

    // Making a lesson in the window: add, rename, move, remove, a note typed; each one undo
    // step in the lesson's own stack (the scene's stays as it was), and redo brings it back.
    void aLessonMadeAndUndone() {
        auto w = test::openedWindow(example("planar_2r.json"), [](MainWindow& m) { return test::settled(m, 120); });
        const auto titles = [&] {
            QStringList out;
            for (const LessonView& lv : w->lessons().lesson().views) out << QString::fromStdString(lv.view.name);
            return out.join(", ");
        };
        w->lessons().newLesson();
        w->showDerivationStep(7);
        w->lessons().addCurrentView();
        QVERIFY(w->linking().selectEntry("b12"));
        w->lessons().addCurrentView();
        QCOMPARE(titles(), QString("View 1, View 2"));
        QCOMPARE(w->lessons().lesson().views[1].view.pick.entry.value_or(""), std::string("b12"));
        w->lessons().renameView(1, "b12 picked");
        QVERIFY(test::waitUntil([&] { return titles() == "View 1, b12 picked"; }, 5000));
        w->lessons().moveView(1, 0);
        QCOMPARE(titles(), QString("b12 picked, View 1"));
        auto* note = w->findChild<QPlainTextEdit*>("lesson-note");
        QVERIFY(note);
        auto* list = w->findChild<QListWidget*>("lesson-views");
        list->setCurrentRow(0);
        QTest::keyClicks(note, "Ask first");
        QCOMPARE(w->lessons().lesson().views[0].view.note, std::string("Ask first"));
        w->lessons().removeView(1);
        QCOMPARE(titles(), QString("b12 picked"));
        QUndoStack& undo = *w->lessons().undoStack();
        QCOMPARE(undo.count(), 6);  // two adds, rename, move, the note (its keys one step), remove
        undo.undo();
        QCOMPARE(titles(), QString("b12 picked, View 1"));
        undo.undo();  // the note
        QCOMPARE(w->lessons().lesson().views[0].view.note, std::string());
        undo.undo();
        QCOMPARE(titles(), QString("View 1, b12 picked"));
        undo.undo();
        QCOMPARE(titles(), QString("View 1, View 2"));
        undo.redo();  // the name, the move, the note again
        undo.redo();
        undo.redo();
        QCOMPARE(titles(), QString("b12 picked, View 1"));
        QCOMPARE(w->lessons().lesson().views[0].view.note, std::string("Ask first"));
        QVERIFY(!w->document().isModified());  // the scene's undo is untouched
    }

    void aLessonExportsAsPdfAndVideo() {
        const QString lesson = example("lessons/euler_lagrange_intro.lesson");
        const QString out = dir_.filePath("export");
        QProcess p;
        p.start(LL_CLI, {"lesson", lesson, "--out", out, "--format", "pdf", "--notes", "--size", "1280x720"});
        QVERIFY(p.waitForFinished(600000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QFile pdf(out + "/lesson.pdf");
        QVERIFY(pdf.open(QIODevice::ReadOnly));
        const QByteArray bytes = pdf.readAll();
        QCOMPARE(bytes.count("/Type /Page\n") + bytes.count("/Type /Page\r") + bytes.count("/Type /Page "), 10);
        p.start(LL_CLI, {"lesson", lesson, "--out", out, "--format", "mp4", "--size", "1280x720"});
        QVERIFY(p.waitForFinished(600000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        const QStringList videos = QDir(out).entryList({"*.mp4"}, QDir::Files);
        QCOMPARE(videos, QStringList{"07-the-double-pendulum-moving.mp4"});  // the one view that plays
        QProcess probe;
        probe.start("ffprobe", {"-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries", "stream=nb_read_frames,width,height",
                                "-of", "csv=p=0", out + "/" + videos[0]});
        QVERIFY(probe.waitForFinished(60000));
        // play [0.5, 2.5] s at 25 frames per second of the run: 51 frames
        QCOMPARE(QString(probe.readAllStandardOutput()).trimmed(), QString("1280,720,51"));
        // The lab report with the lesson's stills, each shown in its index with its title.
        const QString report = dir_.filePath("report");
        p.start(LL_CLI, {"report", example("planar_2r.json"), "--out", report, "--lesson", lesson, "--duration", "2"});
        QVERIFY(p.waitForFinished(600000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QFile index(report + "/index.md");
        QVERIFY(index.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(index.readAll());
        QCOMPARE(text.count("](lesson/"), 10);
        QVERIFY(text.contains("![3. Where b11 comes from](lesson/03-where-b11-comes-from.png)"));
        QCOMPARE(QImage(report + "/lesson/03-where-b11-comes-from.png").size(), QSize(1280, 720));
    }

    void theCommandLine() {
        const QString view = dir_.filePath("cli.json");
        QProcess p;
        p.start(LL_CLI, {example("planar_2r.json"), "--select", "b12", "--step", "7", "--at", "0.5", "--save-view", view});
        QVERIFY(p.waitForFinished(120000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        const WindowView saved = loadWindowView(view.toStdString());
        QCOMPARE(saved.pick.entry.value_or(""), std::string("b12"));
        QCOMPARE(saved.derivation.step.value_or(-1), 7);
        QCOMPARE(saved.playback.time.value_or(-1), 0.5);
        // A lesson with no view that can be read: the window opens it (beside the default
        // scene); the export has nothing to export and says so.
        const QString empty = dir_.filePath("empty.lesson");
        QFile file(empty);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format": "lagrangelab-lesson/1", "views": [{"include": "gone.json"}]})");
        file.close();
        p.start(LL_CLI, {empty, "--screenshot", dir_.filePath("empty.png")});
        QVERIFY(p.waitForFinished(120000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        p.start(LL_CLI, {"lesson", empty, "--out", dir_.filePath("nothing")});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(p.readAllStandardError().contains("no view to export"));
        for (const QStringList& bad : {QStringList{"--view", dir_.filePath("none.json"), "--screenshot", dir_.filePath("x.png")},
                                       QStringList{"--view", example("lessons/euler_lagrange_intro.lesson#nope"), "--screenshot", dir_.filePath("x.png")},
                                       QStringList{example("planar_2r.json"), "--save-view", dir_.filePath("v.txt")}}) {
            p.start(LL_CLI, bad);
            QVERIFY(p.waitForFinished(60000));
            QCOMPARE(p.exitCode(), 2);
            const QByteArray err = p.readAllStandardError();
            QVERIFY2(err.contains("none.json") || err.contains("nope") || err.contains("v.txt"), err.constData());
        }
    }
};

LL_TEST_MAIN(TestViewsWindow)

}  // namespace test_views_window
#include "test_views_window.moc"
