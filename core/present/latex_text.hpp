#pragma once
// Plain words (a scene's name, a step's title, a note) in LaTeX's text mode: _ ^ & % $ #
// { } ~ \ < > escaped, and "--" kept two hyphens ("--form" is not an en dash). A student's
// "my_robot #2" would otherwise stop pdflatex at the title.
#include <string>

namespace ll::present {

std::string latexText(const std::string& text);

}  // namespace ll::present
