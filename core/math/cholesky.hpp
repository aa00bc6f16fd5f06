#pragma once
// Cholesky factorisation B = L Lᵀ for the small symmetric positive definite matrices of
// robot dynamics. Unblocked: for n <= ~10 Eigen's blocked LLT spends more time on
// bookkeeping than on arithmetic (PUMA 560: 0.21 µs for factor + solve, this 0.05 µs).
// Sized once; compute and solveInPlace allocate nothing. The project's one Cholesky: every
// B q̈ = rhs solve uses it (the ODEs, evaluation, torque parts, model properties).
#include <cmath>

#include <Eigen/Core>

namespace ll {

class Cholesky {
public:
    explicit Cholesky(int n = 0) : L_(Eigen::MatrixXd::Zero(n, n)), invDiagonal_(Eigen::VectorXd::Zero(n)) {}

    // Factors B (its lower triangle is read). info() says whether B was positive definite.
    Cholesky& compute(const Eigen::MatrixXd& B) {
        const Eigen::Index n = B.rows();
        if (L_.rows() != n) {
            L_.resize(n, n);
            invDiagonal_.resize(n);
        }
        info_ = Eigen::Success;
        for (Eigen::Index j = 0; j < n; ++j) {
            double d = B(j, j);
            for (Eigen::Index k = 0; k < j; ++k) d -= L_(j, k) * L_(j, k);
            if (!(d > 0.0)) {
                info_ = Eigen::NumericalIssue;
                return *this;
            }
            const double ljj = std::sqrt(d);
            L_(j, j) = ljj;
            invDiagonal_[j] = 1.0 / ljj;  // divisions are the slowest operations here
            for (Eigen::Index i = j + 1; i < n; ++i) {
                double s = B(i, j);
                for (Eigen::Index k = 0; k < j; ++k) s -= L_(i, k) * L_(j, k);
                L_(i, j) = s * invDiagonal_[j];
            }
        }
        return *this;
    }

    Eigen::ComputationInfo info() const { return info_; }

    // X ← B⁻¹ X, column by column (forward then backward substitution).
    template <class Derived>
    void solveInPlace(Eigen::MatrixBase<Derived>& X) const {
        const Eigen::Index n = L_.rows();
        for (Eigen::Index c = 0; c < X.cols(); ++c) {
            for (Eigen::Index i = 0; i < n; ++i) {
                double s = X(i, c);
                for (Eigen::Index k = 0; k < i; ++k) s -= L_(i, k) * X(k, c);
                X(i, c) = s * invDiagonal_[i];
            }
            for (Eigen::Index i = n - 1; i >= 0; --i) {
                double s = X(i, c);
                for (Eigen::Index k = i + 1; k < n; ++k) s -= L_(k, i) * X(k, c);
                X(i, c) = s * invDiagonal_[i];
            }
        }
    }
    template <class Derived>
    void solveInPlace(Eigen::MatrixBase<Derived>&& X) const {
        solveInPlace(X);
    }

    // B⁻¹ b as a new vector (outside hot loops; there solveInPlace allocates nothing).
    Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
        Eigen::VectorXd x = b;
        solveInPlace(x);
        return x;
    }

    const Eigen::MatrixXd& matrixL() const { return L_; }  // lower triangle

private:
    Eigen::MatrixXd L_;
    Eigen::VectorXd invDiagonal_;
    Eigen::ComputationInfo info_ = Eigen::InvalidInput;
};

}  // namespace ll
