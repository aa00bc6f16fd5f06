#pragma once
// A system typed by hand as a Lagrangian (Scene::lagrangian) as a first-order ODE over
// the same state as RobotOde, x = [q; q̇; W] (W: work done by Q):
//   q̇ = q̇,  q̈ = B⁻¹(Q − C q̇ − g) by a Cholesky solve (core/math/cholesky.hpp),  Ẇ = Qᵀ q̇,
// with B, C, g and Q from the derivation compiled once by the symbolic layer
// (CompiledLagrangian, plain data): no GiNaC anywhere in a simulation, and no
// allocation per right-hand side.
// Odeint copies systems by value; pass this with std::ref.
#include <Eigen/Core>

#include "core/math/cholesky.hpp"
#include "core/simulation/ode_system.hpp"
#include "core/dynamics/compiled_lagrangian.hpp"

namespace ll {

class LagrangianOde : public OdeSystem {
public:
    explicit LagrangianOde(CompiledLagrangian model);

    // Throws IntegrationError where B(q) is not positive definite (the coordinates stop
    // being independent there, e.g. a spherical pendulum at its pole).
    void operator()(const OdeState& x, OdeState& dxdt, double t) override;

    int coordinates() const override { return n_; }
    long evaluations() const { return evaluations_; }
    OdeState initialState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd) const;
    const CompiledLagrangian& model() const { return model_; }

private:
    int n_;
    CompiledLagrangian model_;
    Eigen::MatrixXd B_;
    Eigen::VectorXd rhs_, Q_;
    Cholesky llt_;
    long evaluations_ = 0;
};

}  // namespace ll
