#include "core/present/text_document.hpp"

#include <algorithm>

#include "core/present/labels.hpp"
#include "core/present/message_text.hpp"

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

// Terminal columns of one line of text.
int columnsOf(const std::string& s) { return static_cast<int>(widestLine(s)); }

int lineCount(const std::string& s) { return 1 + static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

// The spans of an item printed as `text` from line `first`: each entry of a matrix
// printed as a block (its row's line, its column's cells), each entry listed on its own
// line, else the item's lines whole.
void itemSpans(const DisplayItem& item, const std::string& text, int first, int step, int index, std::vector<TextSpan>& out) {
    const int lines = lineCount(text);
    const DisplayNode& value = *item.value;
    if (value.kind == DisplayKind::Matrix && !value.rows.empty()) {
        const std::size_t rows = value.rows.size(), cols = value.rows[0].size();
        if (text.rfind(item.name + " (", 0) == 0) {  // listed entry by entry: one line each after the heading
            int line = first + 1;
            for (std::size_t r = 0; r < rows; ++r)
                for (std::size_t c = 0; c < cols; ++c)
                    if (!isZeroNumber(*value.rows[r][c])) {
                        const std::string entry =
                            "  " + entryName(item, r, c) + " = " + renderDisplay(*value.rows[r][c], DisplayStyle::Text);
                        out.push_back({line, 0, columnsOf(entry), step, index, static_cast<int>(r), static_cast<int>(c)});
                        line += lineCount(entry);
                    }
            return;
        }
        if (lines == static_cast<int>(rows) && item.equation->kind == DisplayKind::Equation) {
            // label = ⎡ cells ⎤, columns padded to their widest, two spaces apart
            std::vector<std::vector<std::string>> cell(rows, std::vector<std::string>(cols));
            std::vector<int> width(cols, 0);
            for (std::size_t r = 0; r < rows; ++r)
                for (std::size_t c = 0; c < cols; ++c) {
                    cell[r][c] = renderDisplay(*value.rows[r][c], DisplayStyle::Text);
                    width[c] = std::max(width[c], columnsOf(cell[r][c]));
                }
            const int left = columnsOf(renderDisplay(*item.equation->children[0], DisplayStyle::Text)) + columnsOf(item.equation->text) + 2;
            for (std::size_t r = 0; r < rows; ++r) {
                int from = left;
                for (std::size_t c = 0; c < cols; ++c) {
                    out.push_back(
                        {first + static_cast<int>(r), from, from + width[c], step, index, static_cast<int>(r), static_cast<int>(c)});
                    from += width[c] + 2;
                }
            }
            return;
        }
    }
    for (int l = 0; l < lines; ++l) out.push_back({first + l, 0, 1 << 20, step, index, -1, -1});
}

}  // namespace

std::string itemText(const DisplayItem& item, Language language) {
    // A block whose entry alone is wider than a row may be is listed entry by entry
    // without being written as a block first (the expanded Panda's C: megabytes).
    bool tooWide = false;
    if (item.value->kind == DisplayKind::Matrix)
        for (const auto& row : item.value->rows)
            for (const DisplayPtr& cell : row) tooWide = tooWide || textColumnsAtLeast(*cell, maxTextMatrixRow + 1) > maxTextMatrixRow;
    if (!tooWide) {
        std::string whole = renderDisplay(*item.equation, DisplayStyle::Text);
        if (item.value->kind != DisplayKind::Matrix || widestLine(whole) <= maxTextMatrixRow) return whole;
    }
    // Too wide to read as a block: the entries one by one, under the matrix's name.
    const auto& rows = item.value->rows;
    const bool zeros = hasZeroEntry(*item.value);  // left out, and said so
    std::string out = item.name + " (" + std::to_string(rows.size()) + "×" + std::to_string(rows.empty() ? 0 : rows[0].size()) + "), " +
                      messageText(MessageId::DocumentEntryByEntry, language) +
                      (zeros ? ", " + messageText(MessageId::DocumentZerosLeftOut, language) + ":" : ":");
    for (std::size_t r = 0; r < rows.size(); ++r)
        for (std::size_t c = 0; c < rows[r].size(); ++c)
            if (!isZeroNumber(*rows[r][c])) out += "\n  " + entryName(item, r, c) + " = " + renderDisplay(*rows[r][c], DisplayStyle::Text);
    return out;
}

std::string textDocument(const DisplayDocument& document, std::vector<TextSpan>* spans) {
    std::string out = document.systemName + "\n" + std::string(document.systemName.size(), '=') + "\n";
    const Language l = document.language;
    if (!document.form.empty())
        out += messageText(MessageId::DocumentForm, l) + ": " + messageText(document.form, l) + " (" + messageText(document.formReason, l) +
               ")\n";
    if (!document.remark.empty()) out += messageText(document.remark, l) + "\n";
    int line = lineCount(out) - 1;  // the line being written
    for (std::size_t s = 0; s < document.steps.size(); ++s) {
        const DisplayStep& step = document.steps[s];
        const std::string heading = "\n" + messageText(MessageId::DocumentStep, l) + " " + std::to_string(step.number) + ". " +
                                    messageText(step.title, l) + "\n    " + step.formulaText + "\n\n";
        out += heading;
        line += lineCount(heading) - 1;
        for (std::size_t i = 0; i < step.items.size(); ++i) {
            const std::string text = itemText(step.items[i], l);
            if (spans) itemSpans(step.items[i], text, line, static_cast<int>(s), static_cast<int>(i), *spans);
            out += text + "\n\n";
            line += lineCount(text) + 1;
        }
    }
    return out + messageText(MessageId::DocumentActuation, l) + ": " + document.actuation + "\n";
}

}  // namespace ll::present
