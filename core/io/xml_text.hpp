#pragma once
// Text inside XML (an SVG page, Moodle's question format): & < > " as entities.
#include <string>

namespace ll {

void appendXmlEscaped(std::string& out, const std::string& text);
inline std::string xmlEscaped(const std::string& text) {
    std::string out;
    appendXmlEscaped(out, text);
    return out;
}

}  // namespace ll
