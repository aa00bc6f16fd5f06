#pragma once
// A derivation with the entries a student is to answer hidden: the value of each entry
// asked (b11, g2, E_kin, a cell of T_2^0) replaced by "?" in every rendering (text, LaTeX,
// the typeset view), decided from the items' quantities and indices, never their names.
// What the window's exercise mode shows (ui/window/exercise_mode.hpp).
#include <vector>

#include "core/present/display_document.hpp"

namespace ll::present {

// Where an entry stands: the item of `quantity` (and `index`, its link or row, when ≥ 0)
// and, in a matrix or vector, the cell (row, col); row < 0: the whole item. The matrices
// of the dynamics match the structured form's single entries too (MassMatrix (0,1) is
// its b12 item); a hidden b_ij hides b_ji too (B is symmetric).
struct EntryPlace {
    int step = -1;  // the derivation's step (0..8); −1: not shown in it (a Christoffel symbol)
    Quantity quantity = Quantity::NamedQuantity;
    int index = -1;
    int row = -1, col = -1;
};

DisplayDocument withAnswersHidden(const DisplayDocument& document, const std::vector<EntryPlace>& hidden);

// The placeholder shown where an answer is hidden.
DisplayPtr hiddenAnswer();

}  // namespace ll::present
