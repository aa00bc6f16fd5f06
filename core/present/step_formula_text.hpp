#pragma once
// A step's general formula (core/model/step_formula.hpp) written for a reader: its
// letters in the notation's (B → D or M, g → G, Q → τ, a robot's q → θ and Θ), its words
// in the reader's language, as plain text or as LaTeX. The derivation's documents, the
// typeset pages and the window show what these write, so no formula is rewritten after
// it is written.
#include <string>

#include "core/model/step_formula.hpp"
#include "core/present/language.hpp"
#include "core/present/notation.hpp"

namespace ll::present {

struct FormulaReader {
    Language language = Language::English;
    Notation notation = Notation::Notes;
    bool robot = false;  // a robot's joint variables take the notation's letter; a typed Lagrangian's keep theirs
};

std::string formulaText(const StepFormula& formula, const FormulaReader& reader);
std::string formulaLatex(const StepFormula& formula, const FormulaReader& reader);

}  // namespace ll::present
