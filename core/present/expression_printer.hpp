#pragma once
// A GiNaC expression or matrix printed as a string, one call: built as a display tree
// (display_builder.hpp) and rendered in one style (display_tree.hpp):
//   Plain  re-parsable by GiNaC's parser: I1+m2*(a1^2+2*a1*lc2*cos(q2)), 1/2*m1*qd1^2
//   Text   a terminal's textbook:         I1 + m2 (a1² + 2 a1 ℓc2 c2), 1/2 m1 q̇1²
//   Latex  I_{1} + m_{2} \left(a_{1}^{2} + 2 a_{1} \ell_{c2} c_{2}\right)
// Never expands or regroups: shape first (textbook_form.hpp), then print. Call with the
// GiNaC lock held.
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/present/display_builder.hpp"
#include "core/symbolic/derivation.hpp"

namespace ll::present {

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
PrintOptions printOptionsFor(const symbolic::Derivation& derivation, Style style);

// A coordinate's name as Style::Text prints it, with `dots` dots over it (0: the
// coordinate, 1: its velocity, 2: its acceleration): q1, q̇1; theta1, θ̇1; x, ẍ.
std::string textCoordinateName(const std::string& name, int dots = 0);

// A scalar, or a GiNaC::matrix: Plain [[a,b],[c,d]]; Text rows between ⎡⎢⎣ ⎤⎥⎦ with
// aligned columns (several lines); Latex \begin{bmatrix} a & b \\ c & d \end{bmatrix}.
std::string print(const GiNaC::ex& e, const PrintOptions& options = {});

// "lhs = rhs" (GiNaC's parser has no equations: in Plain each side parses alone). A
// matrix side in Text sets the two blocks side by side, " = " on the middle line.
std::string printEquation(const GiNaC::ex& lhs, const GiNaC::ex& rhs, const PrintOptions& options = {});
// The left side given already in the style.
std::string printEquation(const std::string& lhs, const GiNaC::ex& rhs, const PrintOptions& options = {});

}  // namespace ll::present
