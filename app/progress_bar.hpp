#pragma once
// A progress bar on stderr for long commands (simulate, render), drawn only on a
// terminal, redrawn at most every percent and erased when done.
#include <cstdio>

namespace ll::cli {

class ProgressBar {
public:
    explicit ProgressBar(bool enabled) : enabled_(enabled) {}
    ~ProgressBar() {
        if (enabled_ && drawn_) std::fprintf(stderr, "\r%*s\r", 60, "");
    }
    void operator()(double fraction) {
        const int percent = static_cast<int>(fraction * 100);
        if (!enabled_ || percent == last_) return;
        last_ = percent;
        drawn_ = true;
        const int width = 40, filled = percent * width / 100;
        std::fprintf(stderr, "\r[%.*s%*s] %3d%%", filled, "########################################", width - filled, "", percent);
        std::fflush(stderr);
    }

private:
    bool enabled_;
    bool drawn_ = false;
    int last_ = -1;
};

}  // namespace ll::cli
