// lagrangelab-bench --render [SCENE] [--batches N]: what headless export costs.
//  1. The whole `render` pipeline, 10 s of the scene at 30 fps, 1280x720, MP4 with every
//     overlay: wall time (median of N runs) and where it goes per stage.
//  2. Render-only frames per second (OSG draw into the FBO, glFinish), with and without
//     4× MSAA, and with the read-back.
//  3. The composite slide, `render --layout composite` as a process, 10 s at 720p30.
//  4. Peak memory of `lagrangelab render` at 1920x1080 for 10 s and 60 s of video
//     (run as a child process; its own report of its and ffmpeg's peak RSS).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "app/bench/bench.hpp"
#include "app/bench/bench_timing.hpp"
#include "app/bench/program_run.hpp"
#include "app/commands.hpp"
#include "app/offscreen_gui.hpp"
#include "app/scene_loading.hpp"
#include "core/visual/trajectory_sampler.hpp"
#include "core/pipeline/scene_visual.hpp"
#include "core/visual/visual_scene.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "ui/document/animation_export.hpp"
#include "core/io/data_directory.hpp"
#include "ui/paint/headless_renderer.hpp"
#include "ui/paint/osg_scene.hpp"

namespace ll::bench {

using namespace ll::cli;
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Frames per second of `frames` frames of the trajectory (pose + draw [+ read-back]).
double framesPerSecond(const Scene& scene, const Trajectory& trajectory, int antialiasing, bool readBack, int frames) {
    VisualScene visual = visualScene(scene);
    visual.fitToMotion(trajectory);
    ui::OsgScene graph(visual);
    ui::HeadlessRenderer gl(1280, 720, antialiasing);
    gl.setScene(graph.root());
    ui::applyCameraView(*gl.camera(), cameraView(visual, CameraSpec{}, gl.aspect()), gl.aspect());
    const TrajectorySampler sampler(trajectory);
    Eigen::VectorXd q(sampler.dof()), qd(sampler.dof());
    QImage image;
    gl.draw();  // first frame compiles the scene's GL objects
    const auto start = Clock::now();
    for (int k = 0; k < frames; ++k) {
        const double t = sampler.startTime() + k / 30.0;
        sampler.sample(t, q, qd);
        visual.pose(q, t);
        graph.update(visual);
        gl.draw();
        if (readBack) gl.readBack(image);
    }
    return frames / std::chrono::duration<double>(Clock::now() - start).count();
}

// Runs `lagrangelab render` as a child; returns its "peak memory: …" line.
std::string peakMemory(const std::string& scene, double duration, const fs::path& out) {
    const fs::path log = fs::temp_directory_path() / ("lagrangelab-bench-" + std::to_string(::getpid()) + ".log");
    const std::string seconds = std::to_string(duration);
    const int exitCode = runLagrangelab({"render", scene, "--duration", seconds, "--size", "1920x1080", "--out", out.string()}, log);
    if (exitCode == 127) return "could not start the render";
    std::ifstream in(log);
    std::string line, found = "render failed (exit " + std::to_string(exitCode) + ")";
    while (std::getline(in, line))
        if (line.rfind("peak memory", 0) == 0) found = line;
    fs::remove(log);
    fs::remove(out);
    return found;
}

}  // namespace

int render(const std::vector<std::string>& scenes, int runs) {
    const std::string path = scenes.empty() ? (examplesDirectory() / "puma560.json").string() : scenes.front();
    Scene scene = loadSceneReportingWarnings(path);
    scene.simulation.duration = 10.0;
    const auto app = makeGuiApplication();
    const Trajectory trajectory = simulate(scene, scene.simulation).trajectory;
    const fs::path dir = fs::temp_directory_path();
    const fs::path video = dir / ("lagrangelab-bench-" + std::to_string(::getpid()) + ".mp4");

    std::printf("%s, headless (EGL surfaceless), 1280x720\n\n", scene.name.c_str());
    ui::ExportSettings settings;
    settings.out = video.string();
    settings.duration = 10.0;
    ui::ExportTimings last;
    struct Mode {
        int antialiasing;
        const char* name;
    };
    for (const Mode mode : {Mode{ui::kAutoAntialiasing, "--msaa auto (default)"}, Mode{4, "--msaa 4"}, Mode{0, "--msaa 0"}}) {
        settings.antialiasing = mode.antialiasing;
        std::vector<double> wall;
        for (int r = 0; r < runs; ++r) {
            last = ui::exportAnimation(scene, trajectory, settings);
            wall.push_back(last.total);
            fs::remove(video);
        }
        std::printf("render 10 s at 30 fps to MP4 (H.264) with overlays, 300 frames, %s = %s: %.2f s wall (median of %d; "
                    "%.1f frames/s, %.2fx real time)\n",
                    mode.name, last.antialiasing.c_str(), median(wall), runs, 300 / median(wall), 10.0 / median(wall));
        std::printf("  last run per stage [s]: setup %.2f, pose %.2f, draw %.2f, read-back %.2f, overlay %.2f, to ffmpeg %.2f\n",
                    last.setup, last.pose, last.draw, last.readBack, last.overlay, last.write);
    }
    std::printf("  renderer: %s\n\n", last.renderer.c_str());

    std::printf("render only (pose + OSG draw + glFinish), frames/s over 150 frames:\n");
    std::printf("  4x MSAA %.1f, no MSAA %.1f; with read-back: 4x MSAA %.1f, no MSAA %.1f, edge smoothing %.1f\n\n",
                framesPerSecond(scene, trajectory, 4, false, 150), framesPerSecond(scene, trajectory, 0, false, 150),
                framesPerSecond(scene, trajectory, 4, true, 150), framesPerSecond(scene, trajectory, 0, true, 150),
                framesPerSecond(scene, trajectory, ui::kEdgeSmoothing, true, 150));

    // The slide: the whole `render --layout composite` process (load, simulate, derive
    // step 8, render the view, compose, encode), budget 15 s for 10 s at 720p30.
    {
        std::vector<double> wall;
        const fs::path log = dir / ("lagrangelab-bench-composite-" + std::to_string(::getpid()) + ".log");
        const fs::path slide = dir / ("lagrangelab-bench-composite-" + std::to_string(::getpid()) + ".mp4");
        int exitCode = 0;
        for (int r = 0; r < runs && exitCode == 0; ++r) {
            const auto start = Clock::now();
            exitCode = runLagrangelab({"render", path, "--layout", "composite", "--duration", "10", "--fps", "30", "--size", "1280x720",
                                       "--out", slide.string()},
                                      log);
            wall.push_back(std::chrono::duration<double>(Clock::now() - start).count());
            fs::remove(slide);
        }
        fs::remove(log);
        if (exitCode != 0) std::printf("render --layout composite failed (exit %d)\n\n", exitCode);
        else
            std::printf("`lagrangelab render --layout composite`, 10 s at 720p30 (simulate, derive step 8, render, compose, "
                        "encode): %.2f s wall (median of %d; budget 15 s)\n\n",
                        median(wall), runs);
    }

    std::printf("peak resident memory of `lagrangelab render` at 1920x1080, MP4:\n");
    for (double seconds : {10.0, 60.0})
        std::printf("  %2.0f s of video: %s\n", seconds, peakMemory(path, seconds, dir / ("lagrangelab-bench-memory.mp4")).c_str());
    return 0;
}

}  // namespace ll::bench
