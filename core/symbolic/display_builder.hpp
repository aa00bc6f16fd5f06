#pragma once
// GiNaC → display tree (core/symbolic/display_tree.hpp): the one place that decides how
// an expression reads. Order of the terms of a sum (the key, compared in turn):
//   1. the indices of its velocity factors (none first; q̇1 before q̇1 q̇2 before q̇2),
//   2. the largest index of any other symbol (I1, m1 ℓc1² before I2),
//   3. without trigonometry before with it, 4. total degree, 5. the term's Plain
//   rendering without its coefficient, 6. the coefficient.
// Order of the factors of a product: number, constants (π), masses, other parameters,
// coordinates, c/s symbols, functions, parenthesised sums, velocities; within a group
// by index, then name (m2 a1 ℓc2 s2 q̇2).
// Names: theta1 → θ1 (\theta_{1}), lc2 → ℓc2, Ixx1 → I_{xx,1}, qd1 → q̇1, theta1_dot → θ̇1,
// c12 → c12 (Plain: cos(q1+q2)), m_cart → m_{\mathrm{cart}}.
// Must be called with the GiNaC lock held (core/symbolic/ginac_lock.hpp); the tree it
// returns is plain data.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/symbolic/display_tree.hpp"

namespace ll::symbolic {

struct DisplayOptions {
    // The coordinates by index (q1..qn for robots; theta1, x for Lagrangian systems).
    // Empty: any q<i> is a coordinate and Plain writes c1 as cos(q1).
    std::vector<std::string> coordinateNames;
    // Whether c<i>, s<i>, c12, c9_10 mean cos/sin of coordinate sums (robots). Off for
    // Lagrangian systems, where c1 may be the user's damping coefficient.
    bool trigSymbols = true;
    // Symbols drawn as given (the structured form's named quantities: Jx2_4 as
    // J_{P2,x}^{(4)}), by GiNaC name; any other symbol as above.
    std::shared_ptr<const std::map<std::string, DisplayPtr>> givenSymbols;
    // Only for pages: a sum of more than maxTypesetTerms terms is built already cut as
    // the typesetter cuts it (its first keptTypesetTerms terms in display order and
    // "⋯ (N more terms)"). Every term is still ordered; the others are never built, which
    // for the expanded Panda's C and equations is most of them.
    bool cutLongSums = false;
};

// A scalar, a GiNaC::matrix (Matrix node) or a relational (Equation node). Never expands.
DisplayPtr buildDisplay(const GiNaC::ex& e, const DisplayOptions& options);

// Builds many expressions with the same options, sharing the caches of sort keys and
// of subexpressions that repeat (the same sum in several entries of C).
class DisplayBuilder {
public:
    // Everything: sums that repeat across expressions (the expanded C). Symbols: only
    // the symbols' and numbers' nodes and keys; each expression's own caches are freed
    // after it (many short expressions over the same names: the structured form).
    enum class Sharing { Everything, Symbols };
    explicit DisplayBuilder(const DisplayOptions& options, Sharing sharing = Sharing::Everything);
    ~DisplayBuilder();
    DisplayBuilder(const DisplayBuilder&) = delete;
    DisplayBuilder& operator=(const DisplayBuilder&) = delete;
    DisplayPtr operator()(const GiNaC::ex& e);
    // e as (*this)(readableNumbers(e)) shows it, without rebuilding e when only its
    // coefficients change (core/symbolic/readable_numbers.hpp). Such a sum is never
    // taken from the cache: GiNaC's equality has 9/16 == 0.5625, so the same sum built
    // exact before would come back with its fractions.
    DisplayPtr readable(const GiNaC::ex& e);

private:
    struct Impl;
    Impl* impl_;
};

// The name of a derivation item (b11, T_2^0, p_c1, E_kin, w_2, dL/dtheta1_dot) as a
// node: Text prints `name`, LaTeX `latexName`, and the typesetter draws a symbol with
// sub- and superscript read from `name` (b with subscript 11, T with 2 and 0).
DisplayPtr displayLabel(const std::string& name, const std::string& latexName, const DisplayOptions& options);

// A name (no c/s shorthand) as a symbol node with `dots` dots over it: theta1 → θ1,
// with 1 dot θ̇1. Needs no GiNaC (any thread).
DisplayPtr displaySymbolName(const std::string& name, int dots = 0);

// Terms a + b − c joined in the given order; each part a Sum (its signs kept) or a term.
DisplayPtr displaySumOf(const std::vector<DisplayPtr>& parts);

}  // namespace ll::symbolic
