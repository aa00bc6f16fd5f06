#pragma once
// A derivation as a student reads it in a terminal (Unicode): the title, the form when
// one was chosen, each step with its general formula, each item as label = value, and
// the actuation. A matrix wider than maxTextMatrixRow characters is listed entry by
// entry (b11 = …), which is what a reader can follow anyway. No GiNaC: any thread.
#include <string>
#include <vector>

#include "core/present/display_document.hpp"

namespace ll::present {

// Where an item (or one entry of its matrix) stands in the text: line `line` (0-based),
// columns [from, to) counted as a terminal shows them (a combining dot takes none).
// What the window's text view picks from a click.
struct TextSpan {
    int line = 0, from = 0, to = 0;
    int step = 0, item = 0;  // indices into the document's steps and the step's items
    int row = -1, col = -1;  // the entry of its matrix; −1: the item
};

// With `spans`, also where every item and matrix entry stands.
std::string textDocument(const DisplayDocument& document, std::vector<TextSpan>* spans = nullptr);

// One item as the text document prints it.
std::string itemText(const DisplayItem& item, Language language = Language::English);

}  // namespace ll::present
