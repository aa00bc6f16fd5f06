#pragma once
// GiNaC expressions and matrices printed three ways, all rendered from one display tree
// (core/symbolic/display_builder, display_tree), in a deterministic order of terms
// and factors (GiNaC's own order is hash-based and can change between runs):
//   Plain  re-parsable by GiNaC's parser: I1+m2*(a1^2+2*a1*lc2*cos(q2)), 1/2*m1*qd1^2
//   Text   a terminal's textbook:         I1 + m2 (a1² + 2 a1 ℓc2 c2), 1/2 m1 q̇1²
//   Latex  I_{1} + m_{2} \left(a_{1}^{2} + 2 a_{1} \ell_{c2} c_{2}\right)
// Symbol names follow derivation.hpp. The printers never expand: group first with
// collectForDisplay, then print.
//
// Order of the terms of a sum (the key, compared in turn):
//   1. the indices of its velocity factors (none first; q̇1 before q̇1 q̇2 before q̇2),
//   2. the largest index of any other symbol (I1, m1 ℓc1² before I2),
//   3. without trigonometry before with it, 4. total degree, 5. the term's Plain
//   rendering without its coefficient, 6. the coefficient.
// Order of the factors of a product: number, constants (π), masses, other parameters,
// coordinates, c/s symbols, functions, parenthesised sums, velocities; within a group
// by index, then name (m2 a1 ℓc2 s2 q̇2).
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/symbolic/derivation.hpp"
#include "core/symbolic/display_builder.hpp"

namespace ll::symbolic {

enum class Style { Plain, Text, Latex };

struct PrintOptions {
    Style style = Style::Text;
    // The coordinates by index (q1..qn for robots; theta1, x for Lagrangian systems).
    // Empty: any q<i> is a coordinate and Plain writes c1 as cos(q1).
    std::vector<std::string> coordinateNames;
    // Whether c<i>, s<i>, c12, c9_10 mean cos/sin of coordinate sums (robots). Off for
    // Lagrangian systems, where c1 may be the user's damping coefficient.
    bool trigSymbols = true;
};

// The display tree's style that renders `style`.
DisplayStyle displayStyle(Style style);

// The display tree's options (coordinates, trig shorthand) of these print options.
DisplayOptions displayOptions(const PrintOptions& options);

// The options for printing a derivation's results in `style`.
PrintOptions printOptionsFor(const Derivation& derivation, Style style);

// A coordinate's name as Style::Text prints it, with `dots` dots over it (0: the
// coordinate, 1: its velocity, 2: its acceleration): q1, q̇1; theta1, θ̇1; x, ẍ.
std::string textCoordinateName(const std::string& name, int dots = 0);

// A scalar, or a GiNaC::matrix as printMatrix does it.
std::string print(const GiNaC::ex& e, const PrintOptions& options = {});

// Plain [[a,b],[c,d]]; Text rows between ⎡⎢⎣ ⎤⎥⎦ with aligned columns (several lines);
// Latex \begin{bmatrix} a & b \\ c & d \end{bmatrix}.
std::string printMatrix(const GiNaC::matrix& m, const PrintOptions& options = {});

// "lhs = rhs" (GiNaC's parser has no equations: in Plain each side parses alone). A
// matrix side in Text sets the two blocks side by side, " = " on the middle line.
std::string printEquation(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const PrintOptions& options = {});
// The left side given already in the style, e.g. a DerivationItem's name or latexName.
std::string printEquation(const std::string& lhs, const GiNaC::ex& rhs, const PrintOptions& options = {});

// The expanded e collected by the monomials in `groupBy` (distributed, like GiNaC's
// collect): b11 with {m1, m2} → I1 + m1 lc1^2 + I2 + m2*(a1^2 + lc2^2 + 2*a1*lc2*c2),
// c_ij with the velocities → Σ_k (…) q̇_k. A common rational factor of a group moves
// in front (1/2*m1*(…)). Terms without a groupBy symbol stay single. Element-wise on a
// matrix. The result is meant for printing only: GiNaC keeps it unexpanded.
GiNaC::ex collectForDisplay(const GiNaC::ex& e, const std::vector<GiNaC::symbol>& groupBy);

// The mass symbols (m, m1, m2, m_cart ...) in e, by index: the usual groupBy for B, g.
std::vector<GiNaC::symbol> massSymbols(const GiNaC::ex& e);

}  // namespace ll::symbolic
