#include "core/symbolic/compiled_derivation.hpp"

#include <algorithm>

#include "core/model/argument_checks.hpp"

namespace ll::symbolic {
namespace {

// Only q, q̇ and t are left once the shorthand and the parameters are substituted.
GiNaC::ex numbersOnly(const Derivation& d, const GiNaC::ex& e) {
    return e.subs(d.trigToFunctions).subs(d.parameterValues);
}

}  // namespace

CompiledDerivation::CompiledDerivation(const Derivation& d) : n_(static_cast<int>(d.q.size())) {
    std::vector<GiNaC::symbol> inputs = d.q;
    inputs.insert(inputs.end(), d.qd.begin(), d.qd.end());
    inputs.push_back(d.t);
    const auto at = [&](const GiNaC::matrix& m, int r, int c) { return numbersOnly(d, m(r, c)); };

    // Right-hand side: B's upper triangle, rhs = Q − C q̇ − g, Q (shared with rhs).
    std::vector<GiNaC::ex> dynamics;
    for (int i = 0; i < n_; ++i)
        for (int j = i; j < n_; ++j) dynamics.push_back(at(d.B, i, j));
    for (int i = 0; i < n_; ++i) {
        GiNaC::ex rhs = at(d.Q, i, 0) - at(d.g, i, 0);
        for (int j = 0; j < n_; ++j) rhs -= at(d.C, i, j) * d.qd[j];
        dynamics.push_back(rhs);
    }
    for (int i = 0; i < n_; ++i) dynamics.push_back(at(d.Q, i, 0));
    dynamics_ = CompiledExpressions(dynamics, inputs);
    energies_ = CompiledExpressions({numbersOnly(d, d.Ekin), numbersOnly(d, d.Epot)}, inputs);

    // Every term, row by row: B, C, g, Q, E_kin, E_pot.
    std::vector<GiNaC::ex> all;
    for (int i = 0; i < n_; ++i)
        for (int j = 0; j < n_; ++j) all.push_back(at(d.B, i, j));
    for (int i = 0; i < n_; ++i)
        for (int j = 0; j < n_; ++j) all.push_back(at(d.C, i, j));
    for (int i = 0; i < n_; ++i) all.push_back(at(d.g, i, 0));
    for (int i = 0; i < n_; ++i) all.push_back(at(d.Q, i, 0));
    all.push_back(numbersOnly(d, d.Ekin));
    all.push_back(numbersOnly(d, d.Epot));
    terms_ = CompiledExpressions(all, inputs);

    input_.assign(2 * n_ + 1, 0.0);
    output_.assign(std::max(dynamics_.outputCount(), terms_.outputCount()), 0.0);
}

ModelTerms CompiledDerivation::terms(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t) const {
    requireSize("CompiledDerivation::terms", "q", q.size(), n_, "the system", "coordinates");
    requireSize("CompiledDerivation::terms", "qd", qd.size(), n_, "the system", "coordinates");
    for (int i = 0; i < n_; ++i) {
        input_[i] = q[i];
        input_[n_ + i] = qd[i];
    }
    input_[2 * n_] = t;
    terms_.evaluate(input_.data(), output_.data());
    ModelTerms m;
    m.B.resize(n_, n_);
    m.C.resize(n_, n_);
    m.g.resize(n_);
    m.Q.resize(n_);
    const double* out = output_.data();
    for (int i = 0; i < n_; ++i)
        for (int j = 0; j < n_; ++j) m.B(i, j) = *out++;
    for (int i = 0; i < n_; ++i)
        for (int j = 0; j < n_; ++j) m.C(i, j) = *out++;
    for (int i = 0; i < n_; ++i) m.g[i] = *out++;
    for (int i = 0; i < n_; ++i) m.Q[i] = *out++;
    m.Ekin = *out++;
    m.Epot = *out;
    return m;
}

void CompiledDerivation::dynamics(const double* x, double t, Eigen::MatrixXd& B, Eigen::VectorXd& rhs,
                                  Eigen::VectorXd& Q) const {
    std::copy(x, x + 2 * n_, input_.begin());
    input_[2 * n_] = t;
    dynamics_.evaluate(input_.data(), output_.data());
    const double* out = output_.data();
    for (int i = 0; i < n_; ++i)
        for (int j = i; j < n_; ++j) B(i, j) = B(j, i) = *out++;
    for (int i = 0; i < n_; ++i) rhs[i] = *out++;
    for (int i = 0; i < n_; ++i) Q[i] = *out++;
}

void CompiledDerivation::energies(const double* x, double& Ekin, double& Epot) const {
    std::copy(x, x + 2 * n_, input_.begin());
    input_[2 * n_] = 0.0;  // energies do not depend on t
    double out[2];
    energies_.evaluate(input_.data(), out);
    Ekin = out[0];
    Epot = out[1];
}

}  // namespace ll::symbolic
