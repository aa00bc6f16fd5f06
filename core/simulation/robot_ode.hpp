#pragma once
// The equations of motion as a first-order ODE for Boost.Odeint, over the state
// x = [q; q̇; W] (W: work done by Q, integrated alongside for the energy balance):
//   q̇ = q̇,  q̈ = B⁻¹(Q − C q̇ − g),  Ẇ = Qᵀ q̇.
// Only declared effects are evaluated: no friction or torques → Q is never computed.
// Odeint copies systems by value; pass this with std::ref.
#include <vector>

#include <Eigen/Core>

#include "core/model/effects.hpp"
#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"
#include "core/simulation/ode_system.hpp"

namespace ll {

class RobotOde : public OdeSystem {
public:
    RobotOde(const RobotModel& model, const Effects& effects);

    void operator()(const OdeState& x, OdeState& dxdt, double t) override;

    int coordinates() const override { return data_.n; }
    long evaluations() const { return evaluations_; }
    OdeState initialState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd) const;

private:
    const RobotModel& model_;
    const Effects& effects_;
    const bool hasGeneralizedForces_;
    RobotData data_;
    Eigen::VectorXd q_, qd_, Q_;
    long evaluations_ = 0;
};

}  // namespace ll
