#include "ui/paint/ffmpeg_encoder.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace ll::ui {
namespace fs = std::filesystem;
namespace {

std::string number(double x) {
    std::ostringstream out;
    out.precision(10);
    out << x;
    return out.str();
}

// Starts `args` (args[0] = "ffmpeg") in its own process group with default signal
// handling, stdin from `stdinFd` (-1: /dev/null), stdout to /dev/null, stderr to `log`.
pid_t spawn(const std::vector<std::string>& args, int stdinFd, const std::string& log) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (stdinFd >= 0) posix_spawn_file_actions_adddup2(&actions, stdinFd, 0);
    else posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t defaults, none;
    sigemptyset(&defaults);
    for (int s : {SIGINT, SIGTERM, SIGPIPE, SIGHUP}) sigaddset(&defaults, s);
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setpgroup(&attributes, 0);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int error = posix_spawnp(&pid, argv[0], &actions, &attributes, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
    if (error == ENOENT) throw FfmpegMissing("ffmpeg not found on PATH");
    if (error != 0) throw std::runtime_error(std::string("cannot start ffmpeg: ") + std::strerror(error));
    return pid;
}

// Waits for `pid`; its exit code, or 128 + signal.
int waitFor(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

}  // namespace

bool FfmpegEncoder::available() {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "");
    std::string dir;
    while (std::getline(dirs, dir, ':'))
        if (!dir.empty() && ::access((fs::path(dir) / "ffmpeg").c_str(), X_OK) == 0) return true;
    return false;
}

FfmpegEncoder::FfmpegEncoder(const std::string& path, VideoFormat format, int width, int height, double fps)
    : path_(path), format_(format), frameBytes_(std::size_t(width) * height * 4) {
    if (!available())
        throw FfmpegMissing("ffmpeg not found on PATH: install it (Debian: apt-get install ffmpeg), or write PNG frames "
                            "with --out FOLDER");
    std::signal(SIGPIPE, SIG_IGN);  // a dead ffmpeg makes write() fail with EPIPE instead of killing us
    const fs::path target(path);
    const std::string stem = target.filename().string(), pid = std::to_string(::getpid());
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    temporary_ = (dir / ("." + stem + ".part-" + pid)).string();
    char logName[] = "/tmp/lagrangelab-ffmpeg-XXXXXX";
    const int logFd = ::mkstemp(logName);
    if (logFd < 0) throw std::runtime_error("cannot create a temporary file in /tmp");
    ::close(logFd);
    log_ = logName;

    std::vector<std::string> args = {"ffmpeg",
                                     "-hide_banner",
                                     "-loglevel",
                                     "error",
                                     "-y",
                                     "-f",
                                     "rawvideo",
                                     "-pix_fmt",
                                     "rgb0",
                                     "-s",
                                     std::to_string(width) + "x" + std::to_string(height),
                                     "-framerate",
                                     number(fps),
                                     "-i",
                                     "pipe:0"};
    switch (format) {
        case VideoFormat::Mp4:
            args.insert(args.end(), {"-c:v", "libx264", "-preset", "veryfast", "-crf", "20", "-pix_fmt", "yuv420p", "-movflags",
                                     "+faststart", "-f", "mp4", temporary_});
            break;
        case VideoFormat::Webm:
            args.insert(args.end(), {"-c:v", "libvpx-vp9", "-deadline", "realtime", "-cpu-used", "8", "-row-mt", "1", "-b:v", "0", "-crf",
                                     "33", "-pix_fmt", "yuv420p", "-f", "webm", temporary_});
            break;
        case VideoFormat::Gif:
            intermediate_ = (dir / ("." + stem + ".part-" + pid + ".mkv")).string();
            palette_ = (dir / ("." + stem + ".part-" + pid + ".png")).string();
            args.insert(args.end(), {"-map", "0", "-c:v", "ffv1", "-f", "matroska", intermediate_, "-map", "0", "-vf",
                                     "palettegen=stats_mode=diff", "-update", "1", "-f", "image2", palette_});
            break;
    }
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("cannot create a pipe to ffmpeg");
    try {
        pid_ = spawn(args, fds[0], log_);
    } catch (...) {
        ::close(fds[0]);
        ::close(fds[1]);
        ::unlink(log_.c_str());
        throw;
    }
    ::close(fds[0]);
    pipe_ = fds[1];
}

FfmpegEncoder::~FfmpegEncoder() {
    if (!finished_) abort();
    if (!log_.empty()) ::unlink(log_.c_str());
}

std::string FfmpegEncoder::logTail() const {
    std::ifstream in(log_);
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return last.empty() ? "no message" : last;
}

void FfmpegEncoder::removeTemporaries() {
    for (const std::string& f : {temporary_, intermediate_, palette_})
        if (!f.empty()) ::unlink(f.c_str());
}

void FfmpegEncoder::write(const unsigned char* rgbx) {
    std::size_t done = 0;
    while (done < frameBytes_) {
        const ssize_t n = ::write(pipe_, rgbx + done, frameBytes_ - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            ::close(pipe_);
            pipe_ = -1;
            const int code = waitFor(pid_);
            pid_ = 0;
            removeTemporaries();
            finished_ = true;
            throw std::runtime_error("ffmpeg stopped while encoding " + path_ + " (exit " + std::to_string(code) + "): " + logTail());
        }
        done += static_cast<std::size_t>(n);
    }
}

void FfmpegEncoder::finish() {
    ::close(pipe_);
    pipe_ = -1;
    int code = waitFor(pid_);
    pid_ = 0;
    if (code == 0 && format_ == VideoFormat::Gif) {
        pid_ = spawn({"ffmpeg", "-hide_banner", "-loglevel", "error", "-y", "-i", intermediate_, "-i", palette_, "-lavfi",
                      "[0:v][1:v]paletteuse=dither=bayer:bayer_scale=4:diff_mode=rectangle", "-f", "gif", temporary_},
                     -1, log_);
        code = waitFor(pid_);
        pid_ = 0;
    }
    finished_ = true;
    if (code != 0) {
        removeTemporaries();
        throw std::runtime_error("ffmpeg failed on " + path_ + " (exit " + std::to_string(code) + "): " + logTail());
    }
    if (::rename(temporary_.c_str(), path_.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        removeTemporaries();
        throw std::runtime_error("cannot rename the finished video to " + path_ + ": " + why);
    }
    temporary_.clear();
    removeTemporaries();
}

void FfmpegEncoder::abort() {
    if (pipe_ >= 0) ::close(pipe_);
    pipe_ = -1;
    if (pid_ > 0) {
        ::kill(pid_, SIGKILL);
        waitFor(pid_);
        pid_ = 0;
    }
    removeTemporaries();
    finished_ = true;
}

}  // namespace ll::ui
