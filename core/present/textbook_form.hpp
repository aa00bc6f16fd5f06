#pragma once
// How an item reads in a textbook, decided before it is built as a display tree
// (display_builder.hpp): a robot's entries with combined angles (c12), s_i² or c_i²
// eliminated whichever gives fewer terms, a common factor pulled out where there is one
// (the 2R's c12 = −m2 a1 ℓc2 s2 (q̇1 + q̇2)); terms grouped as the item's Grouping says
// (by the masses, the velocities or a typed Lagrangian's parameters); scene decimals
// shown as decimals; each equation of motion in B q̈ + C q̇ + g = Q order.
// Call with the GiNaC lock held.
#include <unordered_map>
#include <vector>

#include <ginac/ginac.h>

#include "core/present/angle_sums.hpp"
#include "core/symbolic/derivation.hpp"

namespace ll::present {

using symbolic::Grouping;

class TextbookForm {
public:
    explicit TextbookForm(const symbolic::Derivation& derivation);

    // value (a scalar or a matrix, entry by entry) as it reads, grouped as `grouping` says.
    GiNaC::ex operator()(const GiNaC::ex& value, Grouping grouping);

    // Row i of B q̈ + C q̇ + g = Q in that order: b_i1 q̈1 + … + (C q̇)_i + g_i, the velocity
    // part as one sum over the velocity products with its common factor out (the 2R's
    // −m2 a1 ℓc2 s2 (2 q̇1 q̇2 + q̇2²)).
    std::vector<GiNaC::ex> equationParts(int i);

    // How the system's items group unless they are velocity products: by the masses for
    // a robot, by the parameters for a typed Lagrangian.
    Grouping plainGrouping() const;

private:
    GiNaC::ex shorterInSines(const GiNaC::ex& value) const;
    std::vector<GiNaC::symbol> parameters() const;

    const symbolic::Derivation& d_;
    bool robot_;
    AngleSumCombiner combiner_;
    // Each value shaped once per grouping: B's entries are shaped for B and again in the
    // equations of motion.
    std::unordered_map<GiNaC::ex, GiNaC::ex, std::hash<GiNaC::ex>, GiNaC::ex_is_equal> shaped_[3];
};

// The expanded e collected by the monomials in `groupBy` (distributed, like GiNaC's
// collect): b11 with {m1, m2} → I1 + m1 lc1^2 + I2 + m2*(a1^2 + lc2^2 + 2*a1*lc2*c2),
// c_ij with the velocities → Σ_k (…) q̇_k. A common rational factor of a group moves
// in front (1/2*m1*(…)). Terms without a groupBy symbol stay single. Element-wise on a
// matrix. The result is meant for showing only: GiNaC keeps it unexpanded.
GiNaC::ex collectForDisplay(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& groupBy);

// The mass symbols (m, m1, m2, m_cart ...) in e, by index: the usual groupBy for B, g.
std::vector<GiNaC::symbol> massSymbols(const GiNaC::ex& e);

}  // namespace ll::present
