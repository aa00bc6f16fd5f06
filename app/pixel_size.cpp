#include "app/pixel_size.hpp"

#include <regex>

#include "app/cli_options.hpp"

namespace ll::cli {

PixelSize parsePixelSize(const std::string& text) {
    static const std::regex pattern("([0-9]{1,6})x([0-9]{1,6})");
    std::smatch m;
    if (!std::regex_match(text, m, pattern)) throw UsageError(UsageId::SizeExpected, text);
    const PixelSize size{std::stoi(m[1]), std::stoi(m[2])};
    if (size.width == 0 || size.height == 0) throw UsageError(UsageId::SizeZero, text);
    if (size.width > kMaxPixelSide || size.height > kMaxPixelSide) throw UsageError(UsageId::SizeTooLarge, text, kMaxPixelSide);
    return size;
}

}  // namespace ll::cli
