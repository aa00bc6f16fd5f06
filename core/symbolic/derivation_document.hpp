#pragma once
// How a derivation reads, decided once for every front end (the CLI's `derive`, the
// window's derivation view, the PDF/SVG/PNG typesetter): combined angles (c12), s_i² or
// c_i² eliminated whichever is shorter, entries grouped by masses (by velocities for C,
// ω, v_c and E_kin; by the parameters for a hand-typed Lagrangian), a common factor
// pulled out where there is one (the 2R's c12 = −m2 a1 ℓc2 s2 (q̇1 + q̇2)), scene
// decimals shown as decimals, and each equation in B q̈ + C q̇ + g = Q order.
// displayDocument builds that once as display trees (plain data); the formats render it:
//   Text   the steps as a student reads them in a terminal (Unicode); a matrix wider
//          than maxTextMatrixRow characters is listed entry by entry (b11 = …)
//   Latex  a complete LaTeX document
//   Json   every step's items with name, latex, text and a re-parsable plain `expr`,
//          plus top-level B, C, g, Q, Ekin, Epot, the actuation and warnings.
// Takes the GiNaC lock; the caller must hold it too while it owns the Derivation.
#include <atomic>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "core/symbolic/derivation.hpp"
#include "core/symbolic/display_tree.hpp"

namespace ll::symbolic {

// Display: no string document, only the display trees (DisplayDocument).
enum class DocumentFormat { Text, Latex, Json, Display };

struct DisplayItem {
    std::string name;       // b11, B, equation_1
    std::string latexName;  // b_{11}, B(q)
    DisplayPtr equation;    // name = value (an equation item: B q̈ + C q̇ + g = Q)
    DisplayPtr value;       // the right side alone (for a matrix: the Matrix node)
    std::string note;       // what it means, in words (the structured form's names); may be empty
};

struct DisplayStep {
    int number = 0;
    std::string title, formulaText, formulaLatex;
    std::vector<DisplayItem> items;
    double seconds = 0.0;
    DisplayPtr formula;  // the general formula typeset (null: only formulaText)
};

struct DisplayDocument {
    std::string systemName;
    std::vector<std::string> coordinateNames;
    std::vector<DisplayStep> steps;
    std::string actuation;  // "q1, q2 actuated" …
    std::string form;       // "expanded" or "structured" when a form was chosen (empty: not said)
    std::string formReason; // why that form
};

// The derivation's displayed form (takes the GiNaC lock). Throws Cancelled between items
// once `cancel` is set. forPages: long sums built already cut as pages show them
// (DisplayOptions::cutLongSums).
std::shared_ptr<const DisplayDocument> displayDocument(const Derivation& derivation, const std::atomic<bool>* cancel = nullptr,
                                                       bool forPages = false);

// A document in Text or Latex from its display trees (no GiNaC: any thread).
std::string renderDocument(const DisplayDocument& document, DocumentFormat format);

// An item's Text rendering as the text document prints it.
std::string itemText(const DisplayItem& item);

// modeName ("parameters", "numeric", "symbolic") is recorded in the JSON. Display gives "".
std::string derivationDocument(const Derivation& derivation, DocumentFormat format, const std::string& modeName);

}  // namespace ll::symbolic
