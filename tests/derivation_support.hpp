#pragma once
// Comparing the results of two symbolic derivations: each has its own c_i, s_i, q_i
// and q̇_i symbols, so their expressions are compared as functions of one set of q.
#include <ginac/ginac.h>

#include "core/symbolic/derivation.hpp"

namespace ll::test {

// `e`, a result of `from`, written in the coordinates and velocities of `to`.
inline GiNaC::ex inSymbolsOf(const symbolic::Derivation& from, const symbolic::Derivation& to, const GiNaC::ex& e) {
    GiNaC::lst same;
    for (std::size_t k = 0; k < from.q.size(); ++k) {
        same.append(from.q[k] == to.q[k]);
        same.append(from.qd[k] == to.qd[k]);
    }
    return e.subs(from.trigToFunctions).subs(same);
}

}  // namespace ll::test
