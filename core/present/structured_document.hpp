#pragma once
// The structured form of a robot's model as a document (text, LaTeX or JSON): the
// named quantities grouped under the step where each arises, B as sums of per-link
// contributions β_jk⁽ⁱ⁾ with the coordinates each b_jk depends on, g and C over the
// names, the zero pattern of ∂b_jk/∂q_l with its non-zero count, the Ḃ − 2C skew check,
// and any entries asked for (expanded on demand, with their term counts).
// Takes the GiNaC lock; call with it held while the StructuredDynamics lives.
#include <atomic>
#include <string>
#include <vector>

#include "core/present/display_document.hpp"
#include "core/symbolic/structured_entries.hpp"
#include "core/symbolic/structured_dynamics.hpp"

namespace ll::present {

using symbolic::EntryRef;
using symbolic::ExpandedEntry;
using symbolic::StructuredDynamics;

struct StructuredDocumentInfo {
    std::string modeName;                 // parameters, numeric, symbolic
    Message formReason;                   // why this form ("auto: 7 joints: ...")
    std::vector<EntryRef> entries;        // only these of B, C, g (empty: all)
    std::vector<ExpandedEntry> expanded;  // expanded entries to show
    // FormStructured, or FormExpanded when the entries asked for are shown expanded (the
    // names they need are listed too): what the document says its form is.
    Message form = MessageId::FormStructured;
    // --steps: only the names of these steps of the course notes (1 frames, 4 Jacobian
    // columns, 6 gamma, 7 beta, 8 derivatives); B needs step 7, C, g and the checks step 8.
    int firstStep = 0, lastStep = symbolic::lastDerivationStep;
    // the language of its words (language.hpp): headings, titles, the form and why, the
    // notes and checks, and JSON's form, form_reason and meaning; the names and sums are
    // the same in every language
    Language language = Language::English;
};

std::string structuredDocument(const StructuredDynamics& s, DocumentFormat format, const StructuredDocumentInfo& info);

}  // namespace ll::present
