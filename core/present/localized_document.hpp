#pragma once
// A derivation as shown in one language and one textbook's notation (language.hpp,
// notation.hpp), made from the document as derived (English, the notes' notation) by
// relabelling: the mass matrix, gravity vector and generalized forces named with the
// notation's letters (items and entries: D, d12; M(Θ), G, τ), a robot's joint variables
// renamed in every tree (q̇1 → θ̇1 for Craig), every step's general formula written with
// those letters and in the language (step_formula_text.hpp), the actuation sentence too. The step titles,
// the form and the remark stay messages, put into words in the document's language where
// they are shown (message_text.hpp). Plain data in and out, no GiNaC: the window switches
// language or notation without deriving again, and the text, LaTeX, JSON and typeset
// pages all read the result.
#include <memory>

#include "core/present/display_document.hpp"
#include "core/present/step_formula_text.hpp"

namespace ll::present {

struct Presentation {
    Language language = Language::English;
    Notation notation = Notation::Notes;
};

// `document` (as derived) shown with `presentation`.
std::shared_ptr<DisplayDocument> localizedDocument(const DisplayDocument& document, const Presentation& presentation);

// The step's general formula written for `reader` (its text, LaTeX and typeset tree); a
// robot's step 7 typesets the notes' sum for B beside it, Craig's step 8 his V(Θ, Θ̇).
void writeFormula(DisplayStep& step, const FormulaReader& reader);

// The notes' sum for the mass matrix, as step 7's formula adds it for a robot, in the
// notation's letters: ,\quad B(q) = \sum_i (m_i J_{P,i}^T J_{P,i} + …).
std::string massMatrixSum(const NotationSymbols& n);

// "inputs on θ2 (underactuated: m = 1 < n = 2)" in `language`, the coordinates as given.
std::string actuationSentence(const std::vector<int>& actuated, const std::vector<std::string>& coordinates, Language language);

}  // namespace ll::present
