#pragma once
// Video through a pipe to the ffmpeg program: raw RGBX frames stream into its stdin
// (the pipe blocks, so memory does not grow with the duration), and the file appears
// under its name only when complete.
//   mp4   H.264 (libx264, veryfast, CRF 20), yuv420p, +faststart
//   webm  VP9 (libvpx-vp9, realtime, CRF 33), yuv420p
//   gif   a palette made from this video: ffmpeg writes a lossless FFV1 intermediate and
//         the palette statistics (palettegen, stats_mode=diff) in one pass, then maps
//         the frames onto that palette (paletteuse, Bayer dither)
// ffmpeg writes to a temporary name beside the target (".NAME.part-PID.EXT"), renamed
// by finish(). Destroying an unfinished encoder (an exception, Ctrl-C) kills ffmpeg,
// waits for it and removes every temporary file. ffmpeg runs in its own process group,
// so a Ctrl-C in the terminal reaches only us and we decide what is left behind.
#include <stdexcept>
#include <string>

#include <sys/types.h>

namespace ll::ui {

enum class VideoFormat { Mp4, Webm, Gif };

// ffmpeg is not on PATH: says so and what to do instead.
class FfmpegMissing : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class FfmpegEncoder {
public:
    // Starts ffmpeg for `path`. Throws FfmpegMissing, or std::runtime_error naming the path.
    FfmpegEncoder(const std::string& path, VideoFormat format, int width, int height, double fps);
    ~FfmpegEncoder();
    FfmpegEncoder(const FfmpegEncoder&) = delete;
    FfmpegEncoder& operator=(const FfmpegEncoder&) = delete;

    // One frame: width × height × 4 bytes (R, G, B, X), top row first. Blocks while
    // ffmpeg is busy. Throws std::runtime_error with ffmpeg's message if it stopped.
    void write(const unsigned char* rgbx);
    // Ends the stream, waits for ffmpeg (and the GIF palette pass) and renames the
    // temporary file to `path`. Throws std::runtime_error if ffmpeg failed.
    void finish();
    // Kills ffmpeg (if running), waits for it and removes the temporary files.
    void abort();

    // True when an executable `ffmpeg` is on PATH.
    static bool available();
    // ffmpeg's pid while it runs (0 otherwise), for tests and diagnostics.
    pid_t pid() const { return pid_; }

private:
    std::string path_, temporary_, intermediate_, palette_, log_;
    VideoFormat format_;
    std::size_t frameBytes_;
    pid_t pid_ = 0;
    int pipe_ = -1;
    bool finished_ = false;

    std::string logTail() const;
    void removeTemporaries();
};

}  // namespace ll::ui
