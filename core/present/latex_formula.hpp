#pragma once
// A step's general formula (the course notes' LaTeX: T_i^0 = A_1 A_2 \cdots A_i,
// \frac{\partial E_{\mathrm{pot}}}{\partial q}, \sum_{j \le i}, \begin{bmatrix} …) as a
// display tree the typesetter draws as math. The small subset of LaTeX the derivation
// writes: letters (italic), digits, _ and ^, \frac and \tfrac, \left( \right), \mathrm,
// \text, \dot and \ddot, Greek letters, \ell, \partial, \sum, \cdots, \le, \times,
// \cdot, spaces (\, \; \ \quad), bmatrix; anything else is drawn as its characters.
//
// The result is a Raw node: Text and LaTeX render `text` and `latex` as given; its
// children are the formula's parts (split at top-level \quad), each a Raw row whose
// children the typesetter sets side by side. Plain data, no GiNaC (any thread).
#include <string>

#include "core/present/display_tree.hpp"

namespace ll::present {

DisplayPtr formulaFromLatex(const std::string& latex, const std::string& text);

}  // namespace ll::present
