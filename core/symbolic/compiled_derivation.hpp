#pragma once
// A Derivation's B, C, g, Q, E_kin and E_pot compiled once into a CompiledLagrangian
// (core/dynamics): fast numbers at any state with no GiNaC left. The trigonometric
// shorthand (trigToFunctions) and the parameter values are substituted before
// compiling, so the inputs are q, q̇ and t only. Call with the GiNaC lock held.
#include "core/dynamics/compiled_lagrangian.hpp"
#include "core/symbolic/derivation.hpp"

namespace ll::symbolic {

CompiledLagrangian compileDerivation(const Derivation& derivation);

}  // namespace ll::symbolic
