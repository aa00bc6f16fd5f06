#include "core/simulation/robot_ode.hpp"

#include "core/dynamics/forward_dynamics.hpp"
#include "core/simulation/generalized_forces.hpp"
#include "core/simulation/integrators.hpp"

namespace ll {

RobotOde::RobotOde(const RobotModel& model, const Effects& effects)
    : model_(model),
      effects_(effects),
      hasGeneralizedForces_(!effects.torques.empty() || effects.hasFriction()),
      data_(model),
      q_(Eigen::VectorXd::Zero(model.dof())),
      qd_(Eigen::VectorXd::Zero(model.dof())),
      Q_(Eigen::VectorXd::Zero(model.dof())) {}

OdeState RobotOde::initialState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd) const {
    const int n = data_.n;
    OdeState x(2 * n + 1, 0.0);
    for (int i = 0; i < n; ++i) {
        x[i] = q[i];
        x[n + i] = qd[i];
    }
    return x;
}

void RobotOde::operator()(const OdeState& x, OdeState& dxdt, double t) {
    ++evaluations_;
    const int n = data_.n;
    for (int i = 0; i < n; ++i) {
        q_[i] = x[i];
        qd_[i] = x[n + i];
    }
    if (hasGeneralizedForces_) computeGeneralizedForces(effects_, t, qd_, Q_);
    try {
        forwardDynamics(model_, data_, effects_, q_, qd_, Q_);
    } catch (const SingularMassMatrix& e) {
        throw IntegrationError(t, x, std::string(e.what()) + " at t = " + std::to_string(t) + " s");
    }
    const Eigen::VectorXd& qdd = data_.qdd;
    for (int i = 0; i < n; ++i) {
        dxdt[i] = qd_[i];
        dxdt[n + i] = qdd[i];
    }
    dxdt[2 * n] = hasGeneralizedForces_ ? Q_.dot(qd_) : 0.0;
}

}  // namespace ll
