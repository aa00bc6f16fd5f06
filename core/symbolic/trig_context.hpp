#pragma once
// Robot expressions as polynomials in c_i = cos q_i, s_i = sin q_i (revolute joints),
// q_i (prismatic joints), q̇_i and the parameters. Treating the trigonometric functions
// as symbols and reducing s_i² → 1 − c_i² after every stage keeps results canonical and
// short: expanding GiNaC's cos/sin naively makes a PUMA 560 C matrix reach ~170k terms.
// Derivatives follow the chain rule ∂/∂q_k = ∂/∂q_k|explicit + c_k ∂/∂s_k − s_k ∂/∂c_k.
#include <vector>

#include <ginac/ginac.h>

#include "core/symbolic/shared_symbol.hpp"

namespace ll::symbolic {

class TrigContext {
public:
    // One coordinate per joint; revolute[i] says whether q_i enters through c_i, s_i.
    explicit TrigContext(std::vector<bool> revolute);

    int size() const { return static_cast<int>(revolute_.size()); }
    bool revolute(int i) const { return revolute_[i]; }
    // (Shared symbols, core/symbolic/shared_symbol.hpp: using one allocates nothing.)
    const GiNaC::symbol& q(int i) const { return symbolOf(q_[i]); }
    const GiNaC::symbol& qd(int i) const { return symbolOf(qd_[i]); }
    const GiNaC::symbol& c(int i) const { return symbolOf(c_[i]); }
    const GiNaC::symbol& s(int i) const { return symbolOf(s_[i]); }
    const GiNaC::symbol& t() const { return symbolOf(t_); }
    std::vector<GiNaC::symbol> q() const { return symbols(q_); }
    std::vector<GiNaC::symbol> qd() const { return symbols(qd_); }

    // A constant DH angle (α_i or a θ offset: π/3, 3/10, a parameter symbol) whose sine
    // and cosine appear in the results: reduce() then also lowers sin(x)² to 1 − cos(x)².
    // Angles whose cosine GiNaC evaluates to a rational (0, ±π/2, π) are not needed.
    void addConstantAngle(const GiNaC::ex& angle);

    // Expanded, with every power of s_i reduced to degree < 2 by s_i² = 1 − c_i² (and
    // of sin x by sin² x = 1 − cos² x for the constant angles). The coefficients may be
    // anything: parameters, floats, sqrt(3), cos(alpha2).
    // The sine and cosine of a constant angle that is a number (3/10, 78/125, π/5: not a
    // parameter) are folded to floats first, so the expansion multiplies numbers, not
    // cos(3/10)ᵃ sin(3/10)ᵇ cos(78/125)ᶜ monomials (an 8-joint chain's b₁₁: 15,516 terms and
    // 45 s kept exact; a 3-joint arm with six such angles: minutes). sin² + cos² = 1 of a
    // folded angle then holds only to rounding: a float coefficient below 1e-12 of the
    // largest coefficient of the sum is that residue and is dropped.
    GiNaC::ex reduce(const GiNaC::ex& e) const;
    GiNaC::matrix reduce(const GiNaC::matrix& m) const;

    // ∂e/∂q_k by the chain rule (not reduced).
    GiNaC::ex diffq(const GiNaC::ex& e, int k) const;
    GiNaC::matrix diffq(const GiNaC::matrix& m, int k) const;

    // c_i == cos(q_i), s_i == sin(q_i), for evaluation and plain output.
    GiNaC::lst toFunctions() const;

private:
    GiNaC::ex reduceFolded(const GiNaC::ex& e) const;  // reduce() with folded angles
    std::vector<bool> revolute_;
    std::vector<std::pair<GiNaC::ex, GiNaC::ex>> constantAngles_;  // (sin x, cos x)
    GiNaC::exmap folded_;  // sin x, cos x → their floats, for the constant angles that are numbers
    std::vector<GiNaC::ex> q_, qd_, c_, s_;
    GiNaC::ex t_;
    static std::vector<GiNaC::symbol> symbols(const std::vector<GiNaC::ex>& shared);
};

// e (expanded) with every power x^k, k ≥ 2, written x^(k mod 2) (1 − y²)^(k div 2), expanded:
// the reduction by x² + y² = 1 for any coefficients (GiNaC's rem needs polynomials over the
// rationals, which a DH angle of 0.3, π/3 or α₂ is not).
GiNaC::ex reducePythagorean(const GiNaC::ex& e, const GiNaC::ex& x, const GiNaC::ex& y);

}  // namespace ll::symbolic
