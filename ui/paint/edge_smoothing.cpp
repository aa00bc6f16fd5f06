#include "ui/paint/edge_smoothing.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace ll::ui {
namespace {

constexpr int kSearch = 12;           // pixels walked along an edge each way
constexpr int kMinContrast = 20;      // luma steps (of 255) below which nothing is smoothed
constexpr int kRelativeContrast = 8;  // ... or below the brightest neighbour / 8

// Mixes `weight` / 256 of `other` into `self`, per 8-bit channel.
inline std::uint32_t mix(std::uint32_t self, std::uint32_t other, int weight) {
    std::uint32_t out = 0;
    for (int shift = 0; shift < 32; shift += 8) {
        const int a = int((self >> shift) & 0xff), b = int((other >> shift) & 0xff);
        out |= std::uint32_t(a + (((b - a) * weight) >> 8)) << shift;
    }
    return out;
}

// Marks the pixels of row `y` whose luma differs from its four neighbours' by at least
// the contrast threshold. Plain loops over bytes, so the compiler vectorises them
// (this file is built with -O3): this test rejects most of the frame.
void markEdges(const std::uint8_t* L, int w, int y, std::uint8_t* high, std::uint8_t* low, std::uint8_t* mark) {
    const std::uint8_t* c = L + std::size_t(y) * w;
    const std::uint8_t *n = c - w, *s = c + w;
    for (int x = 1; x < w - 1; ++x) {
        high[x] = std::max(std::max(std::max(c[x], n[x]), std::max(s[x], c[x - 1])), c[x + 1]);
        low[x] = std::min(std::min(std::min(c[x], n[x]), std::min(s[x], c[x - 1])), c[x + 1]);
    }
    for (int x = 1; x < w - 1; ++x) {
        const int threshold = std::max(kMinContrast, high[x] / kRelativeContrast);
        mark[x] = high[x] - low[x] >= threshold;
    }
}

}  // namespace

void EdgeSmoothing::apply(QImage& frame) {
    const int w = frame.width(), h = frame.height();
    if (w < 3 || h < 3) return;
    if (frame.format() != QImage::Format_RGBX8888) frame = frame.convertToFormat(QImage::Format_RGBX8888);
    const std::size_t n = std::size_t(w) * h;
    source_.resize(n);
    luma_.resize(n);
    rows_.resize(3 * std::size_t(w) + 8);
    for (int y = 0; y < h; ++y) std::memcpy(&source_[std::size_t(y) * w], frame.constScanLine(y), std::size_t(w) * 4);
    for (std::size_t i = 0; i < n; ++i) {  // bytes R, G, B, X: red in the low byte
        const std::uint32_t p = source_[i];
        luma_[i] = std::uint8_t(((p & 0xff) * 77 + ((p >> 8) & 0xff) * 150 + ((p >> 16) & 0xff) * 29) >> 8);
    }
    const std::uint8_t* L = luma_.data();
    std::uint8_t *high = rows_.data(), *low = high + w, *mark = low + w;
    for (int y = 1; y < h - 1; ++y) {
        auto* out = reinterpret_cast<std::uint32_t*>(frame.scanLine(y));
        markEdges(L, w, y, high, low, mark);
        for (int x = 1; x < w - 1; ++x) {
            if (!mark[x]) {
                if (x + 8 < w - 1) {  // skip eight flat pixels at a time
                    std::uint64_t eight = 0;
                    std::memcpy(&eight, mark + x, 8);
                    if (eight == 0) x += 7;
                }
                continue;
            }
            const std::size_t i = std::size_t(y) * w + x;
            const int c = L[i], north = L[i - w], south = L[i + w], west = L[i - 1], east = L[i + 1];
            const int range = high[x] - low[x];
            const int nw = L[i - w - 1], ne = L[i - w + 1], sw = L[i + w - 1], se = L[i + w + 1];

            // Across which direction does luma change most sharply? That is the edge's normal.
            const int acrossRows = 2 * std::abs(north + south - 2 * c) + std::abs(nw + sw - 2 * west) + std::abs(ne + se - 2 * east);
            const int acrossColumns = 2 * std::abs(west + east - 2 * c) + std::abs(nw + ne - 2 * north) + std::abs(sw + se - 2 * south);
            const bool horizontal = acrossRows >= acrossColumns;  // the edge runs along x
            const std::ptrdiff_t toPartner =
                horizontal ? (std::abs(north - c) >= std::abs(south - c) ? -w : w) : (std::abs(west - c) >= std::abs(east - c) ? -1 : 1);
            const std::ptrdiff_t along = horizontal ? 1 : w;
            const int partner = L[i + toPartner];
            const int middle = c + partner;                               // twice the luma halfway across the edge
            const int gradient = std::max(2, std::abs(partner - c) / 2);  // twice a quarter step

            // Walk along the edge both ways until the pair (this row, partner row) leaves it.
            const int room = horizontal ? std::min(kSearch, w - 1 - x) : std::min(kSearch, h - 1 - y);
            const int roomBack = horizontal ? std::min(kSearch, x) : std::min(kSearch, y);
            int forward = room + 1, backward = roomBack + 1, endForward = middle, endBackward = middle;
            for (int k = 1; k <= room; ++k) {
                const std::ptrdiff_t j = std::ptrdiff_t(i) + k * along;
                const int pair = L[j] + L[j + toPartner];
                if (std::abs(pair - middle) >= gradient) {
                    forward = k, endForward = pair;
                    break;
                }
            }
            for (int k = 1; k <= roomBack; ++k) {
                const std::ptrdiff_t j = std::ptrdiff_t(i) - k * along;
                const int pair = L[j] + L[j + toPartner];
                if (std::abs(pair - middle) >= gradient) {
                    backward = k, endBackward = pair;
                    break;
                }
            }
            // The nearer end: if there the edge crosses into this pixel's row (the pair
            // turns to the partner's side), this pixel is partly covered by the partner's
            // surface: the nearer the end, the more.
            const bool forwardNearer = forward < backward;
            const int endPair = forwardNearer ? endForward : endBackward;
            const int distance = std::min(forward, backward), span = forward + backward;
            int weight = 0;  // of 256
            if (endPair != middle && ((2 * c < middle) != (endPair < middle)))
                weight = std::max(0, 128 - 256 * distance / span + 128 / span);

            // Lone pixels (thin lines, sharp tips) have no long edge: blend by how far
            // the pixel stands out of its 3x3 neighbourhood.
            const int neighbourhood = (2 * (north + south + west + east) + nw + ne + sw + se);  // 12 × the weighted mean
            const int standOut = std::min(256, std::abs(neighbourhood - 12 * c) * 256 / (12 * range));
            const int smooth = (standOut * standOut >> 8) * (768 - 2 * standOut) >> 8;  // smoothstep, of 256
            weight = std::max(weight, (smooth * smooth >> 8) * 3 / 4);
            if (weight > 0) out[x] = mix(source_[i], source_[i + toPartner], std::min(weight, 128));
        }
    }
}

}  // namespace ll::ui
