#pragma once
// The general formula of a derivation step (the notes' "B(q) q̈ + C q̇ + g = Q" under
// step 8) as data, written into words and letters only where it is shown
// (core/present/step_formula_text.hpp): once as plain text, once as LaTeX, each a list of
// pieces of three kinds —
//   - math, written the same in every language and notation ("E_kin = 1/2 sum_i");
//   - a letter a textbook names its own way: the mass matrix B (Spong's D, Craig's M), its
//     entries b, the gravity vector g (Craig's G), the generalized forces Q (τ), and a
//     robot's joint variables q (Craig's θ, the vector Θ), with their dots;
//   - words: a message id (core/model/messages/formula.def), its arguments formulas of
//     their own, put into the reader's language; and the actuation sentence.
// A formula is written in the derivation's source as one string per style with the
// letters marked (formulaPieces): "«g» = dE_pot/d«q»;  c_ij = sum_k … «q'_»k", the
// words as numbered inserts «1», «2».
#include <string>
#include <string_view>
#include <vector>

#include "core/model/message.hpp"

namespace ll {

enum class FormulaLetter : unsigned char {
    MassMatrix,     // «B»
    MassEntry,      // «b»
    Gravity,        // «g»
    Force,          // «Q»
    JointVector,    // «q» «q'» «q''»: the vector q of B(q), q̇, q̈
    JointVariable,  // «q_» «q'_» «q''_»: the letter of q_i, q̇_i, q̈_i (the index follows)
};

struct FormulaPiece;
using FormulaPieces = std::vector<FormulaPiece>;

struct FormulaPiece {
    enum class Kind : unsigned char { Math, Letter, Words, Actuation };
    Kind kind = Kind::Math;
    FormulaLetter letter = FormulaLetter::MassMatrix;  // Letter
    unsigned char dots = 0;                            // Letter: 1 velocity, 2 acceleration
    std::string math;                                  // Math
    MessageId words = MessageId::Literal;              // Words: its {1}, {2}, … are `args`
    std::vector<FormulaPieces> args;                   // Words
    std::vector<int> actuated;                         // Actuation: 0-based coordinates with an input
    std::vector<std::string> coordinates;              // Actuation: the coordinates' names
};

// The text is written as the entries beneath it are: dots and Greek letters as characters
// (q̇, θ, τ, Σ, ∂, ½), never in ASCII (qd, theta, sum, d^2); one alphabet per page.
struct StepFormula {
    FormulaPieces text, latex;
};

// The pieces of `source`: math, with the letters marked «B» «b» «g» «Q» «q» «q'» «q''»
// «q_» «q'_» «q''_» and «k» standing for inserts[k-1]. A mark it does not know throws
// std::logic_error (a mistake in the program's own formulas).
FormulaPieces formulaPieces(std::string_view source, std::vector<FormulaPiece> inserts = {});

// Math taken as it is, no marks read (a scene's own names and numbers).
FormulaPiece formulaMath(std::string math);

// Words: the id's words with {k} filled by formulaPieces(args[k-1]) …
FormulaPiece formulaWords(MessageId id, const std::vector<std::string>& args = {});
// … or by pieces already made.
FormulaPiece formulaWordsOf(MessageId id, std::vector<FormulaPieces> args);

// A step's formula from its text and its LaTeX, each with its own inserts.
StepFormula stepFormula(std::string_view text, std::string_view latex, std::vector<FormulaPiece> textInserts = {},
                        std::vector<FormulaPiece> latexInserts = {});

// "inputs on q1, q2 (fully actuated)" in the reader's language (core/model/actuation.hpp).
FormulaPiece formulaActuation(std::vector<int> actuated, std::vector<std::string> coordinates);

}  // namespace ll
