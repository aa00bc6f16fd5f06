#pragma once
// A joint-space controller the scene declares ("effects" → "control"): the derived B, C
// and g at work. Only a scene that declares one is controlled; its torque τ joins the
// generalized forces Q beside the scene's other non-conservative effects. The laws, with
// e = q_d − q and ė = q̇_d − q̇ (the reference's q_d, q̇_d, q̈_d at t):
//   pd               τ = K_p e + K_d ė
//   pd_gravity       τ = K_p e + K_d ė + ĝ(q)
//   computed_torque  τ = B̂(q) (q̈_d + K_p e + K_d ė) + Ĉ(q, q̇) q̇ + ĝ(q)
//   feedforward      τ = B̂(q_d) q̈_d + Ĉ(q_d, q̇_d) q̇_d + ĝ(q_d) + K_p e + K_d ė
// where B̂, Ĉ, ĝ are the controller's own model of the robot: the scene's, or with a
// payload it does not know of, or links scaled (a wrong model is one line). Each τ_i is
// clipped to ±limit_i when limits are given. Joints are 0-based here.
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/model/link_inertia.hpp"
#include "core/model/message.hpp"

namespace ll {

enum class ControlLaw { Pd, PdGravity, ComputedTorque, Feedforward };

// q_d(t) and its first two derivatives, one entry per joint.
struct ControlReference {
    enum class Kind { Hold, Step, Quintic, Trapezoidal, Sine, Waypoints };
    Kind kind = Kind::Hold;
    Eigen::VectorXd q0, q1;        // hold: q0; step, quintic, trapezoidal: from q0 to q1
    double t0 = 0.0;               // step: the jump's time; quintic, trapezoidal: the start [s]
    double duration = 1.0;         // quintic [s]
    Eigen::VectorXd velocity;      // trapezoidal: the largest |q̇_d| per joint
    Eigen::VectorXd acceleration;  // trapezoidal: the largest |q̈_d| per joint
    Eigen::VectorXd amplitude;     // sine: q0 + amplitude sin(2π frequency t + phase)
    double frequency = 0.0;        // [Hz]
    double phase = 0.0;            // [rad]
    // waypoints: the joints at these times (increasing), a quintic from each to the next,
    // at rest at every one; before the first and after the last, held there
    std::vector<double> times;           // [s]
    std::vector<Eigen::VectorXd> points;  // one per time

    // q_d, q̇_d, q̈_d at t into the three vectors (sized n beforehand; no allocation).
    void evaluate(double t, Eigen::VectorXd& q, Eigen::VectorXd& qd, Eigen::VectorXd& qdd) const;
    // Its corners, increasing: the times where q_d jumps (step), q̈_d jumps (a trapezoid's
    // phases) or the third derivative does (a quintic's ends, every waypoint). The
    // integrators end a step at each (core/simulation/ode_system.hpp, cornerFraction).
    std::vector<double> corners() const;
};

// What the controller believes the robot is: the scene's robot with these changes, in
// this order: links given their own values, links scaled, a payload added.
struct ControllerLink {
    int joint = 0;     // 0-based
    LinkInertia link;  // the controller's mass, COM and inertia for it
};
struct ControllerModel {
    std::vector<ControllerLink> links;                         // the controller's own values for these links
    double payloadMass = 0.0;                                  // [kg] on the last link
    Eigen::Vector3d payloadCom = Eigen::Vector3d::Zero();      // [m] in the last DH frame
    Eigen::Matrix3d payloadInertia = Eigen::Matrix3d::Zero();  // [kg m²] about its COM, last frame's axes
    Eigen::VectorXd scale;                                     // per link: mass and inertia times this (empty: 1)
};

struct Control {
    ControlLaw law = ControlLaw::PdGravity;
    Eigen::VectorXd kp, kd;  // per joint [N m/rad, N m s/rad] (or N/m, N s/m)
    // Or the gains as a natural frequency wn [rad/s] and a damping ratio zeta per joint
    // (kp, kd empty then; the Controller turns them into gains): computed torque's error
    // obeys ë + K_d ė + K_p e = 0, so K_p = wn², K_d = 2 zeta wn exactly; the other laws act
    // on torques, so K_p = b̂_ii wn², K_d = 2 zeta wn b̂_ii with b̂_ii of the controller's
    // B̂ at the reference's start (each joint as if alone).
    Eigen::VectorXd wn, zeta;
    ControlReference reference;
    ControllerModel model;
    Eigen::VectorXd torqueLimit;  // per joint, > 0 (empty: none)
    std::vector<int> joints;      // the joints with an actuator (empty: all)

    bool drives(int joint) const;
};

// Why `control` cannot drive a robot of n joints (empty: it can): computed torque commands
// B̂ q̈ on every joint, so each needs an actuator.
Message lawImpossible(const Control& control, int n);

const char* toString(ControlLaw law);  // "pd", "pd_gravity", "computed_torque", "feedforward"
const char* toString(ControlReference::Kind kind);

}  // namespace ll
