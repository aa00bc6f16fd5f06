#pragma once
// An animation of a simulated trajectory rendered offscreen into a file: the pipeline of
// `lagrangelab render` (and of the window's export later).
//
//   VisualScene (core, posed per frame at t_k = t0 + k·speed/fps from the Hermite
//   sampler) → OsgScene → HeadlessRenderer (EGL; 4× MSAA, or edge smoothing on software GL) → FrameOverlay (time, name,
//   energy inset) → a sink: ffmpeg (mp4, webm, gif), numbered PNGs in a folder, or one
//   PNG still.
//
// Every sink writes under a temporary name beside the target and renames when
// complete; on an exception or a cancel nothing is left under the target's name (nor a
// temporary, nor an ffmpeg process).
#include <atomic>
#include <functional>
#include <stdexcept>
#include <string>

#include <memory>

#include "core/model/scene.hpp"
#include "core/present/display_document.hpp"
#include "core/visual/camera_view.hpp"
#include "core/simulation/trajectory.hpp"
#include "ui/paint/frame_overlay.hpp"

namespace ll::ui {

enum class OutputKind { Mp4, Webm, Gif, Still, Folder };

// By extension (.mp4, .webm, .gif, .png); a path with no extension, ending in '/', or
// naming an existing folder is a folder of frames. Throws std::invalid_argument for any
// other extension.
OutputKind outputKindFor(const std::string& path);
// Why `path` cannot receive the output (its folder is missing or not writable, or it is
// a folder holding files other than frames of an earlier render), or "" when it can.
std::string outputProblem(const std::string& path, OutputKind kind);

struct ExportSettings {
    std::string out;
    OutputKind kind = OutputKind::Mp4;
    double duration = 0;  // [s] simulated time shown, from the trajectory's start
    double fps = 30;
    double speed = 1;  // simulated seconds per second of video (< 1: slow motion)
    int width = 1280, height = 720;
    CameraSpec camera;
    OverlayOptions overlay;
    bool trail = true;        // end-effector path of the last `trailSeconds`
    double trailSeconds = 2;  // [s] simulated
    bool frames = true;       // DH triads
    bool frameLabels = true;  // and their numbers
    double at = 0;            // Still: the picture's time [s]
    int antialiasing = -1;    // MSAA samples, or kEdgeSmoothing / kAutoAntialiasing (ui/paint/headless_renderer.hpp)
    // The slide layout (ui/paint/composite_frame.hpp): the 3D view beside `step`'s key equation
    // and the energy plot, in one width × height frame; `overlay` is then not used.
    bool composite = false;
    std::shared_ptr<const present::DisplayStep> step;
    present::Language language = present::Language::English;  // the step's document's
};

// Wall time spent per stage over the whole export [s].
struct ExportTimings {
    long frames = 0;
    double setup = 0, pose = 0, draw = 0, readBack = 0, overlay = 0, write = 0, total = 0;
    std::string renderer;      // the GL renderer string
    std::string antialiasing;  // "4x MSAA", "edge smoothing" or "none"
};

class ExportCancelled : public std::runtime_error {
public:
    ExportCancelled() : std::runtime_error("cancelled") {}
};

// Renders `trajectory` of `scene` into settings.out. Needs a QGuiApplication when an
// overlay is on (fonts; headless, QT_QPA_PLATFORM=offscreen). `progress` gets the
// fraction done; a set `cancel` stops at the next frame and throws ExportCancelled,
// after removing every temporary. Throws FfmpegMissing (ui/paint/ffmpeg_encoder.hpp) or
// std::runtime_error naming what failed.
ExportTimings exportAnimation(const Scene& scene, const Trajectory& trajectory, const ExportSettings& settings,
                              const std::function<void(double)>& progress = {}, const std::atomic<bool>* cancel = nullptr);

// Whether the scene has non-conservative forces (friction, torques, a Lagrangian's
// forces): then the energy inset also draws their work W.
bool hasNonConservativeForces(const Scene& scene);

}  // namespace ll::ui
