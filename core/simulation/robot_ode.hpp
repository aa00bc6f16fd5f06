#pragma once
// The equations of motion as a first-order ODE for Boost.Odeint, over the state
// x = [q; q̇; W] (W: work done by Q, integrated alongside for the energy balance):
//   q̇ = q̇,  q̈ = B⁻¹(Q − C q̇ − g),  Ẇ = Qᵀ q̇.
// The right-hand side is composed once, at construction, from the effects the scene
// declares: no gravity → the gravity torques are never computed, no friction → no
// friction code runs. Each term counts its evaluations (termEvaluations), so this is
// checkable, not just claimed. The model and effects are copied in. Odeint copies systems by value; pass this with std::ref.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/model/effects.hpp"
#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"
#include "core/simulation/controller.hpp"
#include "core/simulation/ode_system.hpp"

namespace ll {

// The terms of the right-hand side. MassMatrix (kinematics + B) and Coriolis (C q̇) are
// always there; the others only when declared.
enum class RhsTerm { MassMatrix, Coriolis, Gravity, Springs, Viscous, Coulomb, Torques, Control };
inline constexpr int kRhsTermCount = 8;
const char* toString(RhsTerm term);

class RobotOde : public OdeSystem {
public:
    RobotOde(const RobotModel& model, const Effects& effects);

    void operator()(const OdeState& x, OdeState& dxdt, double t) override;
    int coordinates() const override { return data_.n; }
    // Stick–slip events of CoulombModel::Stick joints (see effects.hpp).
    bool afterStep(double t, OdeState& x) override;
    bool hasEvents() const override { return !stick_.empty(); }
    // A sliding Stick joint whose velocity changed sign during the step.
    double eventFraction(const OdeState& x0, const OdeState& x1) const override;
    // The controller's corners (Controller::cornerFraction), when it declares one.
    bool hasCorners() const override { return controller_ && controller_->hasCorners(); }
    double nextCorner(double t) const override { return controller_ ? controller_->nextCorner(t) : OdeSystem::nextCorner(t); }
    double cornerFraction(double t0, const OdeState& x0, double t1, const OdeState& x1) override;
    bool enterSegment(double t) override { return controller_ && controller_->enterSegment(t); }

    long evaluations() const { return evaluations_; }
    long termEvaluations(RhsTerm term) const { return termCounts_[static_cast<int>(term)]; }
    // The terms this scene's right-hand side is made of, in evaluation order.
    std::vector<RhsTerm> terms() const;
    // Joints (0-based) currently stuck by Coulomb friction.
    std::vector<int> stuckJoints() const;
    long stickEvents() const { return stickEvents_; }

    OdeState initialState(const Eigen::VectorXd& q, const Eigen::VectorXd& qd) const;

private:
    using TermFn = void (RobotOde::*)(double t);
    struct Term {
        RhsTerm kind;
        TermFn add;  // adds its generalized force into rhs_ (and Q_ when non-conservative)
    };
    struct StickJoint {
        int joint = 0;
        double force = 0.0;  // F_c, summed over the joint's Stick entries
        bool stuck = false;
        double sign = 0.0;  // direction of sliding at the last step
    };

    void evaluateForces(const OdeState& x, double t);  // q_, qd_, data_.B, rhs_, Q_
    void solveAccelerations();                         // qdd_ (and the holding forces)
    void addGravity(double t);
    void addSprings(double t);
    void addViscous(double t);
    void addTanhCoulomb(double t);
    void addSlidingCoulomb(double t);
    void addTorques(double t);
    void addControl(double t);

    // Own copies: an editor may change its scene while this runs on a worker thread.
    RobotModel model_;
    Effects effects_;
    std::vector<Term> terms_;
    std::vector<StickJoint> stick_;
    std::optional<Controller> controller_;  // the scene's control law, when it declares one
    bool hasGeneralizedForces_ = false;
    RobotData data_;
    Eigen::VectorXd q_, qd_, Q_, rhs_, qdd_;
    Eigen::VectorXd cornerQ0_, cornerQd0_, cornerQ1_, cornerQd1_;  // cornerFraction's scratch
    std::array<long, kRhsTermCount> termCounts_{};
    long evaluations_ = 0;
    long stickEvents_ = 0;
};

}  // namespace ll
