#pragma once
// A derivation as it is shown: steps of items, each "label = value" as display trees.
// Plain data (no GiNaC), safe to hand to any thread. Every front end draws it: the text,
// LaTeX and JSON documents (text_document, latex_document, json_document), the typeset
// pages and the window's derivation view. Each item says which quantity it is
// (core/symbolic/derivation.hpp), so they decide layout from that, never from names.
#include <string>
#include <vector>

#include "core/model/message.hpp"
#include "core/model/step_formula.hpp"
#include "core/present/display_tree.hpp"
#include "core/present/language.hpp"
#include "core/present/notation.hpp"
#include "core/symbolic/derivation.hpp"

namespace ll::present {

using symbolic::Quantity;

// The documents a derivation is written as; Display is the trees alone.
enum class DocumentFormat { Text, Latex, Json, Display };

struct DisplayItem {
    std::string name;       // the identifier (JSON's "name"): b11, B, equation_1, beta1_1_2
    std::string latexName;  // b_{11}, B(q)
    Quantity quantity = Quantity::NamedQuantity;
    int row = -1, col = -1;   // 0-based: the item's link, joint or row (row), an entry's column (col)
    DisplayPtr equation;      // label = value (an equation of motion: B q̈ + C q̇ + g = Q)
    DisplayPtr value;         // the right side alone (for a matrix: the Matrix node)
    Message note;             // what it means (the structured form's names), in words where it is shown; may be empty
    std::string entryLetter;  // its entries' letter when a notation renames them (d of Spong's D); empty: the quantity's own
};

struct DisplayStep {
    int number = 0;
    Message title;        // in words where it is shown, in the document's language (message_text.hpp)
    StepFormula general;  // the general formula as data; the next three are it written (localized_document.hpp: writeFormula)
    std::string formulaText, formulaLatex;
    std::vector<DisplayItem> items;
    double seconds = 0.0;
    DisplayPtr formula;  // the general formula typeset (null: only formulaText)
};

struct DisplayDocument {
    std::string systemName;
    std::vector<std::string> coordinateNames;
    std::vector<DisplayStep> steps;
    // Step `number` (0..8), or null when this document has none (a typed Lagrangian's 1–5).
    const DisplayStep* step(int number) const {
        for (const DisplayStep& s : steps)
            if (s.number == number) return &s;
        return nullptr;
    }
    std::string actuation;       // "inputs on q1, q2 …", the coordinates as the results show them (θ2)
    std::string actuationLatex;  // the same with the coordinates as LaTeX ($\theta_{2}$)
    Message form;                // FormExpanded or FormStructured when a form was chosen (empty: not said)
    Message formReason;          // why that form
    // As localized_document.hpp wrote it: the language of its words, the notation of its
    // letters, and what that needs (which coordinates have inputs, a robot's coordinates
    // are q_i and renamed with the notation, its DH convention).
    Language language = Language::English;
    Notation notation = Notation::Notes;
    std::vector<int> actuated;
    bool actuationFromInputs = false;  // `actuation` is the sentence made from `actuated` (else a fixed text)
    Message actuationNote;  // the fixed text when not from the inputs (the structured form's); localizedDocument words it into `actuation`
    bool robot = false;
    bool modifiedDH = false;
    Message remark;  // said once about the notation (Craig's goes with modified DH); may be empty
};

}  // namespace ll::present
