#pragma once
// Step 9 of a robot that declares a controller (core/model/control.hpp): its law written
// as a derivation step, with the terms steps 7 and 8 derived put in where the law uses
// them — what B, C and g are for. With e = q_d − q, ė = q̇_d − q̇:
//   τ       the controller's torque per driven joint, the gains as numbers; ĝ, B̂, Ĉ are
//           the derived g, B, C when the controller's model is the scene's, and named
//           symbols ĝ_i, b̂_ij, ĉ_ij when it is its own (a payload, scaled or own links:
//           its values are not the scene's, so its terms are not the derived ones), and
//           always for feedforward, which evaluates them at q_d, q̇_d;
//   the closed loop, B q̈ + C q̇ + g = τ + Q with τ put in: for PD + g with the exact
//           model g cancels (B q̈ + C q̇ = K_p e + K_d ė + Q); for computed torque with the
//           exact model everything but B cancels and, with no other forces, each joint's
//           error obeys ë_i + K_d,i ė_i + K_p,i e_i = 0 (checked symbolically here, not
//           assumed).
// Symbols (core/present/symbol_names.hpp reads them): e1, e1_dot, e1_ddot; q_d1, q_d1_dot,
// q_d1_ddot (the reference); g1_hat, b12_hat, c12_hat (with 10 or more joints the
// indices joined by '_').
#include <functional>

#include <ginac/ginac.h>

#include "core/model/scene.hpp"
#include "core/symbolic/derivation.hpp"

namespace ll::symbolic {

// The step for `scene` (which declares a controller) from a derivation whose B, C, g, Q
// are derived (steps 7 and 8). `reduce` simplifies as the derivation does (TrigContext).
// The gains are the controller's (from a natural frequency and damping ratio when the
// scene gives those: core/simulation/controller.hpp).
DerivationStep controlLawStep(const Scene& scene, const Derivation& d, const std::function<GiNaC::ex(const GiNaC::ex&)>& reduce);

// Whether the controller's model is the scene's robot unchanged.
bool controllerModelIsScenes(const ControllerModel& model);

}  // namespace ll::symbolic
