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

#include "core/symbolic/derivation_document.hpp"
#include "core/symbolic/structured_dynamics.hpp"

namespace ll::symbolic {

// One entry of B, C or g: "B11", "C23", "g4" (indices joined by '_' when one has two
// digits: "B1_10"). 0-based row/col; col is 0 for g.
struct EntryRef {
    char matrix = 'B';
    int row = 0, col = 0;
    std::string label;  // as written
};

// Throws std::invalid_argument with a one-line reason for anything else or an index
// outside 1..n.
EntryRef parseEntry(const std::string& text, int n);

struct ExpandedEntry {
    EntryRef ref;
    GiNaC::ex value;     // in c_i, s_i, q_i, q̇_i and parameters
    std::size_t terms = 0;
    double seconds = 0;
};

// The entry fully expanded: b_jk and g_j by unfolding their names (memoised in the
// table), C_ij from the expanded rows i and j of B by the chain rule (never by
// unfolding the named ∂b). Cancellable between names.
ExpandedEntry expandEntry(StructuredDynamics& s, const EntryRef& ref, const std::atomic<bool>* cancel = nullptr);

struct StructuredDocumentInfo {
    std::string modeName;                 // parameters, numeric, symbolic
    std::string formReason;               // why this form ("7 joints: ...")
    std::vector<EntryRef> entries;        // only these of B, C, g (empty: all)
    std::vector<ExpandedEntry> expanded;  // expanded entries to show
    // "structured", or "expanded" when the entries asked for are shown expanded (the
    // names they need are listed too): what the document says its form is.
    std::string form = "structured";
    // --steps: only the names of these steps of the course notes (1 frames, 4 Jacobian
    // columns, 6 gamma, 7 beta, 8 derivatives); B needs step 7, C, g and the checks step 8.
    int firstStep = 0, lastStep = 8;
};

std::string structuredDocument(const StructuredDynamics& s, DocumentFormat format, const StructuredDocumentInfo& info);

// Whether Ḃ − 2C, from the structured C and Ḃ = Σ_l ∂B/∂q_l q̇_l over the same names,
// is skew-symmetric as an identity in the names (it is by construction; checked).
bool skewSymmetric(const StructuredDynamics& s);

}  // namespace ll::symbolic
