#include "core/symbolic/compiled_derivation.hpp"

#include "core/symbolic/compiled_expressions.hpp"

#include "core/model/argument_checks.hpp"

namespace ll::symbolic {
namespace {

// Only q, q̇ and t are left once the shorthand and the parameters are substituted.
GiNaC::ex numbersOnly(const Derivation& d, const GiNaC::ex& e) { return e.subs(d.trigToFunctions).subs(d.parameterValues); }

}  // namespace

CompiledLagrangian compileDerivation(const Derivation& d) {
    const int n = static_cast<int>(d.q.size());
    std::vector<GiNaC::symbol> inputs = d.q;
    inputs.insert(inputs.end(), d.qd.begin(), d.qd.end());
    inputs.push_back(d.t);
    const auto at = [&](const GiNaC::matrix& m, int r, int c) { return numbersOnly(d, m(r, c)); };

    // Right-hand side: B's upper triangle, rhs = Q − C q̇ − g, Q (shared with rhs).
    std::vector<GiNaC::ex> dynamics;
    for (int i = 0; i < n; ++i)
        for (int j = i; j < n; ++j) dynamics.push_back(at(d.B, i, j));
    for (int i = 0; i < n; ++i) {
        GiNaC::ex rhs = at(d.Q, i, 0) - at(d.g, i, 0);
        for (int j = 0; j < n; ++j) rhs -= at(d.C, i, j) * d.qd[j];
        dynamics.push_back(rhs);
    }
    for (int i = 0; i < n; ++i) dynamics.push_back(at(d.Q, i, 0));

    // Every term, row by row: B, C, g, Q, E_kin, E_pot.
    std::vector<GiNaC::ex> all;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) all.push_back(at(d.B, i, j));
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) all.push_back(at(d.C, i, j));
    for (int i = 0; i < n; ++i) all.push_back(at(d.g, i, 0));
    for (int i = 0; i < n; ++i) all.push_back(at(d.Q, i, 0));
    all.push_back(numbersOnly(d, d.Ekin));
    all.push_back(numbersOnly(d, d.Epot));

    return CompiledLagrangian(n, compileExpressions(dynamics, inputs),
                              compileExpressions({numbersOnly(d, d.Ekin), numbersOnly(d, d.Epot)}, inputs),
                              compileExpressions(all, inputs));
}

}  // namespace ll::symbolic
