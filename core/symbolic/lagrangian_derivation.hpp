#pragma once
// Lagrange–d'Alembert for a system typed by hand (Scene::lagrangian): from the user's
// E_kin(q, q̇), E_pot(q) and generalized forces to B q̈ + C q̇ + g = Q, step by step
// with the course notes' names:
//   0 generalized coordinates q and velocities q̇ (the user's names, x and x_dot)
//   6 E_pot(q)
//   7 E_kin(q, q̇) and the mass matrix b_ij = ∂²E_kin/∂q̇_i∂q̇_j
//   8 L = E_kin − E_pot, ∂L/∂q̇_i, d/dt ∂L/∂q̇_i, ∂L/∂q_i, then g = ∂E_pot/∂q, C from the
//     Christoffel symbols of B, Q (the `forces` plus declared torques and friction),
//     and the equations B q̈ + C q̇ + g = Q (the same as d/dt ∂L/∂q̇ − ∂L/∂q = Q).
// Input errors are thrown as InputError naming the field:
//   lagrangian.kinetic       E_kin is not a homogeneous quadratic ½ q̇ᵀ B(q) q̇, or B
//                            cannot be evaluated at the initial state
//   lagrangian.coordinates   B is not positive definite at the initial state: the
//                            coordinates are not independent or not minimal (the
//                            message names the velocity combination without mass)
//   lagrangian.forces[i]     Q_i depends on q only and ∂Q/∂q is symmetric there: a
//                            conservative force, which belongs in E_pot
//   lagrangian.potential     depends on a velocity; and every expression error (syntax,
//                            unknown symbol, division by zero) with its position
// Symbols: q named as the coordinates, q̇ <name>_dot, q̈ <name>_ddot, time t.
// ParameterMode::Textbook is Parametric here (the user's expressions are the symbols).
#include "core/model/scene.hpp"
#include "core/symbolic/derivation.hpp"
#include "core/symbolic/symbolic_robot.hpp"

namespace ll::symbolic {

// Takes the GiNaC lock for the derivation; the caller holds it too while it keeps or
// prints the returned Derivation (GiNaC objects: ginac_lock.hpp).
Derivation deriveLagrangian(const Scene& scene, ParameterMode mode = ParameterMode::Parametric);

}  // namespace ll::symbolic
