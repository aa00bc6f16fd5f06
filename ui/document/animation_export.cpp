#include "ui/document/animation_export.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <regex>

#include <fcntl.h>
#include <unistd.h>

#include <QImageWriter>

#include "core/visual/trajectory_sampler.hpp"
#include "core/pipeline/scene_visual.hpp"
#include "core/visual/visual_scene.hpp"
#include "ui/paint/ffmpeg_encoder.hpp"
#include "ui/paint/composite_frame.hpp"
#include "ui/paint/headless_renderer.hpp"
#include "ui/paint/osg_scene.hpp"

namespace ll::ui {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

const std::regex& framePattern() {
    static const std::regex pattern("frame_[0-9]+\\.png");
    return pattern;
}

fs::path temporaryBeside(const fs::path& target) {
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    return dir / ("." + target.filename().string() + ".part-" + std::to_string(::getpid()));
}

// `fast`: frames of a folder (zlib level about 2); a still is compressed hardest.
// Qt's PNG writer takes the compression on a 0–100 scale.
void savePng(const QImage& image, const fs::path& path, bool fast) {
    QImageWriter writer(QString::fromStdString(path.string()), "png");
    writer.setCompression(fast ? 25 : 100);
    if (!writer.write(image)) throw std::runtime_error("cannot write " + path.string() + ": " + writer.errorString().toStdString());
}

// Where frames go. The destructor of an unfinished sink removes what it wrote.
class FrameSink {
public:
    virtual ~FrameSink() = default;
    virtual void write(const QImage& frame) = 0;
    virtual void finish() = 0;
};

class VideoSink : public FrameSink {
public:
    VideoSink(const std::string& path, VideoFormat format, int w, int h, double fps) : encoder_(path, format, w, h, fps) {}
    void write(const QImage& frame) override { encoder_.write(frame.constBits()); }
    void finish() override { encoder_.finish(); }

private:
    FfmpegEncoder encoder_;
};

class StillSink : public FrameSink {
public:
    explicit StillSink(const fs::path& path) : path_(path), temporary_(temporaryBeside(path)) {}
    ~StillSink() override {
        std::error_code ignored;
        fs::remove(temporary_, ignored);
    }
    void write(const QImage& frame) override { savePng(frame, temporary_, false); }
    void finish() override { fs::rename(temporary_, path_); }

private:
    fs::path path_, temporary_;
};

// frame_00000.png, frame_00001.png, … in a temporary folder, renamed to the target; an
// earlier render's folder of frames under that name is replaced.
class FolderSink : public FrameSink {
public:
    explicit FolderSink(const fs::path& path) : path_(path), temporary_(temporaryBeside(path)) {
        fs::remove_all(temporary_);
        fs::create_directory(temporary_);
    }
    ~FolderSink() override {
        std::error_code ignored;
        fs::remove_all(temporary_, ignored);
    }
    void write(const QImage& frame) override {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05ld.png", count_++);
        savePng(frame, temporary_ / name, true);
    }
    void finish() override {
        if (fs::exists(path_)) fs::remove_all(path_);  // outputProblem() allowed only an earlier render's frames
        fs::rename(temporary_, path_);
    }

private:
    fs::path path_, temporary_;
    long count_ = 0;
};

std::unique_ptr<FrameSink> makeSink(const ExportSettings& s) {
    switch (s.kind) {
        case OutputKind::Mp4: return std::make_unique<VideoSink>(s.out, VideoFormat::Mp4, s.width, s.height, s.fps);
        case OutputKind::Webm: return std::make_unique<VideoSink>(s.out, VideoFormat::Webm, s.width, s.height, s.fps);
        case OutputKind::Gif: return std::make_unique<VideoSink>(s.out, VideoFormat::Gif, s.width, s.height, s.fps);
        case OutputKind::Still: return std::make_unique<StillSink>(s.out);
        case OutputKind::Folder: return std::make_unique<FolderSink>(s.out);
    }
    return nullptr;
}

}  // namespace

OutputKind outputKindFor(const std::string& path) {
    const fs::path p(path);
    std::string ext = p.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".mp4") return OutputKind::Mp4;
    if (ext == ".webm") return OutputKind::Webm;
    if (ext == ".gif") return OutputKind::Gif;
    if (ext == ".png") return OutputKind::Still;
    if (ext.empty() || path.back() == '/' || fs::is_directory(p)) return OutputKind::Folder;
    throw std::invalid_argument("unknown output type '" + ext + "' (use .mp4, .webm, .gif, .png, or a folder for PNG frames)");
}

std::string outputProblem(const std::string& path, OutputKind kind) {
    fs::path target(path);
    if (kind == OutputKind::Folder && !path.empty() && path.back() == '/') target = fs::path(path.substr(0, path.size() - 1));
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    if (!fs::is_directory(dir)) return "folder " + dir.string() + " does not exist";
    // Writable for real (root passes access() everywhere, even where nothing can be created).
    const fs::path probe = dir / (".lagrangelab-probe-" + std::to_string(::getpid()));
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
    if (fd < 0) return "folder " + dir.string() + " is not writable";
    ::close(fd);
    ::unlink(probe.c_str());
    if (kind == OutputKind::Folder && fs::exists(target)) {
        if (!fs::is_directory(target)) return "exists and is not a folder";
        for (const auto& entry : fs::directory_iterator(target))
            if (!std::regex_match(entry.path().filename().string(), framePattern()))
                return "folder holds files other than frames of an earlier render (" + entry.path().filename().string() + ")";
    }
    if (kind != OutputKind::Folder && fs::is_directory(target)) return "is a folder";
    return "";
}

