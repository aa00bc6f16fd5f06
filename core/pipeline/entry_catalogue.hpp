#pragma once
// The entries a derivation shows, each one a student can pick in the window (b_jk, c_ij,
// g_j, E_kin, E_pot, a structured β_jk⁽ⁱ⁾ or J_P,j⁽ⁱ⁾, a link's p_ci, ω_i, v_ci, I_li⁰, a
// typed Lagrangian's terms): traced to what feeds it — the links whose inertial
// parameters occur in it, the joints whose coordinates it depends on, the joint
// velocities in it — and evaluable at any state without GiNaC, from one compiled tape.
// Built with the derivation, under the GiNaC lock, from the items the display document
// shows (so its step and item numbers are the document's); plain data after that, for
// the window's picking, its value readout and its plot of an entry over a run.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/dynamics/link_contributions.hpp"
#include "core/math/expression_tape.hpp"
#include "core/model/scene.hpp"
#include "core/present/display_document.hpp"
#include "core/symbolic/derivation.hpp"
#include "core/symbolic/structured_dynamics.hpp"

namespace ll {

struct CatalogueEntry {
    std::string id;     // what `--select` names: b12, c21, g2, E_kin, beta2_3_4, p_c2, dL/dtheta1
    std::string label;  // as text shows it: b12, β23(4), p_c2, dL/dtheta1
    present::Quantity quantity = present::Quantity::NamedQuantity;
    int step = 0, item = 0;         // indices of its step and item in the display document
    bool cell = false;              // one entry (row, col) of its item's matrix (the expanded B);
                                    // false: the item itself (the structured form's b_jk, p_c2)
    int row = -1, col = -1;         // its indices in B, C, g or Q (b_jk: j−1, k−1; g_j: j−1, 0); −1: none
    int first = 0;                  // its values: the tape's outputs first … first + rows·cols − 1,
    int rows = 1, cols = 1;         // row by row
    int link = -1;                  // the link (0-based) it is a quantity of (p_ci, β_jk⁽ⁱ⁾); −1: none
    std::vector<int> links;         // the links whose inertial parameters occur in it, ascending
    bool perLink = false;           // a sum over the links (b, c, g, E_kin, E_pot): its shares by link
                                    // come from core/dynamics/link_contributions
    std::uint64_t coordinates = 0;  // bit k: it depends on q_{k+1}
    std::uint64_t velocities = 0;   // bit k: q̇_{k+1} occurs in it (the velocities that multiply a c_ij)
    std::string unit;               // SI; "" when dimensionless, mixed or not known (a typed Lagrangian's)

    bool dependsOn(int coordinate) const { return (coordinates >> coordinate) & 1u; }
    bool hasVelocity(int coordinate) const { return (velocities >> coordinate) & 1u; }
};

class EntryCatalogue {
public:
    int n = 0;  // coordinates
    std::vector<CatalogueEntry> entries;
    ExpressionTape values;  // inputs [q; q̇; t] (2n + 1); every entry's values

    // By id as typed: exactly, else ignoring '_' and case (beta23_4 for beta2_3_4); null
    // when there is none or it is ambiguous.
    const CatalogueEntry* find(const std::string& id) const;
    // The entry shown at item `item` of step `step` (indices into the document): its
    // cell (row, col) when the item's entries are listed, else the item's own; null: none.
    const CatalogueEntry* at(int step, int item, int row = -1, int col = -1) const;
    // The entry (row, col) of B, C, g or Q (either form: MassMatrix and MassMatrixEntry
    // alike), or E_kin, E_pot (row −1): what a matrix shown elsewhere (the teach pose's
    // B(q)) picks. Null: none.
    const CatalogueEntry* ofQuantity(present::Quantity quantity, int row = -1, int col = -1) const;
    // The entries the link (0-based) feeds.
    std::vector<const CatalogueEntry*> fedBy(int link) const;

    // Every entry's values at one state, into out (values.outputCount() doubles).
    void evaluate(const double* q, const double* qd, double t, std::vector<double>& out) const;
};

// Link `link`'s part of the per-link sum `entry` is (b_jk, c_ij, g_j, E_kin, E_pot) at the
// state `contributions` was last evaluated at; 0 for any other entry.
double linkPart(const CatalogueEntry& entry, const LinkContributions& contributions, int link);

// Take the GiNaC lock themselves; `shown` is the display document built from the same
// derivation. Throw std::invalid_argument when an entry's expression does not compile.
std::shared_ptr<EntryCatalogue> expandedCatalogue(const Scene& scene, const symbolic::Derivation& derivation,
                                                  const present::DisplayDocument& shown);
std::shared_ptr<EntryCatalogue> structuredCatalogue(const Scene& scene, const symbolic::StructuredDynamics& structured,
                                                    const present::DisplayDocument& shown);

}  // namespace ll
