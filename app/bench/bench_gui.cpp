// lagrangelab-bench --gui [SCENE…] [--batches N]: what the window costs, in the window
// itself (needs a display; under xvfb-run on a machine without one):
//   - edit-to-updated-view latency: a DH cell edited through the editor's model (the
//     same undoable command a keystroke makes) until the re-simulated scene is drawn in
//     the 3D view (validation, debounce, worker simulation, VisualScene, plots, one GL
//     frame swapped: SceneView::frameSwapped); the derivation re-runs
//     beside it in its own thread and is timed apart;
//   - the Panda opened in a fresh window until its derivation (step 7) is on screen;
//   - the PUMA 560 animated in a 1280×720 view (posed at a new time every frame);
//   - start to the first drawn frame of the simulated default scene, a fresh lagrangelab;
//   - exercise mode: an answer checked in the window (Enter in its field until the verdict
//     is shown), the PUMA 560's b11 right and wrong.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <sys/resource.h>

#include <QApplication>
#include <QFile>
#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>

#include "core/io/data_directory.hpp"
#include "app/bench/bench.hpp"
#include "app/bench/bench_timing.hpp"
#include "app/bench/window_bench.hpp"
#include "app/commands.hpp"
#include "app/bench/program_run.hpp"
#include "app/event_wait.hpp"
#include "app/offscreen_gui.hpp"
#include "app/scene_loading.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/pipeline/scene_visual.hpp"
#include "core/visual/trajectory_sampler.hpp"
#include "ui/document/joint_table_model.hpp"
#include "ui/window/derivation_view.hpp"
#include "ui/window/main_window.hpp"
#include "ui/window/entry_linking.hpp"
#include "ui/window/exercise_mode.hpp"
#include "ui/window/exercise_panel.hpp"
#include <QLineEdit>
#include "ui/window/model_editor.hpp"
#include "ui/window/playback_bar.hpp"
#include "ui/window/scene_view.hpp"

