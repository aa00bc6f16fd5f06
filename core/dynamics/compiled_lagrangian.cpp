#include "core/dynamics/compiled_lagrangian.hpp"

#include "core/model/argument_checks.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace ll {

CompiledLagrangian::CompiledLagrangian(int n, ExpressionTape dynamics, ExpressionTape energies, ExpressionTape terms)
    : n_(n), dynamics_(std::move(dynamics)), energies_(std::move(energies)), terms_(std::move(terms)) {
    const int inputs = 2 * n + 1;
    if (n < 0 || dynamics_.inputCount() != inputs || energies_.inputCount() != inputs || terms_.inputCount() != inputs ||
        dynamics_.outputCount() != n * (n + 1) / 2 + 2 * n || energies_.outputCount() != 2 || terms_.outputCount() != 2 * n * n + 2 * n + 2)
        throw std::invalid_argument("CompiledLagrangian: tapes do not fit " + std::to_string(n) + " coordinates");
    input_.assign(inputs, 0.0);
    output_.assign(std::max(dynamics_.outputCount(), terms_.outputCount()), 0.0);
}

ModelTerms CompiledLagrangian::terms(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t) const {
    requireSize("CompiledLagrangian::terms", "q", q.size(), n_, "the system", "coordinates");
    requireSize("CompiledLagrangian::terms", "qd", qd.size(), n_, "the system", "coordinates");
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

void CompiledLagrangian::dynamics(const double* x, double t, Eigen::MatrixXd& B, Eigen::VectorXd& rhs, Eigen::VectorXd& Q) const {
    std::copy(x, x + 2 * n_, input_.begin());
    input_[2 * n_] = t;
    dynamics_.evaluate(input_.data(), output_.data());
    const double* out = output_.data();
    for (int i = 0; i < n_; ++i)
        for (int j = i; j < n_; ++j) B(i, j) = B(j, i) = *out++;
    for (int i = 0; i < n_; ++i) rhs[i] = *out++;
    for (int i = 0; i < n_; ++i) Q[i] = *out++;
}

void CompiledLagrangian::energies(const double* x, double& Ekin, double& Epot) const {
    std::copy(x, x + 2 * n_, input_.begin());
    input_[2 * n_] = 0.0;  // energies do not depend on t
    double out[2];
    energies_.evaluate(input_.data(), out);
    Ekin = out[0];
    Epot = out[1];
}

}  // namespace ll
