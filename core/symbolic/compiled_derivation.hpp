#pragma once
// The results of a Derivation (B, C, g, Q, E_kin, E_pot) compiled once into
// CompiledExpressions for fast numbers at any state: what the simulation of a
// Lagrangian system calls at every right-hand side, and what `eval` prints. The
// trigonometric shorthand (trigToFunctions) and the parameter values are substituted
// before compiling, so the inputs are q, q̇ and t only. Not thread-safe (scratch
// registers): one object per thread.
#include <vector>

#include <Eigen/Core>

#include "core/symbolic/compiled_expressions.hpp"
#include "core/symbolic/derivation.hpp"

namespace ll::symbolic {

struct ModelTerms {
    Eigen::MatrixXd B, C;
    Eigen::VectorXd g, Q;
    double Ekin = 0.0, Epot = 0.0;
};

class CompiledDerivation {
public:
    explicit CompiledDerivation(const Derivation& derivation);

    int dof() const { return n_; }

    // Every term at one state (slow path: a fresh ModelTerms).
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
    CompiledExpressions dynamics_, energies_, terms_;
    mutable std::vector<double> input_, output_;
};

}  // namespace ll::symbolic
