#pragma once
// Anti-aliasing after the fact, on the CPU, for software OpenGL. Mesa's llvmpipe draws
// a 4x multisampled frame about 3x slower than a plain one (PUMA 560 at 1280x720: 54
// against 20 ms), which puts a 10 s video beyond real time on two cores. This filter
// smooths the stair-steps of a plain frame in about 4 ms instead (1280x720).
//
// How it works (the idea of post-process anti-aliasing, written for this renderer):
//   1. Luma of every pixel. A pixel whose luma differs from its four neighbours by
//      less than a contrast threshold is left alone (flat areas: most of the frame).
//   2. At an edge pixel, the second differences across rows and across columns say
//      whether the edge runs horizontally or vertically; the neighbour across the edge
//      with the larger luma step is the partner.
//   3. Walking along the edge in both directions (up to 12 pixels) finds where the
//      stair-step ends. A pixel near the end of a step that leans towards the partner's
//      side gets more of the partner's colour (up to half), which turns the staircase
//      into a ramp, as coverage sampling would. Isolated pixels (thin lines, tips) get a
//      share from the local average instead.
// The result is written back into the frame; the buffers are kept between frames, so a
// video allocates nothing per frame.
#include <cstdint>
#include <vector>

#include <QImage>

namespace ll::ui {

class EdgeSmoothing {
public:
    // Smooths `frame` in place (any size; converted to Format_RGBX8888 if it is not).
    void apply(QImage& frame);

private:
    std::vector<std::uint8_t> luma_;
    std::vector<std::uint8_t> rows_;  // one row's brightest and darkest neighbour, and its edge marks
    std::vector<std::uint32_t> source_;
};

}  // namespace ll::ui
