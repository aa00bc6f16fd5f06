#pragma once
// A derivation as a student reads it in a terminal (Unicode): the title, the form when
// one was chosen, each step with its general formula, each item as label = value, and
// the actuation. A matrix wider than maxTextMatrixRow characters is listed entry by
// entry (b11 = …), which is what a reader can follow anyway. No GiNaC: any thread.
#include <string>

#include "core/present/display_document.hpp"

namespace ll::present {

std::string textDocument(const DisplayDocument& document);

// One item as the text document prints it.
std::string itemText(const DisplayItem& item);

}  // namespace ll::present
