#pragma once
// How a symbol's name reads, and what it says the symbol is (the naming rules of
// core/symbolic/derivation.hpp): theta1 → θ1 (\theta_{1}), lc2 → ℓc2 (\ell_{c2}),
// Ixx1 → I_{xx,1}, xc1 → x_{c1}, m_cart → m_{\mathrm{cart}}, qd1 → q̇1, theta1_dot → θ̇1,
// c12 → c12 (Plain: cos(q1+q2)). No GiNaC: plain strings in, display nodes out.
#include <map>
#include <string>
#include <vector>

#include "core/present/display_tree.hpp"

namespace ll::present {

// What a name says a symbol is; the order of factors follows it (term_order.hpp).
enum class SymbolRole { Mass, Parameter, Coordinate, Trig, Velocity };

struct SymbolMeaning {
    SymbolRole role = SymbolRole::Parameter;
    // A c/s symbol's angle indices (c12: 1, 2); a coordinate's or velocity's position
    // among the coordinates (1-based); else the name's trailing number (m2: 2); empty: none.
    std::vector<int> indices;
    std::string base;     // a velocity's coordinate (theta1 for theta1_dot, q1 for qd1)
    char trigKind = 0;    // 'c' or 's' for a Trig symbol
    bool second = false;  // an acceleration (qdd1, theta1_ddot)
};

// The coordinates by index (q1..qn for robots; theta1, x for a typed Lagrangian) and
// whether c<i>, s<i>, c12 are the cos/sin shorthand of coordinate sums (robots only:
// in a Lagrangian c1 may be the user's damping coefficient).
struct NameRules {
    std::vector<std::string> coordinateNames;  // empty: any q<i> is a coordinate
    bool trigSymbols = true;
    std::map<std::string, int> links;  // a link's inertial parameters: name → link (0-based)
};

SymbolMeaning symbolMeaning(const std::string& name, const NameRules& rules);

// The node of a symbol: a Symbol node with base, subscript and dots; a c/s symbol's Plain
// is the function it stands for (cos(q1+q2), in the coordinates' names).
DisplayPtr symbolNode(const std::string& name, const SymbolMeaning& meaning, const NameRules& rules);

// A name (no c/s shorthand) as a symbol node with `dots` dots over it: theta1 → θ1,
// with 1 dot θ̇1.
DisplayPtr displaySymbolName(const std::string& name, int dots = 0);

// A LaTeX head or subscript as the typesetter draws it: \theta → θ, \ell → ℓ,
// \mathrm{cart} → cart (and *upright set when it held \mathrm).
std::string shownFromLatex(const std::string& latex, bool* upright = nullptr);

// For \mathrm{} and \operatorname{}: what LaTeX would read as markup escaped; the
// caret, tilde and backslash left out (scene names are identifiers anyway).
std::string latexEscape(const std::string& s);

}  // namespace ll::present
