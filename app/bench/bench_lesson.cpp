// lagrangelab-bench --lesson [--batches N]: going from one view of a lesson to the next in
// presentation mode at 1280×720, from the key (LessonMode::next) until the view is on screen
// (every part restored and a frame of the 3D view drawn after it): between two views of a
// scene already loaded (the 2R: another step, entry, tab and time), and to a view of a scene
// not loaded (the Franka Panda, opened, simulated and derived; and back to the 2R).
#include <chrono>
#include <cstdio>
#include <vector>


#include "app/bench/bench.hpp"
#include "app/bench/bench_timing.hpp"
#include "app/bench/window_bench.hpp"
#include "app/event_wait.hpp"
#include "core/io/data_directory.hpp"
#include "core/io/lesson_file.hpp"
#include "ui/window/lesson_mode.hpp"
#include "ui/window/main_window.hpp"
#include "ui/window/presentation_mode.hpp"
#include "ui/window/scene_view.hpp"

namespace ll::bench {

using namespace ll::cli;
using Clock = std::chrono::steady_clock;

int lesson(int runs) {
    const QTemporaryDir dir;
    const auto app = windowBenchApplication("lesson", dir);
    if (!app) return 2;

    // Views 1 → 2: the same scene; 3 → 4 → 5: the Panda, the 2R, each a scene not loaded.
    const std::string examples = examplesDirectory().string();
    Lesson lesson;
    const auto add = [&](const std::string& scene, const char* json) {
        WindowView view = readWindowView(scene_json::Json::parse(json));
        view.scenePath = examples + "/" + scene;
        lesson.views.push_back(LessonView{view, {}, {}, {}});
    };
    add("planar_2r.json", R"({"derivation": {"step": 7}, "pick": {"entry": "b11"}, "playback": {"time": 1.2}})");
    add("planar_2r.json", R"({"derivation": {"step": 8}, "plots": {"tab": "torques", "joint": 2}, "playback": {"time": 2.0}})");
    add("panda.json", R"({"derivation": {"step": 8}, "playback": {"time": 0.5}})");
    add("planar_2r.json", R"({"derivation": {"step": 5}, "playback": {"time": 0.3}})");
    const std::string path = dir.filePath("bench.lesson").toStdString();
    saveLesson(lesson, path);

    ui::MainWindow window;
    window.setAskBeforeClosing(false);
    window.resize(1280, 720);
    window.presentationMode().setSize(QSize(1280, 720));
    window.show();
    if (!window.lessons().open(QString::fromStdString(path))) return 1;
    int shown = -1;
    QObject::connect(&window.lessons(), &ui::LessonMode::viewShown, &window, [&](int i, const QStringList&) { shown = i; });
    // From the key to the view on screen: restored, then a frame drawn after it.
    const auto timed = [&](int index, bool first) {
        shown = -1;
        const Clock::time_point t0 = Clock::now();
        if (first) window.lessons().present(index);
        else window.lessons().go(index);
        if (!waitFor([&] { return shown == index; }, 300)) return -1.0;
        const long frames = window.sceneView().framesDrawn();
        window.sceneView().requestFrame();
        waitFor([&] { return window.sceneView().framesDrawn() > frames; }, 10);
        return ms(t0, Clock::now());
    };
    if (timed(0, true) < 0) return 1;
    std::vector<double> loaded, panda, back;
    for (int k = 0; k < runs; ++k) {
        loaded.push_back(timed(1, false));  // 2R → 2R
        if (timed(0, false) < 0) return 1;
        loaded.push_back(timed(1, false));
        panda.push_back(timed(2, false));  // 2R → Panda, not loaded
        back.push_back(timed(3, false));   // Panda → 2R, not loaded
        if (timed(0, false) < 0) return 1;
    }
    std::printf("next view, its scene loaded (2R: step, entry, tab, time):   %7.1f ms median of %zu (budget 200 ms)\n", median(loaded), loaded.size());
    std::printf("next view, the Franka Panda not loaded (opened, run, derived): %7.1f ms median of %zu (budget 1000 ms)\n", median(panda), panda.size());
    std::printf("next view, the 2R not loaded (from the Panda):               %7.1f ms median of %zu\n", median(back), back.size());
    return 0;
}

}  // namespace ll::bench
