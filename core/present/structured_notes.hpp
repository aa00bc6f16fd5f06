#pragma once
// The words beside a structured name or entry, as text, the JSON and the typeset pages
// show them ("links 4–7; depends on q2, q3") and as LaTeX ("links 4--7; depends on
// $q_{2}, q_{3}$"): one spelling for the structured printers and the display document,
// as messages put into words in the document's language (message_text.hpp; LaTeX's
// with latexMessageText, the math kept as it is).
#include <cstdint>
#include <string>

#include "core/model/message.hpp"

namespace ll::present::notes {

enum class Style { Text, Latex };

// The coordinates of a bit set, q1 first (bit k is q_{k+1}); "none" when empty.
inline Message coordinateList(std::uint64_t bits, int n, Style style = Style::Text) {
    std::string out;
    for (int k = 0; k < n; ++k)
        if (bits & (std::uint64_t(1) << k)) {
            out += out.empty() ? (style == Style::Latex ? "$q_{" : "q") : (style == Style::Latex ? ", q_{" : ", q");
            out += std::to_string(k + 1);
            if (style == Style::Latex) out += '}';
        }
    if (out.empty()) return MessageId::NoteNoCoordinates;
    return literal(style == Style::Latex ? out + "$" : out);
}

// Links first..last, counted from 0 and written from 1: "link 7" alone, "links 4–7" (an
// en dash; LaTeX's --) for a range.
inline Message linkRange(int first, int last, Style style = Style::Text) {
    if (first == last) return message(MessageId::NoteLink, first + 1);
    return message(MessageId::NoteLinks, std::to_string(first + 1) + (style == Style::Latex ? "--" : "–") + std::to_string(last + 1));
}

}  // namespace ll::present::notes
