#pragma once
// The DH link transform A_i(q_i) over the derivation's trigonometric symbols, and the
// inverse of a homogeneous transform, shared by the expanded and the structured
// derivations. Call with the GiNaC lock held.
#include <ginac/ginac.h>

#include "core/model/dh_row.hpp"
#include "core/symbolic/symbolic_robot.hpp"
#include "core/symbolic/trig_context.hpp"

namespace ll::symbolic {

// A_i with q_i added to θ (revolute: cos(θ+q) = cos θ c − sin θ s) or to d (prismatic).
GiNaC::matrix linkTransform(DhConvention convention, const SymbolicJoint& joint, const TrigContext& tc, int i);

// [Rᵀ, −Rᵀ t; 0, 1] of T = [R, t; 0, 1] (not reduced).
GiNaC::matrix inverseTransform(const GiNaC::matrix& T);

}  // namespace ll::symbolic
