#include "core/symbolic/latex_text.hpp"

namespace ll::symbolic {

std::string latexText(const std::string& text) {
    std::string out;
    for (char c : text) {
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
            case '-': out += "-{}"; break;  // "--form" stays two hyphens, not an en dash
            case '\\': out += "\\textbackslash{}"; break;
            case '<': out += "$<$"; break;
            case '>': out += "$>$"; break;
            default: out += c;
        }
    }
    return out;
}

}  // namespace ll::symbolic
