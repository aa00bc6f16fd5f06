#pragma once
// What an answer key holds (core/pipeline/answer_check.hpp), shared by the files that build
// it (answer_key.cpp) and that explain a wrong answer (answer_feedback.cpp). GiNaC objects:
// used with the GiNaC lock held.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/model/scene.hpp"
#include "core/pipeline/answer_check.hpp"
#include "core/symbolic/answer_reader.hpp"
#include "core/symbolic/derivation.hpp"

namespace ll {

// LinkPart: the structured form's β_jk⁽ⁱ⁾ (k ≥ 0) and γ_j⁽ⁱ⁾ (k = −1), link i's part of b_jk
// and its gravity lever for joint j (core/symbolic/structured_dynamics.hpp).
enum class EntryKind { MassMatrix, Coriolis, Christoffel, Gravity, Force, KineticEnergy, PotentialEnergy, Equation, Item, LinkPart };

struct KeyEntry {
    std::string id;  // b11, c121, T_2^0(1,4)
    EntryKind kind = EntryKind::Item;
    int i = -1, j = -1, k = -1;  // 0-based indices (b_ij, c_ijk, g_i, a matrix item's row and column)
    std::string item;            // a derivation item's name (EntryKind::Item), as shown
    // sin and cos as functions of the coordinates; a Christoffel symbol's and a link part's
    // are made when first asked for (AnswerKey::Data::valueOf: a 6-joint robot has 216 and 77)
    mutable GiNaC::ex value;
    mutable bool ready = true;
    symbolic::Quantity quantity = symbolic::Quantity::NamedQuantity;  // EntryKind::Item: the item's quantity and index
    int index = -1;
};

// Units as powers of kg, m and s.
using Dimension = std::array<int, 3>;

struct LinkRoles {  // the symbols of one link's inertial parameters and its DH lengths
    std::vector<GiNaC::symbol> mass, inertia, com, lengths;
};

struct AnswerKey::Data {
    Scene scene;
    symbolic::ParameterMode mode = symbolic::ParameterMode::Parametric;
    symbolic::Derivation derivation;
    symbolic::AnswerVocabulary vocabulary;
    std::vector<KeyEntry> entries;
    std::vector<std::string> ids;
    std::map<std::string, std::size_t> byKey;  // normalized name → index into entries
    struct Whole {                             // a matrix or vector answered at once: B, g, p_c2, T_2^0
        std::string id;
        unsigned rows = 0, cols = 0;
        std::vector<std::size_t> entries;  // row by row, into entries
    };
    std::vector<Whole> wholes;
    std::map<std::string, std::size_t> wholeByKey;  // normalized name → index into wholes
    GiNaC::exmap toFunctions, toShorthand;          // c12 → cos(q1 + q2) and back
    GiNaC::exmap values;                            // every parameter symbol → its exact value
    std::vector<LinkRoles> links;                   // robots only
    std::vector<GiNaC::ex> masses;                  // robots: each link's mass, in the derivation's symbols
    GiNaC::matrix gravity{3, 1};                    // robots: g0 in the base frame, likewise
    std::map<std::string, Dimension> units;         // by symbol name; absent: not known
    // The same robot derived in the other DH convention, made when first needed.
    mutable std::optional<symbolic::Derivation> otherConvention;

    GiNaC::ex functions(const GiNaC::ex& e) const { return e.subs(toFunctions, GiNaC::subs_options::no_pattern); }
    const GiNaC::ex& valueOf(const KeyEntry& entry) const;
    // β_jk⁽ⁱ⁾ or γ_j⁽ⁱ⁾ (EntryKind::LinkPart) from this derivation's Jacobians and inertia
    // tensors (answer_link_parts.cpp).
    GiNaC::ex linkPart(const KeyEntry& entry) const;
    const GiNaC::ex* itemValue(const symbolic::Derivation& d, symbolic::Quantity quantity, int index) const;
    // The value of `entry` in another derivation of the same scene (the other convention).
    std::optional<GiNaC::ex> entryValue(const symbolic::Derivation& d, const KeyEntry& entry) const;
};

// An entry name as a student may type it, reduced to what identifies it (the keys of
// byKey and wholeByKey): T_2^0(1, 4), T2_0[1,4] and t20(1,4) are the same key.
std::string entryKey(const std::string& typed);

// The feedback on a wrong answer (the verdict is Wrong when this is called): hints, kinds
// and links filled in `check`. answer_feedback.cpp.
void explainWrongAnswer(const AnswerKey::Data& key, const KeyEntry& entry, const GiNaC::ex& answer, AnswerCheck& check);

// Christoffel symbol c_ijk = ½(∂b_ij/∂q_k + ∂b_ik/∂q_j − ∂b_jk/∂q_i), each term with its sign
// (+1, +1, −1 in the notes), B in function form.
GiNaC::ex christoffel(const GiNaC::matrix& B, const std::vector<GiNaC::symbol>& q, int i, int j, int k,
                      const std::array<int, 3>& signs = {1, 1, -1});

}  // namespace ll
