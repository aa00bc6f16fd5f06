// `lagrangelab render SCENE --out FILE [--duration T] [--fps F] [--size WxH] [--camera C]
// [--speed X] [--overlay time,energy,name|none] [--trail on|off] [--frames on|off] [--at T]
// [--msaa auto|edges|0|2|4|8]` (anti-aliasing; auto: 4x MSAA on a graphics card, edge smoothing
// on software GL, where MSAA costs about 3x per frame):
// simulates the scene and renders it headless (EGL, no X server) into an MP4, WebM, GIF,
// a PNG still, or a folder of numbered PNG frames.
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <sstream>

#include <sys/resource.h>
#include <unistd.h>

#include "app/cli_options.hpp"
#include "app/command_usage.hpp"
#include "app/commands.hpp"
#include "app/offscreen_gui.hpp"
#include "app/pixel_size.hpp"
#include "app/progress_bar.hpp"
#include "app/scene_loading.hpp"
#include "core/model/message_error.hpp"
#include "core/pipeline/display_derivation.hpp"
#include "core/pipeline/scene_simulation.hpp"
#include "core/present/localized_document.hpp"
#include "ui/document/animation_export.hpp"
#include "ui/paint/headless_renderer.hpp"
#include "ui/paint/ffmpeg_encoder.hpp"

namespace ll::cli {
namespace {

std::atomic<bool> interrupted{false};

void onInterrupt(int) { interrupted.store(true); }

// Ctrl-C and kill stop the render at the next frame, which then cleans up.
void catchInterrupts() {
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, nullptr);
    sigaction(SIGTERM, &action, nullptr);
    sigaction(SIGHUP, &action, nullptr);
}

ui::ExportSettings parseRenderOptions(const Options& options, const Scene& scene) {
    if (!options.has("out")) throw UsageError(UsageId::OutRequired, synopsisLine("render"));
    ui::ExportSettings s;
    s.out = options.text("out");
    try {
        s.kind = ui::outputKindFor(s.out);
    } catch (const std::invalid_argument& e) {
        throw UsageError(UsageId::OptionValueRefused, "out", s.out, e.what());  // ui's words
    }
    if (const std::string problem = ui::outputProblem(s.out, s.kind); !problem.empty())
        throw UsageError(UsageId::OptionValueRefused, "out", s.out, problem);  // ui's words

    const std::string size = options.text("size", "1280x720");
    const PixelSize pixels = parsePixelSize(size);
    s.width = pixels.width;
    s.height = pixels.height;
    if ((s.kind == ui::OutputKind::Mp4 || s.kind == ui::OutputKind::Webm) && (s.width % 2 || s.height % 2))
        throw UsageError(UsageId::SizeNotEven, size, s.kind == ui::OutputKind::Mp4 ? "H.264" : "VP9",
                         std::to_string(s.width + s.width % 2) + "x" + std::to_string(s.height + s.height % 2));

    s.fps = options.number("fps", 30);
    if (s.fps <= 0 || s.fps > 240) throw UsageError(UsageId::FpsOutOfRange, options.text("fps"));
    if (s.kind == ui::OutputKind::Gif && s.fps > 50) throw UsageError(UsageId::GifFpsTooHigh, options.text("fps"));
    s.duration = options.number("duration", scene.simulation.duration);
    if (s.duration <= 0) throw UsageError(UsageId::DurationNotPositive, options.text("duration"));
    s.speed = options.number("speed", 1.0);
    if (s.speed <= 0) throw UsageError(UsageId::SpeedNotPositive, options.text("speed"));

    try {
        s.camera = parseCameraSpec(options.text("camera", "auto"));
    } catch (const MessageError& e) {
        throw UsageError(UsageId::OptionValueRefused, "camera", options.text("camera"), e.message());  // the core's words
    }
    const auto onOff = [&](const char* name) {
        const std::string v = options.text(name, "on");
        if (v != "on" && v != "off") throw UsageError(UsageId::ValueExpectedOneOf, name, v, "on", "off");
        return v == "on";
    };
    s.trail = onOff("trail");
    s.frames = onOff("frames");

    const std::string overlay = options.text("overlay", "time,energy,name");
    s.overlay = {false, false, false};
    if (overlay != "none") {
        std::stringstream in(overlay);
        std::string item;
        while (std::getline(in, item, ',')) {
            if (item == "time") s.overlay.time = true;
            else if (item == "energy") s.overlay.energy = true;
            else if (item == "name") s.overlay.name = true;
            else throw UsageError(UsageId::UnknownOverlayItem, overlay, item);
        }
    }

    const std::string msaa = options.text("msaa", "auto");
    if (msaa == "auto") s.antialiasing = ui::kAutoAntialiasing;
    else if (msaa == "edges") s.antialiasing = ui::kEdgeSmoothing;
    else if (msaa == "0" || msaa == "2" || msaa == "4" || msaa == "8") s.antialiasing = std::stoi(msaa);
    else throw UsageError(UsageId::MsaaExpected, msaa);
    const std::string layout = options.text("layout", "view");
    if (layout != "view" && layout != "composite") throw UsageError(UsageId::ValueExpectedOneOf, "layout", layout, "view", "composite");
    s.composite = layout == "composite";
    if (options.has("step") && !s.composite) throw UsageError(UsageId::ValueOnlyWith, "step", options.text("step"), "--layout composite");
    if (s.composite && options.has("overlay")) throw UsageError(UsageId::CompositeLaysOutOverlay, options.text("overlay"));
    if (s.composite && (s.width < 480 || s.height < 270)) throw UsageError(UsageId::CompositeTooSmall, size);
    if (options.has("at")) {
        if (s.kind != ui::OutputKind::Still) throw UsageError(UsageId::AtNeedsStill, options.text("at"));
        s.at = options.number("at", 0);
        if (s.at < 0 || s.at > s.duration) throw UsageError(UsageId::AtOutsideDuration, options.text("at"), std::to_string(s.duration));
    }
    return s;
}

// The derivation step the composite frame shows (--step, default 8: the equations of
// motion), derived as `derive --format pdf` derives it, in the --lang/--notation asked.
std::shared_ptr<const present::DisplayStep> keyEquationStep(const Scene& scene, const std::string& path, const Options& options) {
    const double number = options.number("step", 8);
    if (number < 0 || number > symbolic::lastDerivationStep || number != std::floor(number)) throw UsageError(UsageId::StepNotDerivationStep, options.text("step"));
    DocumentRequest request;
    request.firstStep = request.lastStep = static_cast<int>(number);
    request.forPages = true;
    request.presentation = presentation();
    const DerivedDocument derived = inSceneFile(path, [&] { return deriveDisplay(scene, request); });
    const auto document = present::localizedDocument(*derived.display, presentation());
    if (const present::DisplayStep* step = document->step(static_cast<int>(number)))
        return std::make_shared<const present::DisplayStep>(*step);
    throw UsageError(UsageId::SceneHasNoStep, options.text("step"), path);
}

}  // namespace

