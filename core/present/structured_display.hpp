#pragma once
// The structured form (structured_dynamics.hpp) as a display document, for every front
// end that draws display trees (the PDF/SVG/PNG pages, the window's derivation view):
// the named quantities under the step where each arises, each as "name = its
// expression" in textbook notation (J_{P2,x}^{(4)}: x of J_P,2 of link 4 in its own
// frame; β_{23}^{(4)}, γ_2^{(4)}, ∂b_{23}/∂q_3, …) with its meaning beside it; then
// b_jk as the sum of its per-link contributions β, g_j and c_ij over the names, and
// the equations B q̈ + C q̇ + g = Q. Text and LaTeX render the same trees (so their
// leaves agree, tests/test_structured_display).
// Takes the GiNaC lock; call with it held while the StructuredDynamics lives.
#include <atomic>
#include <memory>
#include <string>

#include "core/present/display_document.hpp"
#include "core/symbolic/structured_dynamics.hpp"

namespace ll::present {

using symbolic::StructuredDynamics;

// Steps firstStep..lastStep of the structured form (names arise in steps 1, 4, 6, 7, 8;
// B's sums come with step 7, g, C and the equations with step 8).
// Throws Cancelled between items once `cancel` is set.
std::shared_ptr<const DisplayDocument> structuredDisplayDocument(const StructuredDynamics& s, const Message& formReason, int firstStep = 0,
                                                                 int lastStep = symbolic::lastDerivationStep, const std::atomic<bool>* cancel = nullptr);

// How a generated name reads: Jx2_4 → J_{P2,x}^{(4)}, beta2_3_4 → β_{23}^{(4)},
// Db2_3_3 → ∂b_{23}/∂q_3. A name of no known pattern reads as the display builder
// spells any symbol. Plain data, any thread.
DisplayPtr structuredNameNode(const std::string& name);

}  // namespace ll::present
