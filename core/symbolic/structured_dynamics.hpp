#pragma once
// B(q), C(q, q̇) and g(q) of a DH robot as short sums over a table of named link
// quantities (named_definitions.hpp), the structured form that scales to 10+ joints:
//
//   b_jk = Σ_{i ≥ max(j,k)} β_jk⁽ⁱ⁾,  β_jk⁽ⁱ⁾ = m_i J_P,j⁽ⁱ⁾·J_P,k⁽ⁱ⁾ + z_jᵀ I_i z_k   (+ armature on b_jj)
//   g_j  = −Σ_{i ≥ j} m_i g₀ᵀ J_P,j⁽ⁱ⁾  (+ K_j (q_j − q_j,rest) for a spring)
//   c_ijk = ½(∂b_ij/∂q_k + ∂b_ik/∂q_j − ∂b_jk/∂q_i),   C_ij = Σ_k c_ijk q̇_k
//
// Every vector of link i is written in link i's own frame, where its inertia tensor
// and centre of mass are constant: frame f's axes and origin there depend only on
// q_{f+1..i}, so β_jk⁽ⁱ⁾ never mentions q_1..q_min(j,k) and b_jk depends on
// q_{min(j,k)+1..n} only, structurally. ∂b_jk/∂q_l comes from the Jacobian identities
// (∂J_P,j/∂q_l = z_l × J_P,j for l < j, z_j × J_P,l for j ≤ l ≤ i; ∂z_j/∂q_l = z_l × z_j;
// ∂I_i⁰/∂q_l = [z_l]× I_i⁰ − I_i⁰ [z_l]×), without differentiating polynomials, and
// ∂b_jk/∂q_l = 0 for l ≤ min(j,k) is used, not rediscovered. Here z_j is the axis of
// joint j+1 (0-based j) and J_P,j = z_j for a prismatic joint.
//
// Standard and modified DH, revolute and prismatic joints, full inertia tensors, any
// DH angle, all three parameter modes.
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/model/scene.hpp"
#include "core/symbolic/named_definitions.hpp"
#include "core/symbolic/robot_derivation.hpp"

namespace ll::symbolic {

struct StructuredDynamics {
    std::string systemName;
    DhConvention convention = DhConvention::Standard;
    int n = 0;
    std::shared_ptr<TrigContext> trig;        // the q_i, q̇_i, c_i, s_i symbols
    std::shared_ptr<NamedDefinitions> table;  // the names, in dependency order
    GiNaC::matrix B, C, g, Q;                 // over the names (Q: declared non-conservative forces)
    // The energies over the names: E_kin = ½ q̇ᵀ B q̇ (B's entries as their sums of β),
    // E_pot = −Σ_i m_i g0ᵀ p_ci + the springs' ½ k (q − q₀)², each link's g0ᵀ p_ci written in
    // its own frame as g0^(i) · (p_ci − o_0) (the gravity and frame-0 origin names).
    GiNaC::ex Ekin, Epot;
    // beta[j][k]: the per-link contributions β_jk⁽ⁱ⁾ for i = max(j,k)..n−1 (j ≤ k), names or 0;
    // armature[j]: the motor's Jm G² added to b_jj (0 without one).
    std::vector<std::vector<std::vector<GiNaC::ex>>> beta;
    std::vector<GiNaC::ex> armature;
    // dB[l](j, k) = ∂b_jk/∂q_l over the names (symmetric; zero where it vanishes).
    std::vector<GiNaC::matrix> dB;
    std::vector<GiNaC::symbol> qdd;
    GiNaC::lst parameterValues;              // parameter symbol == value
    GiNaC::lst trigToFunctions;              // c_i == cos(q_i), s_i == sin(q_i)
    double seconds = 0.0;                    // time of the derivation
    std::map<std::string, int> symbolLinks;  // one link's inertial parameters: name → link
    // Which coordinates b_jk depends on (bit l: q_{l+1}), as the names say.
    std::uint64_t coordinatesOfB(int j, int k) const { return table->coordinatesOf(B(j, k)); }
    // How many ∂b_jk/∂q_l with j ≤ k are non-zero.
    int nonZeroMassDerivatives() const;
};

// Throws InputError as deriveRobot does, Cancelled when options.cancel is set between
// names (nothing is kept). Takes the GiNaC lock; hold it while using the result.
StructuredDynamics deriveStructured(const Scene& scene, const DerivationOptions& options = {});

// The values every input of the structured form needs at a state (q_i, c_i, s_i, q̇_i,
// the parameters), for DefinitionValues.
GiNaC::lst structuredInputs(const StructuredDynamics& s, const std::vector<double>& q, const std::vector<double>& qd);

}  // namespace ll::symbolic
