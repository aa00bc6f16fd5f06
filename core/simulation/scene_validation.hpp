#pragma once
// The whole check of a scene before it is simulated, in the layer that has every piece
// it needs: the field checks of core/model/validation, a mass matrix B(q) that is
// regular (core/dynamics/mass_matrix_check) and an integrator that exists
// (core/simulation/integrators). A Lagrangian scene's expressions are checked where
// they are derived; core/pipeline/scene_check runs both for the editor.
#include <vector>

#include "core/model/diagnostics.hpp"
#include "core/model/robot_model.hpp"
#include "core/model/scene.hpp"

namespace ll {

std::vector<Diagnostic> validateRobot(const RobotModel& model);  // fields, then B regular at q = 0
std::vector<Diagnostic> validateScene(const Scene& scene);       // includes validateRobot

// Throws InputError when validateScene finds an error; returns the warnings.
std::vector<Diagnostic> requireValidScene(const Scene& scene);

}  // namespace ll
