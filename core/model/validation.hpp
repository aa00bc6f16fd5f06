#pragma once
// Checks of a model's and a scene's fields, each on its own: what needs no dynamics.
// The whole check of a scene (these, plus a mass matrix that must be regular and an
// integrator that must exist) is core/simulation/scene_validation.
//
// Errors (nothing may be simulated): a non-finite number, a negative mass, an
// inertia tensor that is not symmetric positive semi-definite, a negative armature or
// rotor inertia, a zero gear ratio, a joint that moves no mass or inertia not already
// moved by the joints before it (B(q) singular), a B(q) too ill-conditioned for double
// precision (with its condition number, the joint where it shows and the likely
// cause), initial-state sizes that do not match the number of joints, effects that
// name a joint the robot does not have, negative stiffness/friction.
// Warnings (the model still works): a principal-moment triangle inequality
// violation (I1 + I2 >= I3 and permutations), which no physical body has but
// widely used parameter sets do (Corke's PUMA 560 link 1, the Stanford arm link 5);
// numbers that look typed in the wrong unit (core/model/unit_slips.hpp).
// A Lagrangian scene (Scene::lagrangian) has no robot joints; its initial state has one
// entry per coordinate, effects name coordinates, gravity and springs are errors (they
// belong in the potential), `forces` has one entry per coordinate or none. Its
// expressions are checked where they are parsed and derived, not here.
#include <vector>

#include "core/model/diagnostics.hpp"
#include "core/model/robot_model.hpp"
#include "core/model/scene.hpp"

namespace ll {

std::vector<Diagnostic> validateRobotFields(const RobotModel& model);
std::vector<Diagnostic> validateSceneFields(const Scene& scene);  // includes validateRobotFields

}  // namespace ll
