#pragma once
// The result of a symbolic derivation, as the textbook procedure prints it: named
// steps, each with its general formula and this system's results, and the final
// B(q), C(q, q̇), g(q), Q of B q̈ + C q̇ + g = Q. Plain data over GiNaC expressions;
// printing (text, LaTeX, plain expressions) is core/symbolic/expression_printer.
//
// Symbol names (what the printers and the plain `expr` syntax see):
//   coordinates   q1..qn (robots) or the user's names (Lagrangian systems)
//   velocities    qd1..qdn, or <name>_dot for the user's names
//   trigonometry  c1..cn, s1..sn stand for cos q_i, sin q_i (robots only); after
//                 angle-sum combination c12 = cos(q1 + q2), s23 = sin(q2 + q3); with
//                 an index of 10 or more the indices are joined by '_' (c9_10)
//   parameters    their scene names; in textbook-symbol mode a1, d1, m1, xc1, yc1,
//                 zc1 (COM in frame i), Ixx1, Iyy1, Izz1, Ixy1, Ixz1, Iyz1
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace ll::symbolic {

struct DerivationItem {
    std::string name;       // plain: "T_2^0", "p_c1", "b11", "E_kin"
    std::string latexName;  // "T_{2}^{0}", "p_{c1}", "b_{11}", "E_{\\mathrm{kin}}"
    GiNaC::ex value;        // a scalar or a GiNaC::matrix
};

struct DerivationStep {
    int number = 0;            // 0..8 as in the course notes
    std::string title;         // "Kinematic model"
    std::string formulaText;   // the general formula of the step, plain text
    std::string formulaLatex;  // the same in LaTeX
    std::vector<DerivationItem> items;
    double seconds = 0.0;      // time it took
};

struct Derivation {
    std::string systemName;
    std::vector<GiNaC::symbol> q, qd, qdd;  // coordinates, velocities, accelerations
    GiNaC::symbol t{"t"};                    // time, in external torques
    std::vector<std::string> coordinateNames;  // as the user wrote them (q1.. for robots)
    std::vector<DerivationStep> steps;
    GiNaC::matrix B, C;                // n×n
    GiNaC::matrix g, Q;                // n×1
    GiNaC::ex Ekin, Epot;
    std::vector<int> actuated;         // 0-based coordinates with an input
    bool underactuated = false;
    // Substitutions that turn a result into an expression of q, q̇ and the parameter
    // values only: c_i → cos(q_i), s_i → sin(q_i), c12 → cos(q1+q2) ..., and each
    // parameter symbol → its number (empty in numeric mode, where none are left).
    GiNaC::lst trigToFunctions;
    GiNaC::lst parameterValues;
    std::vector<std::string> warnings;
};

}  // namespace ll::symbolic
