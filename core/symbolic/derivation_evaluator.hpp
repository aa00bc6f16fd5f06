#pragma once
// Numbers from a derivation's results at a state, by GiNaC substitution: slow,
// exact up to the final evaluation; for checking the symbolic results against the
// numeric dynamics, not for simulation.
#include <Eigen/Core>

#include "core/symbolic/derivation.hpp"

namespace ll::symbolic {

class DerivationEvaluator {
public:
    explicit DerivationEvaluator(const Derivation& derivation);

    double value(const GiNaC::ex& e, const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t = 0.0) const;
    Eigen::MatrixXd value(const GiNaC::matrix& m, const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t = 0.0) const;

private:
    GiNaC::lst state(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, double t) const;
    const Derivation& d_;
};

}  // namespace ll::symbolic
