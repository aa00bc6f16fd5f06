#pragma once
// The result of a symbolic derivation, as the textbook procedure derives it: named
// steps, each with its general formula and this system's results, and the final
// B(q), C(q, q̇), g(q), Q of B q̈ + C q̇ + g = Q. Plain data over GiNaC expressions.
// Each item says which quantity of the course notes it is and how its terms group, so
// that how it reads (its label, its entries' names, its grouping; core/present) is
// decided from that, never from its name.
//
// Symbol names (what the printers and the plain `expr` syntax see):
//   coordinates   q1..qn (robots) or the user's names (Lagrangian systems)
//   velocities    qd1..qdn, or <name>_dot for the user's names
//   trigonometry  c1..cn, s1..sn stand for cos q_i, sin q_i (robots only); after
//                 angle-sum combination c12 = cos(q1 + q2), s23 = sin(q2 + q3); with
//                 an index of 10 or more the indices are joined by '_' (c9_10)
//   parameters    their scene names; in textbook-symbol mode a1, d1, m1, xc1, yc1,
//                 zc1 (COM in frame i), Ixx1, Iyy1, Izz1, Ixy1, Ixz1, Iyz1
#include <map>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/model/message.hpp"
#include "core/model/step_formula.hpp"

namespace ll::symbolic {

// The quantities a derivation shows, in the notes' notation (i: the item's index).
enum class Quantity {
    DhTable,            // the DH table with the joint variables in place
    LinkTransform,      // A_i
    Transform,          // T_i^0
    ComPosition,        // p_ci^0
    AngularJacobian,    // J_ω,i
    AngularVelocity,    // ω_i^0
    ComJacobian,        // J_v,ci
    ComVelocity,        // v_ci^0
    LinkInertia,        // I_li^0
    PotentialEnergy,    // E_pot
    MotorInertia,       // B_m = diag(J_m,j G_j²)
    MassMatrix,         // B(q)
    KineticEnergy,      // E_kin
    GravityVector,      // g(q)
    CoriolisMatrix,     // C(q, q̇)
    GeneralizedForces,  // Q
    EquationOfMotion,   // row i of B q̈ + C q̇ + g = Q
    Coordinates,        // q (a typed Lagrangian)
    Velocities,         // q̇
    Lagrangian,         // L = E_kin − E_pot
    MomentumPartial,    // ∂L/∂q̇_i
    MomentumRate,       // d/dt ∂L/∂q̇_i
    CoordinatePartial,  // ∂L/∂q_i
    // The structured form (core/symbolic/structured_dynamics.hpp): a named quantity of
    // its table, and single entries over the names.
    NamedQuantity,    // β_jk^(i), J_P,j^(i), γ_j^(i), ∂b_jk/∂q_l, …
    MassMatrixEntry,  // b_jk
    CoriolisEntry,    // c_ij
    GravityEntry,     // g_j
    ForceEntry,       // Q_j
    // Step 9, a controlled robot's law (core/symbolic/control_law.hpp).
    ProportionalGain,  // K_p
    DerivativeGain,    // K_d
    ControlTorque,     // τ, the controller's torque with the derived terms in place
    ClosedLoop,        // row i of B q̈ + C q̇ + g = τ + Q with τ put in
};

// The steps: 0..8 as in the course notes, 9 the control law of a robot that declares a
// controller (its τ with the derived B, C, g in place).
inline constexpr int lastModelStep = 8;
inline constexpr int controlStepNumber = 9;
inline constexpr int lastDerivationStep = controlStepNumber;

// A quantity of step 9: written in the reference's and the error's symbols (e_i, ė_i,
// q̈_di), which no state of the robot alone gives a value to.
inline bool isControlQuantity(Quantity q) {
    return q == Quantity::ProportionalGain || q == Quantity::DerivativeGain || q == Quantity::ControlTorque || q == Quantity::ClosedLoop;
}

// How the terms of an item group when shown: by the masses (a robot's b11 = I1 + m1 ℓc1²
// + m2 (…)), by the velocities (C, E_kin, ω, v_c: linear or quadratic in q̇), or by the
// parameters (a typed Lagrangian's K2 (θ1 − θ2)).
enum class Grouping { Masses, Velocities, Parameters };

// One term of a sum shown as written, not expanded: coefficient · factor, the coefficient
// grouped on its own (b_12 (q̈_d2 + K_p,2 e_2 + K_d,2 ė_2), the row of C q̇, g_1).
struct ItemPart {
    GiNaC::ex coefficient;
    GiNaC::ex factor = 1;
    Grouping grouping = Grouping::Masses;
};

struct DerivationItem {
    std::string name;  // an identifier, also JSON's "name": "T_2^0", "p_c1", "E_kin", "equation_1"
    Quantity quantity;
    int index = -1;  // 0-based: the link, joint, coordinate or row it is of; -1 for none
    Grouping grouping;
    GiNaC::ex value;  // a scalar, a GiNaC::matrix, or (EquationOfMotion, ClosedLoop) an equation
    // When not empty: the scalar value (an equation's left side) as the sum of these, in
    // this order, as the textbook writes it (the control law's τ_i and closed loop).
    std::vector<ItemPart> parts = {};
};

struct DerivationStep {
    int number = 0;       // 0..8 as in the course notes, 9 the control law
    Message title;        // MessageId::TitleKinematicModel: words only where it is shown
    StepFormula formula;  // the general formula of the step (written for a reader by core/present)
    std::vector<DerivationItem> items;
    double seconds = 0.0;  // time it took
};

// What was derived: a serial robot from its DH table, or a system typed as a Lagrangian.
enum class SystemKind { Robot, Lagrangian };

struct Derivation {
    SystemKind system = SystemKind::Robot;
    std::string systemName;
    std::vector<GiNaC::symbol> q, qd, qdd;     // coordinates, velocities, accelerations
    GiNaC::symbol t{"t"};                      // time, in external torques
    std::vector<std::string> coordinateNames;  // as the user wrote them (q1.. for robots)
    std::vector<DerivationStep> steps;
    GiNaC::matrix B, C;  // n×n
    GiNaC::matrix g, Q;  // n×1
    GiNaC::ex Ekin, Epot;
    bool modifiedDH = false;    // a robot's DH table is in the modified (Craig) convention
    std::vector<int> actuated;  // 0-based coordinates with an input
    bool underactuated = false;
    // Substitutions that turn a result into an expression of q, q̇ and the parameter
    // values only: c_i → cos(q_i), s_i → sin(q_i), c12 → cos(q1+q2) ..., and each
    // parameter symbol → its number (empty in numeric mode, where none are left).
    GiNaC::lst trigToFunctions;
    GiNaC::lst parameterValues;
    std::vector<std::string> warnings;
    // The symbols of one link's inertial parameters, by name → link (symbolic_robot.hpp).
    std::map<std::string, int> symbolLinks;
    // The numbers the scene typed as decimals, exact (1.375 → 11/8): shown as typed.
    std::vector<GiNaC::numeric> typedDecimals;
};

}  // namespace ll::symbolic
