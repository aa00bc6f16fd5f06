#include "core/present/latex_text.hpp"

namespace ll::present {

std::string latexText(const std::string& text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        switch (c) {
            case '_': out += "\\_"; break;
            case '^': out += "\\^{}"; break;
            case '&': out += "\\&"; break;
            case '%': out += "\\%"; break;
            case '$': out += "\\$"; break;
            case '#': out += "\\#"; break;
            case '{': out += "\\{"; break;
            case '}': out += "\\}"; break;
            case '~': out += "\\textasciitilde{}"; break;
            case '-':  // "--form" stays two hyphens, not an en dash; "mass-spring" stays as typed
                out += i + 1 < text.size() && text[i + 1] == '-' ? "-{}" : "-";
                break;
            case '\\': out += "\\textbackslash{}"; break;
            case '<': out += "$<$"; break;
            case '>': out += "$>$"; break;
            default: out += c;
        }
    }
    return out;
}

}  // namespace ll::present
