#pragma once
// A scene's robot and effects with GiNaC values, in one of three modes:
//   Parametric: fields written as expressions keep their parameter symbols ("l1/2"),
//               plain numbers become exact rationals;
//   Numeric:    every field is its (exact) number;
//   Textbook:   every nonzero length, mass, COM coordinate, inertia entry, spring
//               and friction coefficient becomes its textbook symbol (a1, d1, m1,
//               xc1, Ixx1, K1, b1, Fc1; gravity ±g), so a student derives the general
//               model from the table alone. Angles α_i and θ offsets that are exact
//               multiples of π/12 stay exact (they fix the structure); any other
//               (0.3, 1.0472) becomes its symbol alpha_i, theta_i.
// A joint's motor armature is its own term in every mode but Numeric: Jm_i G_i² for
// "motor": {inertia, gear_ratio}, Ja_i for "armature" (or the parameters it was
// written with, in Parametric mode), so b_ii reads "… + Jm1 G1²".
#include <map>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "core/model/dh_row.hpp"
#include "core/model/scene.hpp"

namespace ll::symbolic {

enum class ParameterMode { Parametric, Numeric, Textbook };

struct SymbolicJoint {
    JointType type = JointType::Revolute;
    GiNaC::ex a, alpha, d, theta;  // constant parts; q_i is added by the derivation
    GiNaC::ex mass;
    GiNaC::matrix com{3, 1};
    GiNaC::matrix inertia{3, 3};
    GiNaC::ex armature;  // Jm G² of the joint's motor, added to b_ii; 0 without one
};

struct SymbolicTerm {  // one coefficient on one joint (spring, friction, torque)
    int joint = 0;
    GiNaC::ex value;  // K, b, F_c, or τ(t)
    GiNaC::ex extra;  // spring rest position, Coulomb smoothing speed
};

struct SymbolicRobot {
    DhConvention convention = DhConvention::Standard;
    GiNaC::matrix base{4, 4};
    std::vector<SymbolicJoint> joints;
    bool hasGravity = false;
    GiNaC::matrix gravity{3, 1};
    std::vector<SymbolicTerm> springs, viscous, coulomb, torques;
    // The motor symbols introduced (Jm1, G1, Ja2, ...) with their values, for the
    // derivation to say what they stand for.
    std::vector<std::pair<std::string, double>> motorSymbols;
    GiNaC::lst parameterValues;  // symbol == value for every symbol introduced
    // The numbers the scene typed as decimals, made exact (1.375 → 11/8, 9.8 → 49/5): shown
    // as typed wherever they appear (number_spelling.hpp's NumberSpelling).
    std::vector<GiNaC::numeric> typedDecimals;
};

// t is the time symbol torques depend on. Throws InputError for expressions that
// do not parse (already checked when the scene was loaded).
SymbolicRobot symbolicRobot(const Scene& scene, ParameterMode mode, const GiNaC::symbol& t);

// The symbols that stand for one link's inertial parameters: those occurring in link i's
// mass, centre of mass or inertia and in no other link's and no DH row (m2, ℓc2, I2; a
// parameter two links share belongs to neither, a length a1 is the geometry's), by name
// → link (0-based). What the window colours
// in the formulas, each link in its colour.
std::map<std::string, int> linkSymbols(const SymbolicRobot& robot);

// The generalized forces of the declared torques and friction (n×1, n = qd.size()):
// Q_i = τ_i(t) − b_i q̇_i − F_c,i tanh(q̇_i / v_s,i) by joint (core/model/friction_law.hpp).
GiNaC::matrix effectForces(const SymbolicRobot& robot, const std::vector<GiNaC::symbol>& qd);

}  // namespace ll::symbolic
