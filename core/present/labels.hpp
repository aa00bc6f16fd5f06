#pragma once
// The labels of a derivation's items and of their entries, decided from the quantity an
// item is: T_2^0 reads T_{2}^{0}, B reads B(q), the Lagrangian's ∂L/∂θ̇1 in the user's
// own names; a matrix listed entry by entry names them b11 (B), g2 (g), J_{v,c2,12}.
#include <cstddef>
#include <string>

#include "core/present/display_document.hpp"
#include "core/symbolic/derivation.hpp"

namespace ll::present {

// An item's name in LaTeX, as the notes write the quantity.
std::string itemLatexName(const symbolic::DerivationItem& item, const symbolic::Derivation& derivation);

// A label from an identifier and its LaTeX: Text prints `name`, LaTeX `latexName`, and
// the typesetter draws a symbol with the sub- and superscript read from the LaTeX (b with
// subscript 11, T with 2 and 0; a \frac, as the plain name).
DisplayPtr displayLabel(const std::string& name, const std::string& latexName);

// Entry (r, c) of a matrix item as text names it: b11 of B, g2 of g, Q1 of Q, T_2^0[1,4]
// of any other matrix (a column: T[2]).
std::string entryName(const DisplayItem& item, std::size_t r, std::size_t c);

// The same as the typeset pages draw it: b₁₁, Q₁, and the matrix's own label with the
// entry's indices added (J_{v,c6} → J_{v,c6,12}, an upright name: DH_{12}).
DisplayPtr entryLabel(const DisplayItem& item, std::size_t r, std::size_t c);

}  // namespace ll::present
