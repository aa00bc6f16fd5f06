#include "app/pixel_size.hpp"

#include <regex>

#include "app/cli_options.hpp"

namespace ll::cli {

PixelSize parsePixelSize(const std::string& text) {
    static const std::regex pattern("([0-9]{1,6})x([0-9]{1,6})");
    std::smatch m;
    if (!std::regex_match(text, m, pattern)) throw UsageError("--size " + text + ": expected WIDTHxHEIGHT in pixels, e.g. 1280x720");
    const PixelSize size{std::stoi(m[1]), std::stoi(m[2])};
    if (size.width == 0 || size.height == 0) throw UsageError("--size " + text + ": width and height must be at least 1 pixel");
    if (size.width > kMaxPixelSide || size.height > kMaxPixelSide)
        throw UsageError("--size " + text + ": at most " + std::to_string(kMaxPixelSide) + " pixels per side");
    return size;
}

}  // namespace ll::cli
