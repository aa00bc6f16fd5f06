#pragma once
// The structured form of a robot's model as a program: the named quantities in table
// order, then B(q), C(q, q̇), g(q) and the forward dynamics q̈ = B⁻¹(τ − C q̇ − g)
// (Cholesky), as SymPyBotics and ROBOTRAN ship it. C is C99 with only <math.h>;
// Python uses only the standard library (math). A header comment gives the scene's
// name, its DH table and the date. τ holds every non-conservative generalized force
// (torques, friction); gravity and springs are in g. Call with the GiNaC lock held.
#include <string>

#include "core/model/scene.hpp"
#include "core/symbolic/structured_dynamics.hpp"

namespace ll::symbolic {

enum class CodeLanguage { C, Python };

// `date`: the text written in the header ("2026-11-23").
std::string exportCode(const StructuredDynamics& s, const Scene& scene, CodeLanguage language, const std::string& date);

}  // namespace ll::symbolic