int renderCommand(const Args& args) {
    const Options options(args, {"out", "duration", "fps", "size", "camera", "speed", "overlay", "trail", "frames", "at", "msaa", "layout",
                                 "step"});
    if (options.positional().size() != 1) throw UsageError(usageLine("render"));
    const std::string path = options.positional()[0];
    Scene scene = loadSceneReportingWarnings(path);
    ui::ExportSettings settings = parseRenderOptions(options, scene);
    if (settings.kind != ui::OutputKind::Still && settings.kind != ui::OutputKind::Folder && !ui::FfmpegEncoder::available())
        throw std::runtime_error(
            "ffmpeg not found on PATH: install it (Debian: apt-get install ffmpeg), or write PNG frames with --out FOLDER");
    scene.simulation.duration = settings.duration;
    requireValidSceneFrom(scene, path);
    if (settings.composite) {
        settings.step = keyEquationStep(scene, path, options);
        settings.language = presentation().language;
    }

    catchInterrupts();
    const bool tty = ::isatty(STDERR_FILENO);
    SimulationResult result;
    {
        ProgressBar bar(tty);
        result = simulate(
            scene, scene.simulation, [&](double f) { bar(0.2 * f); }, &interrupted);
    }
    if (interrupted.load()) {
        std::fprintf(stderr, "interrupted: nothing written\n");
        return 130;
    }
    if (result.status == SimulationStatus::Failed) {
        const UsageMessage stopped = usageMessage(UsageId::SimulationStoppedNothingRendered, result.message);
        std::fprintf(stderr, "%s\n", usageErrorLine(stopped, presentation().language).c_str());
        return 3;
    }
    const auto app = makeGuiApplication();
    ui::ExportTimings timings;
    try {
        ProgressBar bar(tty);
        timings = ui::exportAnimation(
            scene, result.trajectory, settings, [&](double f) { bar(0.2 + 0.8 * f); }, &interrupted);
    } catch (const ui::ExportCancelled&) {
        std::fprintf(stderr, "interrupted: nothing written\n");
        return 130;
    }
    std::fprintf(stderr, "%ld frame%s of %dx%d in %.2f s (%.1f frames/s; %s, %s)\n", timings.frames, timings.frames == 1 ? "" : "s",
                 settings.width, settings.height, timings.total, timings.frames / std::max(timings.total, 1e-9), timings.renderer.c_str(),
                 timings.antialiasing.c_str());
    rusage self{}, children{};
    getrusage(RUSAGE_SELF, &self);
    getrusage(RUSAGE_CHILDREN, &children);
    std::fprintf(stderr, "peak memory: %.0f MB lagrangelab, %.0f MB ffmpeg\n", self.ru_maxrss / 1024.0, children.ru_maxrss / 1024.0);
    std::printf("%s\n", settings.out.c_str());
    return 0;
}

}  // namespace ll::cli
