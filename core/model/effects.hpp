#pragma once
// The physical effects a scene declares. Only declared effects are evaluated:
// gravity and springs are conservative and enter E_pot (and so g(q)); viscous and
// Coulomb friction and external torques are the generalized forces Q.
// Joint indices here are 0-based; scene files number joints from 1.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/model/control.hpp"

namespace ll {

struct JointSpring {  // E = ½ K (q_i - rest)^2
    int joint = 0;
    double stiffness = 0.0;
    double rest = 0.0;
};

struct ViscousFriction {  // Q_i = -b q̇_i
    int joint = 0;
    double coefficient = 0.0;
};

// Coulomb friction of magnitude F_c on one joint, in one of two models:
//  - Tanh (the default): Q_i = -F_c tanh(q̇_i / v_s). Smooth, so every integrator
//    handles it, and it always opposes motion (Q_i q̇_i <= 0, never adds energy). The
//    price: below v_s it is a stiff viscous damper (slope F_c/v_s), so a joint held
//    by a load smaller than F_c creeps at a speed of order v_s and never sticks.
//  - Stick: the set-valued law of the textbook. A sliding joint feels -F_c sign(q̇_i);
//    when q̇_i reaches zero and the force needed to hold it is at most F_c, the joint
//    sticks: q̇_i is set to exactly 0 by an inelastic impulse on that joint alone (its
//    kinetic energy loss is booked as work of friction), and while stuck the friction
//    is the holding force, a constraint force that does no work. It breaks free when
//    the holding force would exceed F_c. Implemented as a step event in the
//    integrator drivers (RobotOde::afterStep), so it never adds energy and comes to
//    rest exactly. `smoothing` is not used.
enum class CoulombModel { Tanh, Stick };

struct CoulombFriction {
    int joint = 0;
    double force = 0.0;
    double smoothing = 1e-3;  // v_s [rad/s or m/s], Tanh model only
    CoulombModel model = CoulombModel::Tanh;
};

enum class TorqueKind { Constant, Step, Sine, Ramp };

// An external torque (revolute) or force (prismatic) on one joint, a function of t.
struct JointTorque {
    int joint = 0;
    TorqueKind kind = TorqueKind::Constant;
    double value = 0.0;      // constant, step
    double at = 0.0;         // step: switches from 0 to value at t = at
    double amplitude = 0.0;  // sine: amplitude sin(2π frequency t + phase)
    double frequency = 0.0;  // [Hz]
    double phase = 0.0;      // [rad]
    double slope = 0.0;      // ramp: slope (t - start) for t >= start, else 0
    double start = 0.0;

    double operator()(double t) const;
};

struct Effects {
    std::optional<Eigen::Vector3d> gravity;  // g0 in the world frame [m/s^2]
    std::vector<JointSpring> springs;
    std::vector<ViscousFriction> viscous;
    std::vector<CoulombFriction> coulomb;
    std::vector<JointTorque> torques;
    std::optional<Control> control;  // a joint-space controller (core/model/control.hpp)

    bool hasFriction() const { return !viscous.empty() || !coulomb.empty(); }
};

const char* toString(TorqueKind kind);
const char* toString(CoulombModel model);  // "tanh", "stick"

// Joints that have an input (an external torque); fewer than n means underactuated.
std::vector<int> actuatedJoints(const Effects& effects, int dof);

}  // namespace ll
