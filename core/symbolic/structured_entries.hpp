#pragma once
// Single entries of the structured form's B, C and g (structured_dynamics.hpp): named as
// a user types them (--entry B11,C23,g4), fully expanded on demand, and the check that
// Ḃ − 2C is skew-symmetric over the names. Call with the GiNaC lock held while the
// StructuredDynamics lives (expandEntry takes it itself).
#include <atomic>
#include <string>

#include "core/symbolic/structured_dynamics.hpp"

namespace ll::symbolic {

// One entry of B, C or g: "B11", "C23", "g4" (indices joined by '_' when one has two
// digits: "B1_10"). 0-based row/col; col is 0 for g.
struct EntryRef {
    char matrix = 'B';
    int row = 0, col = 0;
    std::string label;  // as written
};

// Throws MessageError (core/model/message_error.hpp) with a one-line reason for anything
// else or an index outside 1..n.
EntryRef parseEntry(const std::string& text, int n);

struct ExpandedEntry {
    EntryRef ref;
    GiNaC::ex value;  // in c_i, s_i, q_i, q̇_i and parameters
    std::size_t terms = 0;
    double seconds = 0;
};

// The entry fully expanded: b_jk and g_j by unfolding their names (memoised in the
// table), C_ij from the expanded rows i and j of B by the chain rule (never by
// unfolding the named ∂b). Cancellable between names.
ExpandedEntry expandEntry(StructuredDynamics& s, const EntryRef& ref, const std::atomic<bool>* cancel = nullptr);

// The label of entry (r, c) of 'B', 'C' or 'g' (0-based): B11, g4, B1_10 (indices joined
// by '_' when n ≥ 10).
std::string entryLabel(char matrix, int r, int c, int n);

// Whether Ḃ − 2C, from the structured C and Ḃ = Σ_l ∂B/∂q_l q̇_l over the same names,
// is skew-symmetric as an identity in the names (it is by construction; checked).
bool skewSymmetric(const StructuredDynamics& s);

}  // namespace ll::symbolic