namespace ll::bench {

using namespace ll::cli;

namespace {

using Clock = std::chrono::steady_clock;

// CPU seconds used by this process so far (every thread, llvmpipe's included).
double processCpu() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

// The first joint row with a non-zero numeric `a` (else d) to nudge.
std::pair<int, int> editableCell(const ui::SceneDocument& doc) {
    const auto joints = doc.value("/robot/joints");
    for (std::size_t i = 0; i < joints.size(); ++i)
        for (int column : {ui::JointTableModel::A, ui::JointTableModel::D}) {
            const auto v = doc.value(ui::JointTableModel::pointer(static_cast<int>(i), column));
            if (v.is_number() && v.get<double>() != 0) return {static_cast<int>(i), column};
        }
    return {0, ui::JointTableModel::A};
}

// `window` at 1280×800 on screen with `path` open (false, and said, when it cannot be).
bool openedIn(ui::MainWindow& window, const std::string& path) {
    window.setAskBeforeClosing(false);
    window.resize(1280, 800);
    window.show();
    if (window.openFile(QString::fromStdString(path), nullptr, true)) return true;
    std::printf("%s: cannot open\n", path.c_str());
    return false;
}

void latency(const std::string& path, int runs) {
    ui::MainWindow window;
    if (!openedIn(window, path)) return;
    waitFor([&] { return window.result() && !window.liveDerivation().busy(); }, 120);
    auto [row, column] = editableCell(window.document());
    ui::JointTableModel& model = window.editor().joints();
    const QModelIndex cell = model.index(row, column);
    const QString original = model.data(cell, Qt::EditRole).toString();
    double value = original.toDouble();
    if (value == 0) value = 0.5;
    std::vector<double> view, derive, validate, worker, shownAt, cpu;
    for (int k = 0; k < runs; ++k) {
        const long frames = window.sceneView().framesDrawn();
        int shown = -1;
        Clock::time_point shownTime, swapTime;
        bool swapped = false;
        auto connection = QObject::connect(&window, &ui::MainWindow::resultShown, [&](int request) {
            shown = request;
            shownTime = Clock::now();
        });
        // The first composed frame after the result: the moment the window shows it. (When
        // the wait below returns, events queued behind that frame, such as the derivation
        // and its own frame, may have been handled too.)
        auto swapConnection = QObject::connect(&window.sceneView(), &ui::SceneView::frameSwapped, [&] {
            if (shown >= window.liveSimulation().latestRequest() && !swapped) {
                swapped = true;
                swapTime = Clock::now();
            }
        });
        const double cpu0 = processCpu();
        const auto t0 = Clock::now();
        model.setData(cell, QString::number(value * (k % 2 ? 1.0 : 1.02), 'g', 12), Qt::EditRole);
        waitFor([&] { return !window.document().validating(); }, 30);
        const auto tValid = Clock::now();
        const int request = window.liveSimulation().latestRequest();
        bool drawn = waitFor([&] { return shown >= request && window.sceneView().framesDrawn() > frames && swapped; }, 30);
        const auto t1 = swapped ? swapTime : Clock::now();
        const double cpu1 = processCpu();
        waitFor([&] { return !window.liveDerivation().busy(); }, 60);
        const auto t2 = Clock::now();
        QObject::disconnect(connection);
        QObject::disconnect(swapConnection);
        if (!drawn) continue;
        view.push_back(ms(t0, t1));
        derive.push_back(ms(t0, t2));
        validate.push_back(ms(t0, tValid));
        worker.push_back(window.result()->workerSeconds * 1000);
        shownAt.push_back(ms(t0, shownTime));
        cpu.push_back((cpu1 - cpu0) * 1000);
    }
    std::printf("edit-to-updated-view latency, %s (joint %d %s): %.1f ms median of %zu (min %.1f, max %.1f): "
                "validation %.1f ms, worker (simulate + scene) %.1f ms, result on screen at %.1f ms, then the frame; "
                "process CPU %.1f ms; derivation shown after %.1f ms\n",
                path.c_str(), row + 1, column == ui::JointTableModel::A ? "a" : "d", median(view), view.size(),
                view.empty() ? 0 : *std::min_element(view.begin(), view.end()),
                view.empty() ? 0 : *std::max_element(view.begin(), view.end()), median(validate), median(worker), median(shownAt),
                median(cpu), median(derive));
}

// A large robot opened in a fresh window until its derivation is on screen: from the
// open until the derivation view has the document and its step is painted.
void derivationOnScreen(const std::string& path, int runs) {
    std::vector<double> times;
    for (int k = 0; k < runs; ++k) {
        ui::MainWindow window;
        window.setAskBeforeClosing(false);
        window.resize(1280, 800);
        window.show();
        waitFor([&] { return window.isVisible(); }, 10);
        window.showDerivationStep(7);
        bool finished = false;
        auto connection = QObject::connect(&window.derivationView(), &ui::DerivationView::derivationFinished, [&] { finished = true; });
        const auto t0 = Clock::now();
        if (!window.openFile(QString::fromStdString(path), nullptr, true)) {
            std::printf("%s: cannot open\n", path.c_str());
            return;
        }
        const bool shown = waitFor([&] { return finished && window.derivationView().document(); }, 60);
        QApplication::processEvents();  // the step's first paint
        const auto t1 = Clock::now();
        QObject::disconnect(connection);
        if (shown) times.push_back(ms(t0, t1));
    }
    std::printf("%s opened to its derivation on screen: %.0f ms median of %zu (budget 1000 ms)\n", path.c_str(), median(times),
                times.size());
}

// Exercise mode on `path`: Enter pressed in b11's field until its verdict is in the panel,
// `runs` times each for the right answer and a wrong one (another link's part missing).
void exerciseCheck(const std::string& path, int runs) {
    ui::MainWindow window;
    if (!openedIn(window, path)) return;
    window.showDerivationView("exercise");
    window.document().setValue("/exercise/entries", std::vector<std::string>{"b11"}, "bench");
    if (!waitFor([&] { return window.exercise().checking().key() && window.exercisePanel().field("b11"); }, 120)) {
        std::printf("%s: no answer key\n", path.c_str());
        return;
    }
    const auto key = window.exercise().checking().key();
    const QString right = QString::fromStdString(key->rightAnswer("b11")), wrong = right + " + m2";
    std::vector<double> times[2];
    QLineEdit* field = window.exercisePanel().field("b11");
    for (int k = 0; k < 2 * runs; ++k) {
        field->setText(k % 2 ? wrong : right);
        window.exercisePanel().showVerdict("b11", ui::ExercisePanel::Mark::None, {});
        const auto t0 = Clock::now();
        emit field->returnPressed();
        if (!waitFor([&] { return window.exercisePanel().mark("b11") != ui::ExercisePanel::Mark::None; }, 60)) break;
        QApplication::processEvents();  // the verdict's paint
        times[k % 2].push_back(ms(t0, Clock::now()));
    }
    std::printf("exercise check in the window, %s b11: right %.1f ms, wrong %.1f ms median of %d (budget 100 ms)\n", path.c_str(),
                median(times[0]), median(times[1]), runs);
}

// The frames `view` draws per second while `advance` is called for 2 s, `runs` times:
// the median frames/s and process CPU milliseconds per frame.
template <class Advance>
std::pair<double, double> framesPerSecond(ui::SceneView& view, int runs, Advance advance) {
    std::vector<double> fps, cpuPerFrame;
    for (int r = 0; r < runs; ++r) {
        const long before = view.framesDrawn();
        const double cpu0 = processCpu();
        QElapsedTimer clock;
        clock.start();
        while (clock.elapsed() < 2000) advance();
        fps.push_back((view.framesDrawn() - before) / (clock.elapsed() / 1000.0));
        cpuPerFrame.push_back((processCpu() - cpu0) * 1000 / std::max(1L, view.framesDrawn() - before));
    }
    return {median(fps), median(cpuPerFrame)};
}

void frameRate(const std::string& path, int runs) {
    const Scene scene = loadSceneReportingWarnings(path);
    const SimulationResult result = ll::simulate(scene);
    auto visual = std::make_shared<VisualScene>(visualScene(scene));
    visual->fitToMotion(result.trajectory);
    const TrajectorySampler sampler(result.trajectory);
    ui::SceneView view;
    view.resize(1280, 720);
    view.show();
    view.setVisualScene(visual, true);
    waitFor([&] { return view.framesDrawn() > 2; }, 10);
    Eigen::VectorXd q(sampler.dof()), qd(sampler.dof());
    double t = 0;
    const auto [fps, cpu] = framesPerSecond(view, runs, [&] {
        t = std::fmod(t + 1.0 / 30, sampler.endTime());
        sampler.sample(t, q, qd);
        const long frames = view.framesDrawn();
        view.setPose(q, t);
        waitFor([&] { return view.framesDrawn() > frames; }, 5);
    });
    std::printf("animation, %s in a %dx%d view (%s): %.1f frames/s median of %d runs of 2 s, %.1f ms process CPU per frame\n", path.c_str(),
                static_cast<int>(view.width() * view.devicePixelRatioF()), static_cast<int>(view.height() * view.devicePixelRatioF()),
                "software GL, Mesa llvmpipe under the current display", fps, runs, cpu);
}

// The window playing with an entry picked: every frame the entry's value is evaluated
// from the catalogue's tape, the links' shares computed, the 3D emphasis, the readout and
// the entry plot's cursor updated. Frames the 3D view draws per second of wall time.
void linkedFrameRate(const std::string& path, const QString& entry, int runs) {
    ui::MainWindow window;
    window.setAskBeforeClosing(false);
    window.resize(1280, 800);
    window.show();
    if (!window.openFile(QString::fromStdString(path), nullptr, true) ||
        !waitFor([&] { return window.result() && !window.liveDerivation().busy() && window.selection().catalogue(); }, 120) ||
        !window.linking().selectEntry(entry)) {
        std::printf("%s: could not pick %s\n", path.c_str(), qPrintable(entry));
        return;
    }
    // The 3D view at 1280x720 (the window around it as much larger as its docks need; the
    // display must be large enough: xvfb-run -s '-screen 0 2400x1400x24').
    ui::SceneView& view = window.sceneView();
    for (int k = 0; k < 3; ++k) {
        window.resize(window.width() + 1280 - view.width(), window.height() + 720 - view.height());
        pauseFor(0.2);
    }
    window.playback().setLoop(true);
    window.playback().play();
    waitFor([&] { return view.framesDrawn() > 5; }, 10);
    const auto [fps, cpu] = framesPerSecond(view, runs, [] { pauseFor(0.05); });  // the playback's timer draws
    window.playback().pause();
    std::printf("animation with %s picked (value, shares, emphasis, readout, entry plot every frame), %s, window %dx%d, "
                "3D view %dx%d: %.1f frames/s median of %d runs of 2 s, %.1f ms process CPU per frame\n",
                qPrintable(entry), path.c_str(), window.width(), window.height(), view.width(), view.height(), fps, runs, cpu);
}

void firstFrame(int runs) {
    std::vector<double> outside, inside;
    for (int r = 0; r < runs; ++r) {
        QProcess p;
        const auto t0 = Clock::now();
        // As a user starts it: lagrangelab, which hands the window over to this program.
        p.start(QString::fromStdString(lagrangelabProgram().string()), {"--first-frame"});
        p.waitForFinished(60000);
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        const QString out = QString::fromUtf8(p.readAllStandardOutput());
        const auto m = QRegularExpression("first frame after ([0-9.]+) ms").match(out);
        if (p.exitCode() != 0 || !m.hasMatch()) {
            std::printf("start to first frame: the window failed (exit %d): %s\n", p.exitCode(), p.readAllStandardError().constData());
            return;
        }
        inside.push_back(m.captured(1).toDouble());
        outside.push_back(ms);
    }
    std::printf("start to first drawn frame (default scene, simulated): %.0f ms median of %d (from main(); %.0f ms "
                "from spawning lagrangelab to exit)\n",
                median(inside), runs, median(outside));
}

}  // namespace

int gui(const std::vector<std::string>& scenes, int runs) {
    const QTemporaryDir recovery;
    const auto app = windowBenchApplication("gui", recovery);
    if (!app) return 2;
    const std::string examples = examplesDirectory().string();
    std::vector<std::string> latencyScenes = scenes;
    if (latencyScenes.empty()) latencyScenes = {examples + "/planar_2r.json", examples + "/puma560.json"};
    for (const std::string& s : latencyScenes) latency(s, runs);
    derivationOnScreen(examples + "/panda.json", std::max(3, runs / 2));
    frameRate(scenes.empty() ? examples + "/puma560.json" : scenes.front(), 3);
    linkedFrameRate(examples + "/puma560.json", "b23", 3);
    linkedFrameRate(examples + "/panda.json", "b11", 3);
    firstFrame(std::max(3, runs / 2));
    exerciseCheck(examples + "/puma560.json", std::max(5, runs));
    return 0;
}

}  // namespace ll::bench
