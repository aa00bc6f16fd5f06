#pragma once
// The course notes' procedure (steps 0–8) for a robot given by its DH table:
//   0 DH table → 1 T_n^0(q) → 2 p_ci^0(q) → 3 ω_i^0, J_ω,i → 4 v_ci^0, J_v,ci →
//   5 I_li^0 = R_i I_li R_iᵀ → 6 E_pot → 7 E_kin = ½ q̇ᵀ B q̇ → 8 g, C (Christoffel), Q,
//   B q̈ + C q̇ + g = Q.
// Only the declared effects appear. Everything is exact (rationals, multiples of π).
#include <atomic>
#include <functional>
#include <string>

#include "core/model/cancellation.hpp"
#include "core/model/scene.hpp"
#include "core/symbolic/derivation.hpp"
#include "core/symbolic/symbolic_robot.hpp"

namespace ll::symbolic {

struct DerivationOptions {
    ParameterMode mode = ParameterMode::Parametric;
    int firstStep = 0;  // the steps to show; B, C, g and Q are always derived
    int lastStep = lastDerivationStep;
    // Called before each piece of work with the step (0..8) and what it is ("b_23",
    // "c_41"), on the deriving thread. Optional.
    std::function<void(int step, const std::string& what)> progress;
    // Checked between entries; when set, the derivation throws Cancelled. Optional.
    const std::atomic<bool>* cancel = nullptr;
};

// Takes the GiNaC lock for the derivation; the caller holds it too while it keeps or
// prints the returned Derivation (GiNaC objects: ginac_lock.hpp).
// Throws InputError naming "parameters.<name>" when, with parameters kept as symbols
// (ParameterMode::Parametric), a parameter is named like the derivation's trigonometric
// shorthand for this robot (c1, s2, c12, s9_10: cos q1, sin q2, ...).
Derivation deriveRobot(const Scene& scene, const DerivationOptions& options = {});

// The check above on its own (for the structured derivation).
void refuseShorthandParameterNames(const Scene& scene);

}  // namespace ll::symbolic
