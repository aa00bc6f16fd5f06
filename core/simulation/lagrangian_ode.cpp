#include "core/simulation/lagrangian_ode.hpp"

#include <string>
#include <utility>

#include "core/model/argument_checks.hpp"
#include "core/simulation/integrators.hpp"

namespace ll {

LagrangianOde::LagrangianOde(CompiledLagrangian model)
    : n_(model.dof()),
      model_(std::move(model)),
      B_(Eigen::MatrixXd::Zero(n_, n_)),
      rhs_(Eigen::VectorXd::Zero(n_)),
      Q_(Eigen::VectorXd::Zero(n_)),
      llt_(n_) {}

OdeState LagrangianOde::initialState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd) const {
    requireSize("LagrangianOde::initialState", "q", q.size(), n_, "the system", "coordinates");
    requireSize("LagrangianOde::initialState", "qd", qd.size(), n_, "the system", "coordinates");
    OdeState x(2 * n_ + 1, 0.0);
    for (int i = 0; i < n_; ++i) {
        x[i] = q[i];
        x[n_ + i] = qd[i];
    }
    return x;
}

void LagrangianOde::operator()(const OdeState& x, OdeState& dxdt, double t) {
    ++evaluations_;
    model_.dynamics(x.data(), t, B_, rhs_, Q_);
    llt_.compute(B_);
    if (llt_.info() != Eigen::Success) {
        std::string q;
        for (int i = 0; i < n_; ++i) q += (i ? ", " : "") + std::to_string(x[i]);
        throw IntegrationError(t, x, message(MessageId::CoordinatesDependentAt, std::to_string(t), q));
    }
    llt_.solveInPlace(rhs_);  // now q̈
    double power = 0.0;
    for (int i = 0; i < n_; ++i) {
        dxdt[i] = x[n_ + i];
        dxdt[n_ + i] = rhs_[i];
        power += Q_[i] * x[n_ + i];
    }
    dxdt[2 * n_] = power;
}

}  // namespace ll
