#pragma once
// `--size WxH` in pixels, as `render` and the window's `--screenshot` take it: both
// sides 1..8192, nothing around the numbers. A bad value is a UsageError naming the
// option and the value (exit 2), never a window or frame buffer of any size asked for.
#include <string>

namespace ll::cli {

struct PixelSize {
    int width = 0;
    int height = 0;
};

inline constexpr int kMaxPixelSide = 8192;

PixelSize parsePixelSize(const std::string& text);

}  // namespace ll::cli
