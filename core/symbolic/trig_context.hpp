#pragma once
// Robot expressions as polynomials in c_i = cos q_i, s_i = sin q_i (revolute joints),
// q_i (prismatic joints), q̇_i and the parameters. Treating the trigonometric functions
// as symbols and reducing s_i² → 1 − c_i² after every stage keeps results canonical and
// short: expanding GiNaC's cos/sin naively makes a PUMA 560 C matrix reach ~170k terms.
// Derivatives follow the chain rule ∂/∂q_k = ∂/∂q_k|explicit + c_k ∂/∂s_k − s_k ∂/∂c_k.
#include <vector>

#include <ginac/ginac.h>

namespace ll::symbolic {

class TrigContext {
public:
    // One coordinate per joint; revolute[i] says whether q_i enters through c_i, s_i.
    explicit TrigContext(std::vector<bool> revolute);

    int size() const { return static_cast<int>(revolute_.size()); }
    bool revolute(int i) const { return revolute_[i]; }
    const GiNaC::symbol& q(int i) const { return q_[i]; }
    const GiNaC::symbol& qd(int i) const { return qd_[i]; }
    const GiNaC::symbol& c(int i) const { return c_[i]; }
    const GiNaC::symbol& s(int i) const { return s_[i]; }
    const GiNaC::symbol& t() const { return t_; }
    const std::vector<GiNaC::symbol>& q() const { return q_; }
    const std::vector<GiNaC::symbol>& qd() const { return qd_; }

    // Expanded, with every power of s_i reduced to degree < 2 by s_i² = 1 − c_i².
    GiNaC::ex reduce(const GiNaC::ex& e) const;
    GiNaC::matrix reduce(const GiNaC::matrix& m) const;

    // ∂e/∂q_k by the chain rule (not reduced).
    GiNaC::ex diffq(const GiNaC::ex& e, int k) const;
    GiNaC::matrix diffq(const GiNaC::matrix& m, int k) const;

    // c_i == cos(q_i), s_i == sin(q_i), for evaluation and plain output.
    GiNaC::lst toFunctions() const;

private:
    std::vector<bool> revolute_;
    std::vector<GiNaC::symbol> q_, qd_, c_, s_;
    GiNaC::symbol t_;
};

}  // namespace ll::symbolic
