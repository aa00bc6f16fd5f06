#pragma once
// The words beside a structured name or entry, as text, the JSON and the typeset pages
// show them ("links 4–7; depends on q2, q3") and as LaTeX ("links 4--7; depends on
// $q_{2}, q_{3}$"): one spelling for the structured printers and the display document.
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

namespace ll::symbolic::notes {

enum class Style { Text, Latex };

// The coordinates of a bit set, q1 first (bit k is q_{k+1}); "none" when empty.
inline std::string coordinateList(std::uint64_t bits, int n, Style style = Style::Text) {
    std::string out;
    for (int k = 0; k < n; ++k)
        if (bits & (std::uint64_t(1) << k)) {
            out += out.empty() ? (style == Style::Latex ? "$q_{" : "q") : (style == Style::Latex ? ", q_{" : ", q");
            out += std::to_string(k + 1);
            if (style == Style::Latex) out += '}';
        }
    if (out.empty()) return "none";
    return style == Style::Latex ? out + "$" : out;
}

// Indices side by side as the textbook writes them (b23), or with commas once one has
// two digits (b7,10; β_{7,10}): the labels' and the notes' one rule.
inline std::string joined(const std::vector<std::string>& indices) {
    bool wide = false;
    for (const std::string& i : indices) wide = wide || i.size() > 1;
    std::string out;
    for (const std::string& i : indices) {
        if (wide && !out.empty()) out += ',';
        out += i;
    }
    return out;
}

// The same for indices counted from 0, written from 1.
inline std::string indexList(std::initializer_list<int> zeroBased) {
    std::vector<std::string> indices;
    for (int i : zeroBased) indices.push_back(std::to_string(i + 1));
    return joined(indices);
}

// Links first..last, counted from 0 and written from 1: "link 7" alone, "links 4–7" (an
// en dash; LaTeX's --) for a range.
inline std::string linkRange(int first, int last, Style style = Style::Text) {
    if (first == last) return "link " + std::to_string(first + 1);
    return "links " + std::to_string(first + 1) + (style == Style::Latex ? "--" : "–") + std::to_string(last + 1);
}

}  // namespace ll::symbolic::notes
