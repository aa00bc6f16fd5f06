#pragma once
// A Lagrangian system's B(q), C(q, q̇), g(q), Q(q, q̇, t), E_kin and E_pot as compiled
// tapes (core/math/expression_tape): what the simulation of a system typed as a
// Lagrangian calls at every right-hand side, and what `eval` prints. The symbolic layer
// derives and compiles it once (core/symbolic/compiled_derivation: compileDerivation);
// after that it is plain data with no GiNaC inside, so it crosses threads by copy. The
// inputs are x = [q; q̇] and t. Not thread-safe (scratch registers): one object per
// thread.
#include <vector>

#include <Eigen/Core>

#include "core/math/expression_tape.hpp"

namespace ll {

struct ModelTerms {
    Eigen::MatrixXd B, C;
    Eigen::VectorXd g, Q;
    double Ekin = 0.0, Epot = 0.0;
};

class CompiledLagrangian {
public:
    CompiledLagrangian() = default;
    // n coordinates; the tapes' inputs are [q; q̇; t] (2n + 1). `dynamics` outputs B's upper
    // triangle row by row, rhs = Q − C q̇ − g (n) and Q (n); `energies` E_kin, E_pot;
    // `terms` B and C (row by row), g, Q, E_kin, E_pot. Throws std::invalid_argument when a
    // tape's sizes do not fit n.
    CompiledLagrangian(int n, ExpressionTape dynamics, ExpressionTape energies, ExpressionTape terms);

    int dof() const { return n_; }
    // Every term at one state (slow path: a fresh ModelTerms). Throws std::invalid_argument
    // when q or q̇ does not have dof() entries.
    ModelTerms terms(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t) const;
    // The right-hand side's pieces at x = [q; q̇] (2n values): B(q) (full n×n), the
    // generalized forces Q, and rhs = Q − C q̇ − g, so that B q̈ = rhs. No allocation.
    void dynamics(const double* x, double t, Eigen::MatrixXd& B, Eigen::VectorXd& rhs, Eigen::VectorXd& Q) const;
    // E_kin and E_pot at x = [q; q̇]. No allocation.
    void energies(const double* x, double& Ekin, double& Epot) const;
    // Instructions of the right-hand side's tape (for benchmarks and reports).
    int dynamicsInstructions() const { return dynamics_.instructionCount(); }

private:
    int n_ = 0;
    ExpressionTape dynamics_, energies_, terms_;
    mutable std::vector<double> input_, output_;
};

}  // namespace ll
