#pragma once
// Step 9 (the control law, core/symbolic/control_law.hpp) for a robot derived in the
// structured form: τ_i and the closed loop written over step 8's entries b_jk, c_ij, g_i
// as their names, not their sums (the structured form never expands an entry unasked).
// The caller holds the GiNaC lock.
#include "core/model/scene.hpp"
#include "core/present/display_document.hpp"
#include "core/symbolic/structured_dynamics.hpp"

namespace ll::present {

// The step for a scene that declares a controller, in English and the notes' notation.
DisplayStep structuredControlStep(const Scene& scene, const symbolic::StructuredDynamics& s);

}  // namespace ll::present
