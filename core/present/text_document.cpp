#include "core/present/text_document.hpp"

#include <algorithm>

#include "core/present/labels.hpp"

namespace ll::present {
namespace {

// Text columns of the longest line (combining dots take none).
std::size_t widestLine(const std::string& s) {
    std::size_t widest = 0, n = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const unsigned char b = static_cast<unsigned char>(s[i]);
        if (b == '\n') {
            widest = std::max(widest, n);
            n = 0;
        } else if ((b & 0xC0) != 0x80 && !(b == 0xCC || (b == 0xCD && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) < 0xB0))) {
            ++n;
        }
    }
    return std::max(widest, n);
}

// A lower bound of the columns a node takes in Text, counted no further than `limit`:
// every symbol or number at least one column, " + " between terms, a space between
// factors, parentheses around a fence.
std::size_t textColumnsAtLeast(const DisplayNode& n, std::size_t limit) {
    std::size_t count = 0;
    auto add = [&](std::size_t k) { count = std::min(limit, count + k); };
    switch (n.kind) {
        case DisplayKind::Sum:
        case DisplayKind::Product:
            for (std::size_t i = 0; i < n.children.size() && count < limit; ++i)
                add(textColumnsAtLeast(*n.children[i], limit - count) + (i ? (n.kind == DisplayKind::Sum ? 3 : 1) : 0));
            return count;
        case DisplayKind::Fence: return std::min(limit, textColumnsAtLeast(*n.children[0], limit) + 2);
        default: return 1;
    }
}

}  // namespace

std::string itemText(const DisplayItem& item) {
    // A block whose entry alone is wider than a row may be is listed entry by entry
    // without being written as a block first (the expanded Panda's C: megabytes).
    bool tooWide = false;
    if (item.value->kind == DisplayKind::Matrix)
        for (const auto& row : item.value->rows)
            for (const DisplayPtr& cell : row)
                tooWide = tooWide || textColumnsAtLeast(*cell, maxTextMatrixRow + 1) > maxTextMatrixRow;
    if (!tooWide) {
        std::string whole = renderDisplay(*item.equation, DisplayStyle::Text);
        if (item.value->kind != DisplayKind::Matrix || widestLine(whole) <= maxTextMatrixRow) return whole;
    }
    // Too wide to read as a block: the entries one by one, under the matrix's name.
    const auto& rows = item.value->rows;
    const bool zeros = hasZeroEntry(*item.value);  // left out, and said so
    std::string out = item.name + " (" + std::to_string(rows.size()) + "×" + std::to_string(rows.empty() ? 0 : rows[0].size()) +
                      "), entry by entry" + (zeros ? ", the zeros left out:" : ":");
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t c = 0; c < rows[r].size(); ++c)
            if (!isZeroNumber(*rows[r][c])) out += "\n  " + entryName(item, r, c) + " = " + renderDisplay(*rows[r][c], DisplayStyle::Text);
    return out;
}

std::string textDocument(const DisplayDocument& document) {
    std::string out = document.systemName + "\n" + std::string(document.systemName.size(), '=') + "\n";
    if (!document.form.empty()) out += "Form: " + document.form + " (" + document.formReason + ")\n";
    for (const DisplayStep& step : document.steps) {
        out += "\nStep " + std::to_string(step.number) + ". " + step.title + "\n    " + step.formulaText + "\n\n";
        for (const DisplayItem& item : step.items) out += itemText(item) + "\n\n";
    }
    return out + "Actuation: " + document.actuation + "\n";
}

}  // namespace ll::present