bool hasNonConservativeForces(const Scene& scene) {
    if (scene.effects.hasFriction() || !scene.effects.torques.empty()) return true;
    if (scene.lagrangian)
        for (const std::string& force : scene.lagrangian->forces)
            if (force.find_first_not_of(" 0.") != std::string::npos) return true;
    return false;
}

ExportTimings exportAnimation(const Scene& scene, const Trajectory& trajectory, const ExportSettings& settings,
                              const std::function<void(double)>& progress, const std::atomic<bool>* cancel) {
    ExportTimings timings;
    const auto start = Clock::now();
    ExportSettings s = settings;
    if (s.kind == OutputKind::Folder && !s.out.empty() && s.out.back() == '/') s.out.pop_back();

    VisualScene visual = visualScene(scene);
    visual.fitToMotion(trajectory);
    OsgSceneOptions sceneOptions;
    sceneOptions.frames = s.frames;
    sceneOptions.frameLabels = s.frameLabels;
    sceneOptions.trail = s.trail;
    sceneOptions.labelPixels = std::max(10.0, s.height / 40.0);
    OsgScene graph(visual, sceneOptions);
    const CompositeLayout layout = CompositeLayout::forSize(QSize(s.width, s.height));
    const QSize viewSize = s.composite ? layout.view.size() : QSize(s.width, s.height);
    HeadlessRenderer gl(viewSize.width(), viewSize.height(), s.antialiasing);
    timings.renderer = gl.rendererName();
    timings.antialiasing = gl.antialiasing();
    gl.setScene(graph.root());
    const CameraView camera = cameraView(visual, s.camera, gl.aspect());
    applyCameraView(*gl.camera(), camera, gl.aspect());

    const TrajectorySampler sampler(trajectory);
    const std::vector<double> times =
        s.kind == OutputKind::Still ? std::vector<double>{s.at} : frameTimes(sampler.startTime(), s.duration, s.fps, s.speed);

    // The end effector's path at 100 Hz of simulated time, for the trail.
    std::vector<double> pathTimes;
    std::vector<Eigen::Vector3d> path;
    const int n = sampler.dof();
    Eigen::VectorXd q(n), qd(n);
    if (s.trail && visual.endEffector >= 0) {
        const double last = times.back();
        for (double t = std::max(sampler.startTime(), times.front() - s.trailSeconds); t < last; t += 0.01) {
            sampler.sample(t, q, qd);
            visual.pose(q, t);
            pathTimes.push_back(t);
            path.push_back(visual.endEffectorPosition());
        }
    }
    std::vector<Eigen::Vector3d> trail;
    trail.reserve(OsgScene::maxTrailPoints);

    std::unique_ptr<FrameOverlay> overlay;
    std::unique_ptr<CompositeFrame> composite;
    if (s.composite)
        composite = std::make_unique<CompositeFrame>(trajectory, QString::fromStdString(scene.name), QSize(s.width, s.height), s.step.get(),
                                                     s.language, hasNonConservativeForces(scene), s.speed);
    else if (s.overlay.any())
        overlay = std::make_unique<FrameOverlay>(trajectory, QString::fromStdString(scene.name), QSize(s.width, s.height), s.overlay,
                                                 hasNonConservativeForces(scene), s.speed);
    std::unique_ptr<FrameSink> sink = makeSink(s);
    timings.setup = since(start);

    QImage image, frame;
    for (std::size_t k = 0; k < times.size(); ++k) {
        if (cancel && cancel->load()) throw ExportCancelled();
        const double t = times[k];
        auto mark = Clock::now();
        sampler.sample(t, q, qd);
        visual.pose(q, t);
        graph.update(visual);
        graph.placeLabels(visual, camera, viewSize.width(), viewSize.height());
        if (!path.empty()) {
            trail.clear();
            const auto first = std::lower_bound(pathTimes.begin(), pathTimes.end(), t - s.trailSeconds);
            const auto end = std::lower_bound(pathTimes.begin(), pathTimes.end(), t);
            for (auto it = first; it != end; ++it) trail.push_back(path[it - pathTimes.begin()]);
            trail.push_back(visual.endEffectorPosition());
            graph.setTrail(trail);
        }
        timings.pose += since(mark);
        mark = Clock::now();
        gl.draw();
        timings.draw += since(mark);
        mark = Clock::now();
        gl.readBack(image);
        timings.readBack += since(mark);
        mark = Clock::now();
        const std::array<double, 4> energies{sampler.scalar(trajectory.Ekin, t), sampler.scalar(trajectory.Epot, t),
                                             sampler.scalar(trajectory.E, t), sampler.scalar(trajectory.work, t)};
        if (composite) composite->paint(frame, image, t, energies);
        else if (overlay) overlay->paint(image, t, energies);
        timings.overlay += since(mark);
        mark = Clock::now();
        sink->write(composite ? frame : image);
        timings.write += since(mark);
        ++timings.frames;
        if (progress) progress(double(k + 1) / times.size());
    }
    if (cancel && cancel->load()) throw ExportCancelled();
    const auto mark = Clock::now();
    sink->finish();
    timings.write += since(mark);
    timings.total = since(start);
    return timings;
}

}  // namespace ll::ui
