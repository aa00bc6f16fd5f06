#pragma once
// The controller a scene declares (core/model/control.hpp), evaluated from the state at
// every right-hand-side call: τ(t, q, q̇) from the reference and the controller's own
// model of the robot (B̂, Ĉ, ĝ by the numeric algorithms of core/dynamics: no GiNaC while
// simulating). Computed torque is one recursive Newton–Euler pass with the commanded
// acceleration q̈_d + K_p e + K_d ė; the split into its terms (parts) is for the plots and
// the output, not for the integrator. Immutable model, scratch data of its own: no
// allocation per call.
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "core/model/control.hpp"
#include "core/model/effects.hpp"
#include "core/model/robot_data.hpp"
#include "core/model/robot_model.hpp"

namespace ll {

// The robot as the controller believes it is: `plant` with `changes` (links with the
// controller's own values, links scaled, a payload lumped into the last link: masses added,
// COM combined, inertias moved to it).
RobotModel controllerModel(const RobotModel& plant, const ControllerModel& changes);

// The controller's terms at one state, each per joint.
struct ControlParts {
    Eigen::VectorXd qRef, qdRef, qddRef;  // q_d, q̇_d, q̈_d
    Eigen::VectorXd error, errorRate;     // e = q_d − q, ė = q̇_d − q̇
    Eigen::VectorXd proportional;         // K_p e (computed torque: B̂ K_p e)
    Eigen::VectorXd derivative;           // K_d ė (computed torque: B̂ K_d ė)
    Eigen::VectorXd inertial;             // B̂ q̈_d (0 for PD laws)
    Eigen::VectorXd coriolis;             // Ĉ q̇ (feedforward: Ĉ(q_d, q̇_d) q̇_d; 0 for PD laws)
    Eigen::VectorXd gravity;              // ĝ (0 for PD)
    Eigen::VectorXd tau;                  // the sum, saturated; 0 on joints without an actuator
    Eigen::VectorXd unsaturated;          // the sum before the limits
};

class Controller {
public:
    // `plantEffects`: the scene's effects, whose gravity and springs the controller's ĝ
    // takes (its friction it does not know of); their control is the law.
    Controller(const RobotModel& plant, const Effects& plantEffects);

    // τ at (t, q, q̇), saturated (allocation-free; the reference is held in the object).
    const Eigen::VectorXd& torque(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd);
    // Every term at (t, q, q̇) (allocates: for output and plots).
    ControlParts parts(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd);

    // Its corners (OdeSystem): the reference's, at known times (the first after t, +inf
    // when none), and each limited joint's demanded torque reaching or leaving ±limit (the
    // fraction of the step from (t0, q0, q̇0) to (t1, q1, q̇1) where the first does, by the
    // secant on |τ_i| − limit_i; 1 when none does or the step ends at it already).
    bool hasCorners() const { return !corners_.empty() || control_.torqueLimit.size() > 0; }
    double nextCorner(double t) const;
    double cornerFraction(double t0, const Eigen::VectorXd& q0, const Eigen::VectorXd& qd0, double t1, const Eigen::VectorXd& q1,
                          const Eigen::VectorXd& qd1);
    // From t on, the reference keeps to its piece between the corners around t (evaluated
    // just inside it at and beyond its ends: OdeSystem::enterSegment); true when the piece
    // changed. Never called (fixed-step methods, plots): the reference as it is at every t.
    bool enterSegment(double t);

    const Control& control() const { return control_; }
    const RobotModel& model() const { return model_; }

private:
    void reference(double t);
    void demand(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qd);  // tau_ before the limits
    void saturate(Eigen::VectorXd& tau) const;
    Control control_;
    RobotModel model_;
    Effects conservative_;  // gravity and springs: what ĝ is made of
    RobotData data_;
    std::vector<double> corners_;  // the reference's
    // The corners around the current piece (±inf: none).
    double segmentStart_ = -std::numeric_limits<double>::infinity(), segmentEnd_ = std::numeric_limits<double>::infinity();
    Eigen::VectorXd qRef_, qdRef_, qddRef_, a_, tau_, zero_, demandStart_;
};

}  // namespace ll
