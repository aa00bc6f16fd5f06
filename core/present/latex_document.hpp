#pragma once
// A derivation as a complete LaTeX document (amsmath, A4 landscape): the title, the form
// when one was chosen, each step as a section with its general formula, each item as a
// display equation, and the actuation. No GiNaC: any thread.
#include <string>

#include "core/present/display_document.hpp"

namespace ll::present {

std::string latexDocument(const DisplayDocument& document);

// One item's equation in LaTeX: b_{11} = …
std::string itemLatex(const DisplayItem& item);

}  // namespace ll::present
